// The editor's page in a real headless browser (Debian's chromium, driven
// by puppeteer-core): the page loads and draws the grammar's buildings, an
// edit changes them, a click on a part shows the rules that made it, and a
// broken grammar shows its error at its line; with examples, how many the
// text derives. Screenshots of each step are kept in ARTIFACTS (CMake gives
// build/test-artifacts/web/).
//   node tests/web/editor_test.mjs SERVE_BINARY SOURCE_DIR ARTIFACTS
// Exit 77 (skipped) where chromium or web/node_modules is missing.
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, writeFileSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { createRequire } from 'node:module';

const [serveBinary, source, artifacts] = process.argv.slice(2);
const chromium = '/usr/bin/chromium';
const require = createRequire(resolve(source, 'web', 'package.json'));
if (!existsSync(chromium)) {
  console.log('skipped: no /usr/bin/chromium (scripts/setup installs it)');
  process.exit(77);
}
let puppeteer;
try {
  puppeteer = require('puppeteer-core');
} catch {
  console.log('skipped: no puppeteer-core in web/node_modules (scripts/setup installs it)');
  process.exit(77);
}
mkdirSync(artifacts, { recursive: true });

const HOUSE = `@scope 10, 8, 6
bay = 1.2
house --> split(z){ ~2 : floor | ~1 : I(roof) }
floor --> split(x){ ~1 : I(wall) | ~bay : I(window) | ~1 : I(wall) }
`;
const work = mkdtempSync(join(tmpdir(), 'vern-web-'));
writeFileSync(join(work, 'house.grm'), HOUSE);

let failures = 0;
function check(ok, what) {
  console.log((ok ? 'ok   ' : 'FAIL ') + what);
  if (!ok) failures++;
}

// serve with these arguments; its port once it says it listens.
const servers = [];
async function startServe(args) {
  const server = spawn(serveBinary, [...args, '--port', '0'], { stdio: ['ignore', 'ignore', 'pipe'] });
  servers.push(server);
  return new Promise((resolve, reject) => {
    let err = '';
    server.stderr.on('data', (d) => {
      err += d;
      const m = /serve: http:\/\/127\.0\.0\.1:(\d+)\//.exec(err);
      if (m) resolve(Number(m[1]));
    });
    server.on('exit', (code) => reject(new Error('serve ended (' + code + '): ' + err)));
    setTimeout(() => reject(new Error('serve said no address: ' + err)), 60000);
  });
}
const port = await startServe([join(work, 'house.grm')]);

