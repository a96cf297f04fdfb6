// Runs the Khronos glTF validator (npm package gltf-validator) on one .glb or
// .gltf file and prints "errors N warnings N infos N hints N", then each
// error (and, with --verbose, every issue) on its own line. Exit status: 0
// when there are no errors, 1 when there are, 2 when the validator or the
// file cannot be loaded.
//   node tests/gltf/validate.js [--verbose] FILE
//   node tests/gltf/validate.js --check      exit 0 when the validator loads
// The validator is looked up in $M3G_GLTF_VALIDATOR (a package directory),
// on NODE_PATH, then in build/tools/node_modules (where scripts/setup puts it).
'use strict';
const fs = require('fs');
const path = require('path');

function loadValidator() {
  const candidates = [];
  if (process.env.M3G_GLTF_VALIDATOR) candidates.push(process.env.M3G_GLTF_VALIDATOR);
  candidates.push('gltf-validator');
  candidates.push(path.resolve(__dirname, '..', '..', 'build', 'tools', 'node_modules', 'gltf-validator'));
  for (const c of candidates) {
    try {
      return require(c);
    } catch (e) {
      // try the next place
    }
  }
  throw new Error('gltf-validator not found');
}

async function main() {
  const args = process.argv.slice(2);
  if (args[0] === '--check') {  // is the validator installed? (exit status)
    try {
      loadValidator();
      process.exit(0);
    } catch (e) {
      process.exit(2);
    }
  }
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
