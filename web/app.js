// The page: the editor on the left, the buildings on the right; every edit
// derives again (the newest answer wins), a click on a part shows the rules
// that made it, a rule's line lights the parts it made.
import { Editor } from '/editor.js';
import { Viewer } from '/viewer.js';

const $ = (id) => document.getElementById(id);
const state = { answer: null, examples: null, asked: 0, shown: 0, derivations: 0 };
window.vernacular = state;  // for the browser tests and the curious

const editor = new Editor({
  text: $('text'), highlight: $('highlight'), gutter: $('gutter'),
  onChange: () => schedule(),
  onLine: (line) => lightLine(line),
});
const viewer = new Viewer($('view'), (entry, event) => showPicked(entry, event));
state.viewer = viewer;

// Constants written as plain numbers (`depth = 0.7`) get a slider each;
// moving it overrides the value in what is derived, not in the text.
const overrides = new Map();  // name -> value
const CONSTANT = /^(\s*)([A-Za-z_][A-Za-z0-9_]*)(\s*=\s*)(-?\d+(?:\.\d+)?(?:e[+-]?\d+)?)(.*)$/;

function constantsOf(text) {
  const found = [];
  for (const line of text.split('\n')) {
    if (/-->|->|→/.test(line)) break;  // constants come before the rules
    const m = CONSTANT.exec(line);
    if (m && !/^\s*(#|\/\/|$)/.test(m[5])) continue;
    if (m) found.push({ name: m[2], value: Number(m[4]) });
  }
  return found;
}

function textToDerive() {
  if (!overrides.size) return editor.value;
  let rules = false;
  return editor.value.split('\n').map((line) => {
    if (/-->|->|→/.test(line)) rules = true;
    const m = !rules && CONSTANT.exec(line);
    return m && overrides.has(m[2]) ? m[1] + m[2] + m[3] + String(overrides.get(m[2])) + m[5] : line;
  }).join('\n');
}

function showConstants() {
  const panel = $('constants');
  const found = constantsOf(editor.value);
  for (const name of [...overrides.keys()]) if (!found.some((c) => c.name === name)) overrides.delete(name);
  const key = found.map((c) => c.name + '=' + c.value).join(',');
  if (panel.dataset.key === key) return;
  panel.dataset.key = key;
  panel.hidden = found.length === 0;
  panel.innerHTML = '';
  for (const c of found) {
    const span = c.value === 0 ? 1 : Math.abs(c.value) * 2;
    const label = document.createElement('label');
    label.textContent = c.name;
    const slider = Object.assign(document.createElement('input'), {
      type: 'range', min: Math.min(0, c.value * 2), max: c.value < 0 ? 0 : span, step: span / 200,
      value: overrides.has(c.name) ? overrides.get(c.name) : c.value,
    });
    slider.dataset.constant = c.name;
    const shown = document.createElement('span');
    const reset = Object.assign(document.createElement('button'), { textContent: 'reset', title: 'back to the value in the text' });
    const update = () => {
      const over = overrides.has(c.name);
      shown.textContent = over ? String(overrides.get(c.name)) : String(c.value);
      shown.className = over ? 'over' : '';
      reset.hidden = !over;
    };
    slider.addEventListener('input', () => {
      overrides.set(c.name, Number(Number(slider.value).toPrecision(6)));
      update();
      schedule();
    });
    reset.addEventListener('click', () => {
      overrides.delete(c.name);
      slider.value = c.value;
      update();
      schedule();
    });
    update();
    panel.append(label, slider, shown, reset);
  }
}

// One request in flight; edits meanwhile ask again once it is back.
let busy = false, again = false;
function schedule() {
  if (busy) { again = true; return; }
  derive();
}

async function derive() {
  busy = true;
  again = false;
  const asked = ++state.asked;
  const started = performance.now();
  showConstants();
  const request = { text: textToDerive(), seed: Number($('seed').value) || 0, count: Math.min(64, Math.max(1, Number($('count').value) || 1)) };
  // A plot given on all three axes replaces the grammar's @scope.
  const plot = ['plot-x', 'plot-y', 'plot-z'].map((id) => Number($(id).value));
  if (plot.every((v) => v > 0)) request.size = plot;
  const body = JSON.stringify(request);
  try {
    const response = await fetch('/api/derive', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body });
    const answer = await response.json();
    if (asked >= state.shown) {
      state.shown = asked;
      show(answer, performance.now() - started);
    }
  } catch (e) {
    $('status').textContent = 'the server does not answer: ' + e.message;
  } finally {
    busy = false;
    if (again) derive();
  }
}

function show(answer, ms) {
  if (!answer.ok) {
    const e = answer.error;
    $('error').hidden = false;
    $('error').textContent = (e.line ? `line ${e.line}, column ${e.column}: ` : '') + e.message + (e.hint ? '\nhint: ' + e.hint : '');
    $('error').dataset.line = e.line || '';
    editor.markError(e.line);
    $('status').textContent = 'error (the buildings shown are the last that derived)';
    return;
  }
  $('error').hidden = true;
  $('error').dataset.line = '';
  editor.markError(0);
  state.answer = answer;
  state.derivations++;
  viewer.show(answer, $('show-examples').checked ? state.examples : null);
  checkExamples();
  $('picked').hidden = true;
  const parts = answer.buildings.reduce((n, b) => n + b.parts.length, 0);
  $('status').textContent = `${answer.buildings.length} building${answer.buildings.length === 1 ? '' : 's'}, ${parts} parts, ${Math.round(ms)} ms` +
    (answer.note ? ` (${answer.note})` : '');
}

// With examples: does the text derive each (check's witness), or where
// does it fail (check's reason)? Asked once the buildings are drawn, and
// again after each edit that derives.
let checking = false, checkAgain = false;
async function checkExamples() {
  if (!state.examples) return;
  if (checking) { checkAgain = true; return; }
  checking = true;
  checkAgain = false;
  try {
    const response = await fetch('/api/check', { method: 'POST', headers: { 'Content-Type': 'application/json' },
                                                 body: JSON.stringify({ text: textToDerive() }) });
    const answer = await response.json();
    if (answer.ok) showChecks(answer.examples);
  } finally {
    checking = false;
    if (checkAgain) checkExamples();
  }
}

function linked(text) {
  // "split(x) at 24:10": a place in the text, lit when clicked.
  return text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;')
    .replace(/\b(\d+):(\d+)\b/g, '<span class="at" data-line="$1">$1:$2</span>');
}

function showChecks(examples) {
  const derivable = examples.filter((e) => e.derivable).length;
  $('checks').hidden = false;
  $('checks-summary').textContent = `examples: ${derivable} of ${examples.length} derivable`;
  $('checks-summary').className = derivable === examples.length ? 'yes' : 'no';
  state.checks = examples;
  $('checks-list').innerHTML = examples.map((e) =>
    `<li class="${e.derivable ? 'yes' : 'no'}">${linked(e.name)}: ${e.derivable ? 'derivable' : 'not derivable'}` +
    `<pre>${linked(e.derivable ? e.witness.join('\n') : e.reason)}</pre></li>`).join('');
}
$('checks-list').addEventListener('click', (event) => {
  const at = event.target.closest('.at');
  if (at) editor.light([Number(at.dataset.line)]);
});

function partOf(entry) {
  return state.answer.buildings[entry.building].parts[entry.part];
}

// A part's storey: the innermost split part or repeat tile it lies in
// along z ("op:index"). Its column: the parts and tiles along x or y it
// lies in below that (the bay of a row, and the window's half of the bay),
// which the same bay of every storey shares. null when there is none.
function tag(part, horizontal) {
  let storey = -1;
  part.path.forEach(([, , axis], i) => { if (axis === 2) storey = i; });
  if (!horizontal) return storey < 0 ? null : `${part.path[storey][0]}:${part.path[storey][1]}`;
  const below = part.path.slice(storey + 1).filter(([, , axis]) => axis !== 2).map(([op, index]) => `${op}:${index}`);
  return below.length ? below.join('/') : null;
}

// Alike parts, lit: every part of the picked one's label (in every
// building), or those of them in its storey or its column (of its building:
// the same part or tile of the same split or repeat along z, or along x or y).
function selectAlike(entry, kind) {
  const picked = partOf(entry);
  const key = kind === 'storey' ? tag(picked, false) : kind === 'column' ? tag(picked, true) : null;
  const count = viewer.lightWhere((e) => {
    const p = partOf(e);
    if (p.label !== picked.label) return false;
    if (kind === 'label') return true;  // in every building
    return e.building === entry.building && tag(p, kind === 'column') === key;
  });
  const what = kind === 'label' ? '' : kind === 'storey' ? ' in its storey' : ' in its column';
  $('picked').hidden = false;
  $('picked').textContent = `every ${state.answer.labels[picked.label]}${what}: ${count} part${count === 1 ? '' : 's'}`;
}

function showPicked(entry, event) {
  if (entry && event && event.shiftKey) return selectAlike(entry, 'label');
  if (!entry) {
    $('picked').hidden = true;
    editor.light([]);
    return;
  }
  const part = partOf(entry);
  const rules = part.rules.map((r) => state.answer.rules[r]);
  $('picked').hidden = false;
  $('picked').textContent = `${state.answer.labels[part.label]} (building ${entry.building + 1}, seed ${state.answer.buildings[entry.building].seed})\n` +
    `made by: ${part.chain}\ninserted at line ${part.at[0]}, column ${part.at[1]}` +
    `\nrules: ${rules.map((r) => r.label + ' (line ' + r.line + ')').join(' > ')}`;
  editor.light([part.at[0], ...rules.map((r) => r.line)]);
  // Select alike parts from here.
  const buttons = document.createElement('div');
  const name = state.answer.labels[part.label];
  for (const [kind, text] of [['label', `every ${name}`], ['storey', `${name}s of its storey`], ['column', `${name}s of its column`]]) {
    if (kind !== 'label' && tag(part, kind === 'column') === null) continue;
    const b = Object.assign(document.createElement('button'), { textContent: text });
    b.dataset.select = kind;
    b.addEventListener('click', () => selectAlike(entry, kind));
    buttons.append(b, ' ');
  }
  $('picked').append(buttons);
}

// The cursor on a line lights the parts made there: inserted by it, or
// derived through the rule that starts on it.
function lightLine(line) {
  if (!state.answer) return;
  const rulesHere = new Set(state.answer.rules.map((r, i) => (r.line === line ? i : -1)).filter((i) => i >= 0));
  viewer.lightWhere((entry) => {
    const p = partOf(entry);
    return p.at[0] === line || p.rules.some((r) => rulesHere.has(r));
  });
}

function step(by) {
  $('seed').value = Math.max(0, (Number($('seed').value) || 0) + by);
  schedule();
}
$('previous').addEventListener('click', () => step(-1));
$('next').addEventListener('click', () => step(1));
$('seed').addEventListener('input', () => schedule());
$('count').addEventListener('input', () => schedule());
for (const id of ['plot-x', 'plot-y', 'plot-z']) $(id).addEventListener('input', () => schedule());
$('show-examples').addEventListener('change', () => state.answer && viewer.show(state.answer, $('show-examples').checked ? state.examples : null));
$('save').addEventListener('click', () => {
  // A copy where the browser saves files: the server never writes the grammar it was given.
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([editor.value], { type: 'text/plain' }));
  a.download = $('name').textContent || 'style.grm';
  a.click();
  URL.revokeObjectURL(a.href);
});

const session = await (await fetch('/api/session')).json();
$('name').textContent = session.name;
document.title = session.name + ' - Vernacular';
if (session.examples.length) {
  state.examples = { list: session.examples, colours: session.colours };
  $('examples-toggle').hidden = false;
}
editor.value = session.text;
derive();
