// Runs the Khronos glTF validator (npm package gltf-validator) on one .glb or
// .gltf file and prints "errors N warnings N infos N hints N", then each
// error (and, with --verbose, every issue) on its own line. Exit status: 0
// when there are no errors, 1 when there are, 2 when the validator or the
// file cannot be loaded.
//   node tests/gltf/validate.js [--verbose] FILE
// The validator is looked up on NODE_PATH, then in build/tools/node_modules
// (where scripts/setup installs it).
'use strict';
const fs = require('fs');
const path = require('path');

function loadValidator() {
  try {
    return require('gltf-validator');
  } catch (e) {
    const local = path.resolve(__dirname, '..', '..', 'build', 'tools', 'node_modules', 'gltf-validator');
    return require(local);
  }
}

async function main() {
  const args = process.argv.slice(2);
  const verbose = args.includes('--verbose');
  const file = args.filter((a) => a !== '--verbose')[0];
  if (!file) {
    console.error('usage: node validate.js [--verbose] FILE.glb|FILE.gltf');
    process.exit(2);
  }
  let validator;
  try {
    validator = loadValidator();
  } catch (e) {
    console.error('gltf-validator not found (npm install --prefix build/tools gltf-validator)');
    process.exit(2);
  }
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,  // all of them
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (err, data) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(data)));
      }),
  });
  const i = report.issues;
  console.log(`errors ${i.numErrors} warnings ${i.numWarnings} infos ${i.numInfos} hints ${i.numHints}`);
  for (const m of i.messages) {
    if (m.severity === 0 || verbose) console.log(`  [${m.severity}] ${m.code} ${m.pointer || ''} ${m.message}`);
  }
  process.exit(i.numErrors === 0 ? 0 : 1);
}

main().catch((e) => {
  console.error(String(e));
  process.exit(2);
});
