// Gives the main module's imports from its JS glue short names, in the module and in the
// glue together: node scripts/minify-imports.mjs MODULE.wasm GLUE.js (run by
// scripts/build-web.sh after wasm-opt, before terser).
//
// wasm-bindgen names each import it writes after its function and a 16-digit hash
// (`__wbg_next_af5ac6a08bb0a717`); the main module imports about 300, and each name is in
// the first load twice, in the module's import section and as a key of the glue's import
// object, where gzip can do little with the hashes (about 5 KB of the first load). Names
// become `a`, `b`, … `Z`, `aa`, …: a key and its import still match exactly, so nothing
// else changes. The glue is read strictly: every import must be a key of the glue's
// `"./plc-web_bg.js"` object exactly once, and every such key an import, or the script
// fails (a new wasm-bindgen writing its glue differently stops the build, never the page).
import { readFileSync, writeFileSync } from 'node:fs';
import { leb, readLeb } from './leb.mjs';

const GLUE_MODULE = './plc-web_bg.js';

const [wasmPath, gluePath] = process.argv.slice(2);
if (!wasmPath || !gluePath) {
  console.error('usage: node scripts/minify-imports.mjs MODULE.wasm GLUE.js');
  process.exit(2);
}

/** A length-prefixed name. */
function name(text) {
  const bytes = Buffer.from(text, 'utf8');
  return Buffer.concat([leb(bytes.length), bytes]);
}

/** The `k`-th short name: a … z, A … Z, then two letters and more. */
function shortName(k) {
  const letters = 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ';
  let out = '';
  do {
    out = letters[k % letters.length] + out;
    k = Math.floor(k / letters.length) - 1;
  } while (k >= 0);
  return out;
}

/** The import section rewritten with the glue's imports renamed; the renaming made. */
function renameImports(body) {
  let [count, at] = readLeb(body, 0);
  const parts = [leb(count)];
  const renamed = new Map();
  for (let i = 0; i < count; i++) {
    const start = at;
    let length;
    [length, at] = readLeb(body, at);
    const module = body.toString('utf8', at, at + length);
    at += length;
    [length, at] = readLeb(body, at);
    const field = body.toString('utf8', at, at + length);
    at += length;
    const descStart = at;
    const kind = body[at++];
    if (kind === 0) [, at] = readLeb(body, at); // function: its type
    else if (kind === 1) { // table: element type, limits
      at++;
      const flags = body[at++];
      [, at] = readLeb(body, at);
      if (flags & 1) [, at] = readLeb(body, at);
    } else if (kind === 2) { // memory: limits
      const flags = body[at++];
      [, at] = readLeb(body, at);
      if (flags & 1) [, at] = readLeb(body, at);
    } else if (kind === 3) at += 2; // global: value type, mutability
    else throw new Error(`import ${module}.${field}: unknown kind ${kind}`);
    if (module === GLUE_MODULE && kind === 0) {
      if (renamed.has(field)) throw new Error(`import ${field} twice`);
      const short = shortName(renamed.size);
      renamed.set(field, short);
      parts.push(name(module), name(short), body.subarray(descStart, at));
    } else {
      parts.push(body.subarray(start, at));
    }
  }
  if (at !== body.length) throw new Error('import section: bytes after the last import');
  return [Buffer.concat(parts), renamed];
}

/** The module with its import section replaced by `rewrite(body)`. */
function withImports(bytes, rewrite) {
  const parts = [bytes.subarray(0, 8)];
  let at = 8;
  let result;
  while (at < bytes.length) {
    const id = bytes[at];
    const [size, bodyAt] = readLeb(bytes, at + 1);
    const end = bodyAt + size;
    if (id === 2) {
      let body;
      [body, result] = rewrite(bytes.subarray(bodyAt, end));
      parts.push(Buffer.from([2]), leb(body.length), body);
    } else {
      parts.push(bytes.subarray(at, end));
    }
    at = end;
  }
  if (!result) throw new Error('the module has no import section');
  return [Buffer.concat(parts), result];
}

/** The glue with the keys of its import object renamed; fails on anything unexpected. */
function renameKeys(glue, renamed) {
  // The object that the glue hands over as the module `./plc-web_bg.js`.
  const handed = new RegExp(`"${GLUE_MODULE.replace(/[./]/g, '\\$&')}": (\\w+),`).exec(glue);
  if (!handed) throw new Error(`the glue hands over no "${GLUE_MODULE}" object`);
  const open = glue.indexOf(`const ${handed[1]} = {\n`);
  const close = glue.indexOf('\n    };\n', open);
  if (open < 0 || close < 0) throw new Error(`the glue's object ${handed[1]} is not where expected`);
  const keys = /^ {8}(\w+): function\(/gm;
  const seen = new Set();
  const object = glue.slice(open, close).replace(keys, (line, key) => {
    const short = renamed.get(key);
    if (!short) throw new Error(`the glue's key ${key} is no import of the module`);
    seen.add(key);
    return line.replace(key, short);
  });
  const missing = [...renamed.keys()].filter((k) => !seen.has(k));
  if (missing.length) throw new Error(`imports the glue has no key for: ${missing.join(', ')}`);
  return glue.slice(0, open) + object + glue.slice(close);
}

try {
  const [wasm, renamed] = withImports(readFileSync(wasmPath), renameImports);
  const glue = renameKeys(readFileSync(gluePath, 'utf8'), renamed);
  writeFileSync(wasmPath, wasm);
  writeFileSync(gluePath, glue);
  console.log(`  ${renamed.size} imports of the main module renamed (scripts/minify-imports.mjs)`);
} catch (e) {
  console.error(`minify-imports.mjs: ${e.message}`);
  process.exit(1);
}
