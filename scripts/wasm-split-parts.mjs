// What wasm-split's loader (`__wasm_split.js`, scripts/build-web.sh step 3) fetches for each
// split: read by scripts/pack.mjs and scripts/site.mjs.

/** split name → its own file and the chunk files it needs, from the loader's source. */
export function splitParts(source) {
  const chunks = new Map();
  for (const m of source.matchAll(/const (__chunk_\d+) = makeLoad\(\(\) => \{\s*const src = fetch\(new URL\("\.\/([^"]+)"/g)) {
    chunks.set(m[1], m[2]);
  }
  const out = new Map();
  const exportRe = /export const __wasm_split_load_(\w+) = wrapAsyncCb\(makeLoad\(([\s\S]*?)\n?, \[([^\]]*)\]\)\)/g;
  for (const m of source.matchAll(exportRe)) {
    const own = /"\.\/([^"]+\.wasm)"/.exec(m[2]);
    const deps = m[3].split(',').map((s) => s.trim()).filter(Boolean).map((c) => chunks.get(c));
    out.set(m[1], [...(own ? [own[1]] : []), ...deps]);
  }
  return out;
}
