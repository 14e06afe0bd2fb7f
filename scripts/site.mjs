// The last steps of scripts/build-web.sh (see docs/loading.md).
//
//   node scripts/site.mjs assemble DIST WORK   puts the app (WORK/app: the bound and
//       optimised main module, its chunks, their JS) into DIST/app-<hash of its files>/ and
//       starts it from DIST/index.html (preloads and one inline module script);
//   node scripts/site.mjs finish DIST WORK     writes DIST/sw.js (the service worker, from
//       web/sw.js) with the build's id and file list, prints every part of the site with
//       its gzip -9 size and fails when the first load is over the README's budget, a part
//       loaded on first use is over 200 KB, opening an exercise adds over 150 KB, or the
//       first load holds code it must not (ladder editor, Petri net editor, exporters:
//       found by function name in WORK/main-names.wasm, the main module before wasm-opt
//       drops the names).
import { readFileSync, writeFileSync, readdirSync, statSync, mkdirSync, copyFileSync } from 'node:fs';
import { createHash } from 'node:crypto';
import { dirname, join, relative, sep } from 'node:path';
import { gzipSync } from 'node:zlib';
import { fileURLToPath } from 'node:url';
import { splitParts } from './wasm-split-parts.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const [mode, dist = 'dist', work = 'target/site'] = process.argv.slice(2);
const LAZY_LIMIT = 200 * 1024;
/** What opening an exercise may add to the first load and the parts fetched at start. */
const EXERCISE_LIMIT = 150 * 1024;
/**
 * The parts the page fetches as soon as it starts, while the first screen is drawn (the
 * engine's checker and compiler: web/src/lazy.rs, `load_engine`). They are not in the first
 * load, but every later part finds them already fetched.
 */
const START_UP = ['engine'];

/** Every file under `dir`, as paths relative to it with `/`, sorted. */
function walk(dir) {
  const out = [];
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) out.push(...walk(path).map((p) => `${name}/${p}`));
    else out.push(name);
  }
  return out.sort();
}

function hashOf(dir, files) {
  const h = createHash('sha256');
  for (const f of files) h.update(f).update('\0').update(readFileSync(join(dir, f)));
  return h.digest('hex');
}

const gz = (file) => gzipSync(readFileSync(file), { level: 9 }).length;
const kb = (n) => `${(n / 1024).toFixed(1)} KB`;

/** The app folder in dist (`app-<hash>`). */
function appFolder() {
  const found = readdirSync(dist).filter((f) => /^app-[0-9a-f]+$/.test(f));
  if (found.length !== 1) throw new Error(`expected one app-* folder in ${dist}, found ${found.length}`);
  return found[0];
}

function assemble() {
  const app = join(work, 'app');
  const files = walk(app);
  const folder = `app-${hashOf(app, files).slice(0, 12)}`;
  mkdirSync(join(dist, folder), { recursive: true });
  for (const f of files) {
    mkdirSync(dirname(join(dist, folder, f)), { recursive: true });
    copyFileSync(join(app, f), join(dist, folder, f));
  }
  const index = join(dist, 'index.html');
  let html = readFileSync(index, 'utf8');
  const start = [
    `<link rel="modulepreload" href="./${folder}/boot.js">`,
    `<link rel="modulepreload" href="./${folder}/plc-web.js">`,
    `<link rel="modulepreload" href="./${folder}/__wasm_split.js">`,
    `<link rel="preload" href="./${folder}/plc-web_bg.wasm" as="fetch" type="application/wasm" crossorigin>`,
    `<script type="module">import"./${folder}/boot.js"</script>`,
  ].join('');
  // Trunk leaves the skipped Rust link (web/index.html) where the app starts.
  const skipped = /<link data-trunk[^>]*data-trunk-skip[^>]*>/;
  if (!skipped.test(html)) throw new Error(`no skipped Rust link in ${index} to start the app at`);
  html = html.replace(skipped, start);
  writeFileSync(index, html);
  console.log(`  the app is in ${dist}/${folder}/ (${files.length} files)`);
}

