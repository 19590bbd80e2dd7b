// Runs the Khronos glTF validator (a JavaScript library, no command line)
// on each file named: one summary line per file, then its errors and
// warnings. Exit status 1 when any file has an error. Called by
// scripts/validate-gltf, which installs the library into $VERN_TOOLS.
import { createRequire } from 'node:module';
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const tools = process.env.VERN_TOOLS;
if (!tools) {
  console.error('validate-gltf.mjs: run it through scripts/validate-gltf');
  process.exit(2);
}
const require = createRequire(path.join(tools, 'node_modules', 'noop.js'));
const validator = require('gltf-validator');

const severities = ['error', 'warning', 'info', 'hint'];
let failed = false;
for (const file of process.argv.slice(2)) {
  let bytes;
  try {
    bytes = new Uint8Array(await readFile(file));
  } catch (e) {
    console.log(`${file}: cannot read: ${e.message}`);
    failed = true;
    continue;
  }
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    // A .gltf may name buffers beside it.
    externalResourceFunction: (uri) =>
      readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
  });
  const i = report.issues;
  console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
  for (const m of i.messages) {
    if (m.severity <= 1) {
      console.log(`  ${severities[m.severity]}: ${m.code} at ${m.pointer ?? '/'}: ${m.message}`);
    }
  }
  if (i.numErrors > 0) failed = true;
}
process.exit(failed ? 1 : 0);
