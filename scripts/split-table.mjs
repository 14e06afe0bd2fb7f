// wasm-split's loader (`__wasm_split.js`, scripts/build-web.sh step 3) written as a table:
// one function fetches any file, and each split names its chunks by number, in place of
// one closure per chunk (365 of them, 4.4 KB of the first load gzipped; 2.6 KB as a table).
// scripts/pack.mjs writes it, with the files it packed fetched from their pack. (What each
// split needs is read from wasm-split's own form by scripts/wasm-split-parts.mjs, before this.)

const HEAD_END = /\/\*[^*]*\*\/\nconst __chunk_\d+ = /;
const CHUNK = /(?:\/\*[^*]*\*\/\n)?const __chunk_(\d+) = makeLoad\(\(\) => \{\s*const src = fetch\(new URL\("\.\/chunk_\1\.wasm", import\.meta\.url\)\);\s*src\.catch\(\(\) => \{\}\);\s*return async \(imports\) => \(WebAssembly\.instantiateStreaming\(src, imports\)\);\s*\}\s*, \[\]\);\n?/g;
const SPLIT = /(?:\/\*[^*]*\*\/\n)?export const (__wasm_split_load_\w+) = wrapAsyncCb\(makeLoad\(\(\) => \{\s*const src = fetch\(new URL\("\.\/([\w.]+\.wasm)", import\.meta\.url\)\);\s*src\.catch\(\(\) => \{\}\);\s*return async \(imports\) => \(WebAssembly\.instantiateStreaming\(src, imports\)\);\s*\}\s*, \[([^\]]*)\]\)\);\n?/g;

/**
 * `js` (the loader wasm-split wrote) as a table; `loader` (JS defining `__fromPack(pack,
 * file)`) goes after its imports, and a file of `packed` (file → pack) comes out of its
 * pack. Throws when `js` holds anything it does not know, so that a new wasm-split cannot
 * lose a part silently.
 */
export function tableForm(js, loader, packed) {
  const end = HEAD_END.exec(js);
  if (!end) throw new Error('__wasm_split.js: no chunk after the helpers');
  const head = js.slice(0, end.index);
  const body = js.slice(end.index);
  const chunks = new Set([...body.matchAll(CHUNK)].map((m) => Number(m[1])));
  const splits = [...body.matchAll(SPLIT)].map((m) => ({
    exported: m[1],
    file: m[2],
    chunks: m[3].split(',').map((s) => s.trim()).filter(Boolean).map((c) => Number(c.replace(/^__chunk_/, ''))),
  }));
  const left = body.replace(CHUNK, '').replace(SPLIT, '').trim();
  if (left) throw new Error(`__wasm_split.js: not understood: ${left.slice(0, 200)}`);
  for (const s of splits) {
    for (const c of s.chunks) if (!chunks.has(c)) throw new Error(`${s.file} needs chunk ${c}, which is not defined`);
  }
  const files = new Set([...[...chunks].map((c) => `chunk_${c}.wasm`), ...splits.map((s) => s.file)]);
  const byPack = {};
  for (const [file, pack] of packed) {
    if (!files.has(file)) throw new Error(`__wasm_split.js does not fetch ${file}`);
    (byPack[pack] ??= []).push(file);
  }
  const firstImport = /^import [^\n]*\n/m;
  if (!firstImport.test(head)) throw new Error('__wasm_split.js: no import line to put the pack loader after');
  return `${head.replace(firstImport, (line) => line + loader)}
// The files each pack holds (scripts/pack.mjs).
const __packed = ${JSON.stringify(byPack)};
const __packOf = new Map(Object.entries(__packed).flatMap(([pack, files]) => files.map((file) => [file, pack])));
/** Fetches \`file\` (out of its pack when packed) and instantiates it. */
function __fetcher(file) {
    return () => {
        const pack = __packOf.get(file);
        const src = pack === undefined ? fetch(new URL("./" + file, import.meta.url)) : __fromPack(pack, file);
        src.catch(() => {});
        return async (imports) => (WebAssembly.instantiateStreaming(src, imports));
    };
}
const __chunks = new Map();
/** Chunk \`n\`'s loader, made once: the splits that need it share it. */
function __chunk(n) {
    let load = __chunks.get(n);
    if (load === undefined) {
        load = makeLoad(__fetcher("chunk_" + n + ".wasm"), []);
        __chunks.set(n, load);
    }
    return load;
}
/** A split's loader: its own file once the chunks it needs are loaded. */
function __split(file, chunks) {
    return wrapAsyncCb(makeLoad(__fetcher(file), chunks.map(__chunk)));
}
${splits.map((s) => `export const ${s.exported} = __split(${JSON.stringify(s.file)}, [${s.chunks.join(',')}]);`).join('\n')}
`;
}
