// Validates glTF files with the Khronos glTF validator (npm package gltf-validator).
// Usage: node validate.mjs FILE.glb|FILE.gltf ...  Exits non-zero on any error or warning.
import { readFile } from 'node:fs/promises';
import validator from 'gltf-validator';

let failed = 0;
for (const file of process.argv.slice(2)) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, {
    maxIssues: 100,
    // Our buffers are embedded or in the GLB BIN chunk: nothing external to load.
    externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}`)),
  });
  const { numErrors, numWarnings, numInfos } = report.issues;
  const counts = report.info ? `${report.info.drawCallCount} draw calls, ${report.info.totalVertexCount} vertices` : '';
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos; ${counts}`);
  for (const m of report.issues.messages) {
    if (m.severity <= 1) console.log(`  [${m.severity === 0 ? 'error' : 'warning'}] ${m.code} ${m.pointer ?? ''}: ${m.message}`);
  }
  if (numErrors > 0 || numWarnings > 0) failed += 1;
}
if (failed > 0) {
  console.log(`${failed} file(s) failed validation`);
  process.exit(1);
}