const browser = await puppeteer.launch({
  executablePath: chromium,
  headless: true,
  userDataDir: join(work, 'profile'),
  args: ['--no-sandbox', '--disable-gpu', '--enable-unsafe-swiftshader', '--use-angle=swiftshader', '--disable-quic',
         '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 720 });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`http://127.0.0.1:${port}/`);
  const derived = (n) => page.waitForFunction((k) => window.vernacular && window.vernacular.derivations >= k, { timeout: 20000 }, n);
  await derived(1);
  // One building, so the view's middle is the house.
  await page.$eval('#count', (e) => { e.value = '1'; e.dispatchEvent(new Event('input')); });
  await derived(2);
  const before = await page.evaluate(() => window.vernacular.answer.buildings[0].parts.length);
  check(before === 4, `the page loads and derives the house: ${before} parts (wall, window, wall, roof)`);
  await page.screenshot({ path: join(artifacts, '1-loaded.png') });

  // The constant's slider overrides its value in what is derived, not in the text.
  const windowWidth = () => page.evaluate(() => {
    const a = window.vernacular.answer;
    const p = a.buildings[0].parts.find((q) => a.labels[q.label] === 'window');
    return p.matrix[0];
  });
  const widthBefore = await windowWidth();
  const sliders = await page.$$eval('#constants input[type=range]', (ls) => ls.map((l) => l.dataset.constant));
  check(JSON.stringify(sliders) === '["bay"]', `a slider for each constant: ${sliders.join(', ')}`);
  const n = await page.evaluate(() => window.vernacular.derivations);
  await page.$eval('#constants input[data-constant=bay]', (e) => { e.value = '2.4'; e.dispatchEvent(new Event('input')); });
  await derived(n + 1);
  const widthAfter = await windowWidth();
  const text = await page.$eval('#text', (e) => e.value);
  check(widthAfter > widthBefore * 1.3 && text.includes('bay = 1.2'),
        `moving bay's slider to 2.4 widens the window (${widthBefore.toFixed(2)} -> ${widthAfter.toFixed(2)} m), the text keeps 1.2`);
  await page.$eval('#constants button', (e) => e.click());  // reset
  await derived(n + 2);
  check(Math.abs((await windowWidth()) - widthBefore) < 1e-9, 'reset gives the text\'s value back');
  const pixelsBefore = await page.$eval('#view canvas', (c) => c.toDataURL());

  // A plot given in the header replaces the grammar's @scope.
  const before2 = await page.evaluate(() => window.vernacular.derivations);
  await page.$eval('#plot-y', (e) => { e.value = '8'; });
  await page.$eval('#plot-z', (e) => { e.value = '6'; });
  await page.$eval('#plot-x', (e) => { e.value = '20'; e.dispatchEvent(new Event('input')); });
  await derived(before2 + 1);
  const plotSize = await page.evaluate(() => window.vernacular.answer.buildings[0].size);
  check(JSON.stringify(plotSize) === '[20,8,6]', `a plot of 20 x 8 x 6 given in the header: ${JSON.stringify(plotSize)}`);
  await page.$eval('#plot-x', (e) => { e.value = ''; e.dispatchEvent(new Event('input')); });
  await derived(before2 + 2);
  const scopeSize = await page.evaluate(() => window.vernacular.answer.buildings[0].size);
  check(JSON.stringify(scopeSize) === '[10,8,6]', `an empty plot size is the grammar's @scope: ${JSON.stringify(scopeSize)}`);

  // An edit: a third wall bay, typed at the end of line 4.
  await page.focus('#text');
  await page.evaluate(() => {
    const t = document.getElementById('text');
    const at = t.value.indexOf(' }\n', t.value.indexOf('floor -->'));
    t.setSelectionRange(at, at);
  });
  await page.keyboard.type(' | ~1 : I(wall)');
  await page.waitForFunction(() => window.vernacular.answer.buildings[0].parts.length === 5, { timeout: 20000 });
  check(true, 'typing a bay into the grammar derives the house again with 5 parts');
  const pixelsAfter = await page.$eval('#view canvas', (c) => c.toDataURL());
  check(pixelsAfter !== pixelsBefore, 'the picture changed with the edit');
  await page.screenshot({ path: join(artifacts, '2-edited.png') });

  // A click on the middle of the view picks a part and shows its rules.
  const box = await (await page.$('#view canvas')).boundingBox();
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  await page.waitForSelector('#picked:not([hidden])', { timeout: 10000 });
  const picked = await page.$eval('#picked', (e) => e.textContent);
  check(/made by: house/.test(picked), `a click shows the part's rules: ${JSON.stringify(picked.split('\n')[1])}`);
  const lit = await page.$$eval('#gutter .hit', (ls) => ls.map((l) => Number(l.textContent)));
  // Lit: the line that inserted it and the lines of the rules it came through.
  const said = [Number(/inserted at line (\d+)/.exec(picked)[1]), ...[...picked.matchAll(/\(line (\d+)\)/g)].map((m) => Number(m[1]))];
  const expected = [...new Set(said)].sort();
  check(JSON.stringify(lit.sort()) === JSON.stringify(expected) && lit.includes(3),
        `the rules' lines are lit in the editor: ${lit.join(', ')} (${picked.split('\n')[0]})`);
  await page.screenshot({ path: join(artifacts, '3-picked.png') });

  // A shift-click on a wall lights every wall.
  const wallAt = await page.evaluate(() => {
    const s = window.vernacular;
    return s.viewer.whereIs((e) => s.answer.labels[s.answer.buildings[e.building].parts[e.part].label] === 'wall');
  });
  await page.keyboard.down('Shift');
  await page.mouse.click(wallAt.x, wallAt.y);
  await page.keyboard.up('Shift');
  const alike = await page.$eval('#picked', (e) => e.textContent);
  check(alike === 'every wall: 3 parts', `a shift-click on a wall selects every wall: ${JSON.stringify(alike)}`);
  await page.screenshot({ path: join(artifacts, '4-every-wall.png') });

  // Storeys and columns: a grammar of two floors of three bays; a click on
  // a window, then its storey (3 windows) and its column (2 windows).
  await page.evaluate(() => {
    const t = document.getElementById('text');
    t.value = '@scope 9, 4, 6\nhouse --> split(z){ ~1 : floor | ~1 : floor | ~1 : I(roof) }\n' +
              'floor --> repeatN(x, 3){ split(x){ ~1 : I(wall) | ~1 : I(window) } }\n';
    t.dispatchEvent(new Event('input'));
  });
  await page.waitForFunction(() => window.vernacular.answer.buildings[0].parts.length === 13, { timeout: 20000 });
  const windowAt = await page.evaluate(() => {
    const s = window.vernacular;
    return s.viewer.whereIs((e) => s.answer.labels[s.answer.buildings[e.building].parts[e.part].label] === 'window');
  });
  await page.mouse.click(windowAt.x, windowAt.y);
  await page.waitForSelector('#picked button[data-select=storey]', { timeout: 10000 });
  await page.click('#picked button[data-select=storey]');
  const storey = await page.$eval('#picked', (e) => e.textContent);
  check(storey === 'every window in its storey: 3 parts', `a window's storey: ${JSON.stringify(storey)}`);
  await page.mouse.click(windowAt.x, windowAt.y);
  await page.waitForSelector('#picked button[data-select=column]', { timeout: 10000 });
  await page.click('#picked button[data-select=column]');
  const column = await page.$eval('#picked', (e) => e.textContent);
  check(column === 'every window in its column: 2 parts', `a window's column: ${JSON.stringify(column)}`);
  await page.screenshot({ path: join(artifacts, '5-column.png') });

  // A broken grammar: the error at its line, the last buildings kept.
  await page.evaluate(() => {
    const t = document.getElementById('text');
    t.value = t.value.replace('~1 : I(roof)', '~1 I(roof)');
    t.dispatchEvent(new Event('input'));
  });
  await page.waitForSelector('#error:not([hidden])', { timeout: 10000 });
  const errorLine = await page.$eval('#error', (e) => e.dataset.line);
  const errorText = await page.$eval('#error', (e) => e.textContent);
  const badGutter = await page.$$eval('#gutter .bad', (ls) => ls.map((l) => l.textContent));
  check(errorLine === '2' && /^line 2, column \d+: expected ':'/.test(errorText) && badGutter.join() === '2',
        `a broken grammar shows its error at line 2: ${JSON.stringify(errorText.split('\n')[0])}`);
  const stillThere = await page.evaluate(() => window.vernacular.answer.buildings[0].parts.length);
  check(stillThere === 13, 'the last buildings that derived stay in view');
  await page.screenshot({ path: join(artifacts, '6-error.png') });
  check(errors.length === 0, 'no script error on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
  // The file served is never written.
  check(readFileSync(join(work, 'house.grm'), 'utf8') === HOUSE, 'the grammar file is as it was');

  // The inference view: serve the garage's examples; the grammar inferred
  // from them derives all ten, a plain block none, each with check's reason.
  const examplesPort = await startServe([join(source, 'data', 'examples', 'garage')]);
  const view = await browser.newPage();
  await view.setViewport({ width: 1280, height: 900 });
  view.on('pageerror', (e) => errors.push(String(e)));
  await view.goto(`http://127.0.0.1:${examplesPort}/`);
  const summary = (text) => view.waitForFunction((t) => document.getElementById('checks-summary').textContent === t,
                                                 { timeout: 60000 }, text);
  await summary('examples: 10 of 10 derivable');
  check(true, 'serve EXAMPLES/ starts from their inferred grammar, which derives all ten');
  await view.$eval('#checks', (e) => { e.open = true; });
  await view.screenshot({ path: join(artifacts, '7-examples-checked.png') });
  await view.evaluate(() => {
    const t = document.getElementById('text');
    t.value = 'building --> I(rect)\n';
    t.dispatchEvent(new Event('input'));
  });
  await summary('examples: 0 of 10 derivable');
  const reasons = await view.$$eval('#checks-list li.no pre', (ps) => ps.map((p) => p.textContent));
  check(reasons.length === 10 && reasons.every((r) => r.length > 0), 'a plain block derives none, and check says why for each');
  await view.screenshot({ path: join(artifacts, '8-examples-refused.png') });
  check(errors.length === 0, 'no script error on the examples page' + (errors.length ? ': ' + errors.join('; ') : ''));
} catch (e) {
  console.log('FAIL ' + (e && e.stack ? e.stack : e));
  failures++;
} finally {
  await browser.close();
  for (const server of servers) server.kill();
  rmSync(work, { recursive: true, force: true });
}
console.log(failures ? `${failures} failed` : 'all passed');
process.exit(failures ? 1 : 0);
