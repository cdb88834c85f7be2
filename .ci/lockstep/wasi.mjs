// Runs a WASI (preview 1) module under Node's built-in `node:wasi`, passing its exit status on.
// Usage: node --no-warnings --experimental-wasi-unstable-preview1 wasi.mjs module.wasm [args...]
// (the flag is needed by Node 18, accepted and ignored by Node 20 and later).
import { readFile } from 'node:fs/promises';
import { argv, exit } from 'node:process';
import { WASI } from 'node:wasi';

const [file, ...args] = argv.slice(2);
if (!file) {
  console.error('usage: node wasi.mjs module.wasm [args...]');
  exit(2);
}
const wasi = new WASI({ version: 'preview1', args: [file, ...args], env: {}, returnOnExit: true });
const module = await WebAssembly.compile(await readFile(file));
// getImportObject() is Node 19.8 and later; Node 18 has only the import itself.
const imports = wasi.getImportObject?.() ?? { wasi_snapshot_preview1: wasi.wasiImport };
const instance = await WebAssembly.instantiate(module, imports);
exit(wasi.start(instance) ?? 0);