/** split name → the chunk files it needs (its own and the shared ones), from the link JS. */
function splits() {
  return splitParts(readFileSync(join(work, 'split', '__wasm_split.js'), 'utf8'));
}

/** The code the first load must not hold: path prefixes of Rust functions. */
const FORBIDDEN = [
  ['the ladder editor', 'plc_web::components::ladder::'],
  ['the Petri net editor', 'plc_web::components::petri::'],
  ['the network view', 'plc_web::components::network::'],
  ['the SFC chart', 'plc_web::components::sfc::'],
  ['the PLCopen XML writer', 'plc_core::plcopen::export'],
  ['the PNML writer', 'plc_core::pnml::export'],
  ['the exercise worker', 'plc_web::workers::exercise::'],
  ['the import worker', 'plc_web::workers::import::'],
  ['the SCORM runtime', 'plc_web::exercises::scorm::'],
  ['the SCORM packer', 'plc_core::exercise::scorm::'],
  ['the ZIP writer', 'plc_core::export::zip::'],
  // Fetched at start (`engine`), while the first screen is drawn.
  ['the ST checker', 'plc_core::semantic::check'],
  ['the compiler', 'plc_core::compile::'],
  ['the ST parser', 'plc_core::syntax::parser::Parser'],
  ['the virtual machine', 'plc_core::vm::machine::'],
  ['the fast scan path', 'plc_core::vm::fast::'],
  ['the standard functions', 'plc_core::vm::builtins::'],
  // Fetched with the first project that has diagram POUs (`project_reader`).
  ['the ladder model\'s reader', 'plc_core::ladder::model::_::_<impl serde_core::de::Deserialize'],
  ['the network model\'s reader', 'plc_core::network::model::_::_<impl serde_core::de::Deserialize'],
  ['the Petri net model\'s reader', 'plc_core::petri::model::_::_<impl serde_core::de::Deserialize'],
];

/** Each function of a wasm module with a name section: its Rust path and code size. */
function functionPaths(file) {
  const b = readFileSync(file);
  const leb = (i) => { let r = 0, s = 0, x; do { x = b[i++]; r += (x & 0x7f) * 2 ** s; s += 7; } while (x & 0x80); return [r, i]; };
  const names = new Map();
  const sizes = [];
  let imported = 0;
  let i = 8;
  while (i < b.length) {
    const id = b[i++];
    let size; [size, i] = leb(i);
    const end = i + size;
    if (id === 2) {
      let [n, k] = leb(i);
      for (let c = 0; c < n; c++) {
        let l; [l, k] = leb(k); k += l; [l, k] = leb(k); k += l;
        const kind = b[k++];
        if (kind === 0) { imported++; [, k] = leb(k); }
        else if (kind === 1) { k++; const fl = b[k++]; [, k] = leb(k); if (fl & 1) [, k] = leb(k); }
        else if (kind === 2) { const fl = b[k++]; [, k] = leb(k); if (fl & 1) [, k] = leb(k); }
        else k += 2;
      }
    } else if (id === 10) {
      let [n, k] = leb(i);
      for (let c = 0; c < n; c++) { let l; [l, k] = leb(k); sizes.push(l); k += l; }
    } else if (id === 0) {
      let [len, j] = leb(i);
      if (b.toString('utf8', j, j + len) === 'name') {
        j += len;
        while (j < end) {
          const sub = b[j++];
          let subSize; [subSize, j] = leb(j);
          if (sub === 1) {
            let [n, k] = leb(j);
            for (let c = 0; c < n; c++) {
              let index, l; [index, k] = leb(k); [l, k] = leb(k);
              names.set(index, b.toString('utf8', k, k + l)); k += l;
            }
          }
          j += subSize;
        }
      }
    }
    i = end;
  }
  const path = (name) => {
    const m = /^_?_ZN(.*)E$/.exec(name);
    if (!m) return name;
    const segs = [];
    for (let s = m[1], k = 0; k < s.length;) {
      const d = /^\d+/.exec(s.slice(k));
      if (!d) break;
      k += d[0].length;
      segs.push(s.slice(k, k + Number(d[0])));
      k += Number(d[0]);
    }
    return segs.join('::').replaceAll('$LT$', '<').replaceAll('$GT$', '>').replaceAll('..', '::')
      .replaceAll('$u20$', ' ').replaceAll('$RF$', '&');
  };
  return sizes.map((size, k) => ({ path: path(names.get(imported + k) ?? ''), size }));
}

