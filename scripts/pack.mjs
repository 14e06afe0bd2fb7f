// One file for a part that wasm-split cut into many (docs/loading.md, "One file for the
// engine"): scripts/build-web.sh runs it on the app folder before the JS is minified.
//
//   node scripts/pack.mjs WORK SPLIT... [--apart OTHER...]
//
// For each SPLIT (a `#[wasm_split]` name, e.g. `engine`), the split's own module and every
// chunk it needs go into WORK/app/pack_SPLIT.wasm, and leave the folder: a wasm module made
// of custom sections only, one per file, named by the file (so a host serves and compresses
// it as wasm). WORK/app/__wasm_split.js, written again as a table (scripts/split-table.mjs),
// then fetches those files from the pack, one fetch for all, and every other file as
// before. A chunk is packed once, with the first SPLIT that needs it. WORK/packs.json lists what each pack holds (scripts/site.mjs reads it).
// A chunk that a split named after `--apart` needs too stays a file of its own, so that
// OTHER never waits for a pack (the readers of a stored project's diagram POUs, fetched
// as the page starts when the project has such POUs, share code with the engine).
//
// Why: wasm-split makes one chunk for each set of splits that share code, so the engine was
// 74 files; on a 60 ms network with six connections per host they held the connections for
// about twelve round trips, and the next part asked for (the ladder editor) waited behind.
import { readFileSync, writeFileSync, rmSync } from 'node:fs';
import { join } from 'node:path';
import { splitParts } from './wasm-split-parts.mjs';
import { tableForm } from './split-table.mjs';
import { leb } from './leb.mjs';

const [work, ...rest] = process.argv.slice(2);
const cut = rest.indexOf('--apart');
const names = cut < 0 ? rest : rest.slice(0, cut);
const apartNames = cut < 0 ? [] : rest.slice(cut + 1);
if (!work || names.length === 0) {
  console.error('usage: node scripts/pack.mjs WORK SPLIT... [--apart OTHER...]');
  process.exit(2);
}
const app = join(work, 'app');
const jsPath = join(app, '__wasm_split.js');
let js = readFileSync(jsPath, 'utf8');

/** A wasm module holding `files` (name → bytes) as custom sections. */
function packOf(files) {
  const parts = [Buffer.from([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0])];
  for (const [name, bytes] of files) {
    const label = Buffer.from(name, 'utf8');
    const payload = Buffer.concat([leb(label.length), label, bytes]);
    parts.push(Buffer.from([0]), leb(payload.length), payload);
  }
  return Buffer.concat(parts);
}

const all = splitParts(js);
const apart = new Set(apartNames.flatMap((name) => {
  if (!all.has(name)) throw new Error(`no split named ${name} in ${jsPath}`);
  return all.get(name);
}));
const packed = new Map(); // file → pack
const packs = {};
for (const name of names) {
  const files = all.get(name);
  if (!files) throw new Error(`no split named ${name} in ${jsPath}`);
  const pack = `pack_${name}.wasm`;
  const mine = files.filter((f) => !packed.has(f) && !apart.has(f));
  writeFileSync(join(app, pack), packOf(mine.map((f) => [f, readFileSync(join(app, f))])));
  for (const f of mine) {
    packed.set(f, pack);
    rmSync(join(app, f));
  }
  packs[pack] = mine;
  console.log(`  ${pack}: ${mine.length} files in one`);
}

// The loader: a packed file comes out of its pack (fetched once, kept for the others).
const loader = `
// Files packed into one (scripts/pack.mjs): the first one asked for fetches the pack.
const __packs = new Map();
function __openPack(pack) {
  let opening = __packs.get(pack);
  if (opening === undefined) {
    opening = fetch(new URL("./" + pack, import.meta.url)).then((response) => {
      if (!response.ok) throw new Error(pack + ": HTTP " + response.status);
      return response.arrayBuffer();
    }).then((buffer) => {
      // A module of custom sections only, each one file named by its section.
      const bytes = new Uint8Array(buffer);
      const files = new Map();
      let at = 8;
      const leb = () => {
        let n = 0, shift = 0, byte;
        do { byte = bytes[at++]; n += (byte & 0x7f) * 2 ** shift; shift += 7; } while (byte & 0x80);
        return n;
      };
      const text = new TextDecoder();
      while (at < bytes.length) {
        at++;
        const end = leb() + at;
        const length = leb();
        files.set(text.decode(bytes.subarray(at, at + length)), bytes.subarray(at + length, end));
        at = end;
      }
      return files;
    });
    // A failed fetch is not kept: the next load tries again.
    opening.catch(() => { if (__packs.get(pack) === opening) __packs.delete(pack); });
    __packs.set(pack, opening);
  }
  return opening;
}
function __fromPack(pack, name) {
  return __openPack(pack).then((files) => new Response(files.get(name), { headers: { "content-type": "application/wasm" } }));
}
`;
js = tableForm(js, loader, packed);
writeFileSync(jsPath, js);
writeFileSync(join(work, 'packs.json'), `${JSON.stringify(packs, null, 1)}\n`);
