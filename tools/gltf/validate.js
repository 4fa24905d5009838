// Validates one glTF or GLB file with the Khronos glTF validator (pinned in package-lock.json,
// installed here as `npm ci` would: scripts/setup.sh does it) and prints its figures as one line
// of JSON: {"errors": E, "warnings": W, "infos": I, "hints": H, "messages": [...]}, each
// message "SEVERITY CODE at POINTER: text". Exit status 0 when E is 0, 1 when not, 2 when
// the file could not be read or validated at all. External buffers (a .gltf's .bin) are
// read from beside the file.
//
//   node tools/gltf/validate.js out.glb

const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const severities = ['ERROR', 'WARNING', 'INFO', 'HINT'];

function readBeside(file) {
  return (uri) =>
    new Promise((resolve, reject) => {
      fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (error, data) =>
        error ? reject(error.toString()) : resolve(data));
    });
}

async function main(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 1000,
    externalResourceFunction: readBeside(file),
  });
  const issues = report.issues;
  const messages = issues.messages.map(
    (m) => `${severities[m.severity] || m.severity} ${m.code} at ${m.pointer || m.offset || ''}: ${m.message}`);
  console.log(JSON.stringify({
    errors: issues.numErrors,
    warnings: issues.numWarnings,
    infos: issues.numInfos,
    hints: issues.numHints,
    messages,
  }));
  return issues.numErrors === 0 ? 0 : 1;
}

if (process.argv.length !== 3) {
  console.error('usage: node validate.js FILE.glb|FILE.gltf');
  process.exit(2);
}
main(process.argv[2]).then((status) => process.exit(status), (error) => {
  console.error(`validate.js: ${process.argv[2]}: ${error}`);
  process.exit(2);
});