function finish() {
  const folder = appFolder();
  const files = walk(dist).filter((f) => f !== 'sw.js');
  const build = hashOf(dist, files).slice(0, 16);
  const list = files.map((f) => f.split('/').map(encodeURIComponent).join('/'));
  const sw = readFileSync(join(root, 'web', 'sw.js'), 'utf8')
    .replace("'%BUILD_ID%'", JSON.stringify(build))
    .replace('%FILES%', JSON.stringify(list, null, 0));
  writeFileSync(join(dist, 'sw.js'), sw);
  console.log(`  service worker: build ${build}, ${list.length} files precached`);

  const size = new Map();
  const sizeOf = (f) => { if (!size.has(f)) size.set(f, gz(join(dist, f))); return size.get(f); };
  const css = files.filter((f) => !f.includes('/') && f.endsWith('.css'));
  const first = [...css, ...['boot.js', 'plc-web.js', '__wasm_split.js', 'plc-web_bg.wasm'].map((f) => `${folder}/${f}`)];
  const firstSet = new Set(first);
  let firstTotal = 0;
  console.log('  first load:');
  for (const f of first) {
    firstTotal += sizeOf(f);
    console.log(`    ${f.padEnd(44)} ${String(sizeOf(f)).padStart(8)} bytes gzipped`);
  }
  console.log(`  ${'first load'.padEnd(46)} ${String(firstTotal).padStart(8)} bytes gzipped (${kb(firstTotal)})`);

  const problems = [];
  const parts = splits();
  const worker = `${folder}/worker.js`;
  // Files packed into one (scripts/pack.mjs) are fetched as their pack.
  const packs = JSON.parse(readFileSync(join(work, 'packs.json'), 'utf8'));
  const packOf = new Map(Object.entries(packs).flatMap(([pack, held]) => held.map((f) => [f, pack])));
  const partFiles = (name) => {
    const own = [...new Set((parts.get(name) ?? []).map((f) => packOf.get(f) ?? f))].map((f) => `${folder}/${f}`);
    return name.endsWith('_worker') ? [worker, ...own] : own;
  };
  // Fetched right after the first load, whatever the student does.
  const startUp = new Set(START_UP.flatMap((name) => partFiles(name)).filter((f) => !firstSet.has(f)));
  const startUpTotal = [...startUp].reduce((n, f) => n + sizeOf(f), 0);
  console.log(`  ${`fetched at start, after the first load (${START_UP.join(', ')})`.padEnd(46)} ${String(startUpTotal).padStart(8)} bytes gzipped (${kb(startUpTotal)})`);
  for (const name of START_UP) if (!parts.has(name)) problems.push(`no part ${name} to fetch at start`);
  if (startUpTotal > LAZY_LIMIT) problems.push(`the parts fetched at start are ${kb(startUpTotal)}, over ${kb(LAZY_LIMIT)}`);
  const fetched = new Set([...firstSet, ...startUp]);
  console.log('  loaded on first use (each with the chunks it shares with others, beyond those fetched at start):');
  for (const name of [...parts.keys()].sort()) {
    if (START_UP.includes(name)) continue;
    const filesOf = partFiles(name).filter((f) => !fetched.has(f));
    const total = filesOf.reduce((n, f) => n + sizeOf(f), 0);
    const detail = filesOf.map((f) => `${f.slice(folder.length + 1)} ${kb(sizeOf(f))}`).join(' + ');
    console.log(`    ${name.padEnd(20)} ${kb(total).padStart(10)}  (${detail})`);
    if (total > LAZY_LIMIT) problems.push(`the lazily loaded part ${name} is ${kb(total)}, over ${kb(LAZY_LIMIT)}`);
  }
  const exercise = new Set([...partFiles('exercise_ui'), ...partFiles('exercise_worker')]);
  // The exercise's own file (`exercises/ID.json`, the built form): the largest shipped one.
  const exerciseFiles = files.filter((f) => f.startsWith(`${folder}/exercises/`));
  const largest = exerciseFiles.reduce((n, f) => Math.max(n, sizeOf(f)), 0);
  if (exerciseFiles.length === 0) problems.push(`no shipped exercises in ${folder}/exercises/`);
  const exerciseTotal = [...exercise].filter((f) => !fetched.has(f)).reduce((n, f) => n + sizeOf(f), largest);
  console.log(`  ${'opening an exercise adds (largest exercise file)'.padEnd(46)} ${String(exerciseTotal).padStart(8)} bytes gzipped (${kb(exerciseTotal)})`);
  if (exerciseTotal > EXERCISE_LIMIT) problems.push(`opening an exercise adds ${kb(exerciseTotal)}, over ${kb(EXERCISE_LIMIT)}`);
  // The grader (in the worker) and the report's view (in the page) come at the first Check.
  const check = [...partFiles('exercise_grader'), ...partFiles('exercise_report')]
    .filter((f) => !fetched.has(f) && !exercise.has(f));
  const checkTotal = [...new Set(check)].reduce((n, f) => n + sizeOf(f), 0);
  console.log(`  ${'the first Check adds'.padEnd(46)} ${String(checkTotal).padStart(8)} bytes gzipped (${kb(checkTotal)})`);
  const all = files.filter((f) => /\.(wasm|js|css)$/.test(f)).reduce((n, f) => n + sizeOf(f), 0);
  console.log(`  ${'the whole app (wasm, js, css)'.padEnd(46)} ${String(all).padStart(8)} bytes gzipped (${kb(all)})`);

  // A few tiny functions may carry such a name because the linker folded identical code
  // (a closure of a view and one of the page that compile to the same bytes); more than
  // FOLDED bytes of it means the view's code is in the first load.
  const FOLDED = 1024;
  const fns = functionPaths(join(work, 'main-names.wasm'));
  if (fns.filter((f) => f.path.includes('::')).length < 100) problems.push(`${work}/main-names.wasm has no function names to check`);
  const bare = (p) => p.replace(/^[<&]+(mut )?/, '');
  for (const [what, prefix] of FORBIDDEN) {
    const found = fns.filter((f) => bare(f.path).startsWith(prefix));
    const bytes = found.reduce((n, f) => n + f.size, 0);
    if (bytes > FOLDED) {
      const largest = found.sort((a, b) => b.size - a.size)[0];
      problems.push(`the first load holds ${bytes} bytes of ${what} in ${found.length} functions (${largest.path}, ${largest.size} bytes)`);
    }
  }
  if (!problems.length) console.log(`  the first load holds none of: ${FORBIDDEN.map(([w]) => w).join(', ')}`);

  const readme = readFileSync(join(root, 'README.md'), 'utf8');
  const budget = /size budget: \*\*(\d+) KB\*\*/.exec(readme);
  if (!budget) problems.push('README.md states no size budget ("size budget: **N KB**")');
  else if (firstTotal > Number(budget[1]) * 1024) {
    problems.push(`the first load is ${kb(firstTotal)} gzipped, over the ${budget[1]} KB budget in README.md`);
  } else console.log(`  within the ${budget[1]} KB size budget`);
  if (problems.length) {
    for (const p of problems) console.error(`error: ${p}`);
    process.exit(1);
  }
}

if (mode === 'assemble') assemble();
else if (mode === 'finish') finish();
else {
  console.error('usage: node scripts/site.mjs assemble|finish DIST WORK');
  process.exit(2);
}
