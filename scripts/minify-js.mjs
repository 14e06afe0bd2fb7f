// Minifies the app's wasm-bindgen glue (dist/plc-web-*.js) with terser and puts the new
// subresource integrity hash into dist/index.html. Trunk minifies the CSS and the workers'
// glue itself (`minify = "on_release"` in web/Trunk.toml), but its minifier gives up on the
// app's glue and copies it as it is, about 2 KB more on the first load.
import { readFileSync, writeFileSync, readdirSync } from 'node:fs';
import { createHash } from 'node:crypto';
import { join } from 'node:path';
import { minify } from 'terser';

const dist = process.argv[2] ?? 'dist';
const glue = readdirSync(dist).filter((f) => /^plc-web-[0-9a-f]+\.js$/.test(f));
if (glue.length !== 1) {
  console.error(`minify-js.mjs: expected one plc-web-*.js in ${dist}, found ${glue.length}`);
  process.exit(1);
}
const file = join(dist, glue[0]);
const source = readFileSync(file, 'utf8');
const out = await minify(source, { module: true, compress: true, mangle: true });
if (!out.code) {
  console.error(`minify-js.mjs: terser gave no code for ${file}`);
  process.exit(1);
}
writeFileSync(file, out.code);

// The modulepreload link carries the glue's sha384; a stale one would stop the page.
const indexFile = join(dist, 'index.html');
const html = readFileSync(indexFile, 'utf8');
const integrity = `sha384-${createHash('sha384').update(out.code, 'utf8').digest('base64')}`;
// Trunk's minified index.html leaves attribute values unquoted where it can.
const name = glue[0].replace('.', '\\.');
const link = new RegExp(`(<link[^>]*href="?\\./${name}"?[^>]*integrity=)("?)[^" >]*("?)`);
if (!link.test(html)) {
  console.error(`minify-js.mjs: no integrity attribute for ${glue[0]} in ${indexFile}`);
  process.exit(1);
}
writeFileSync(indexFile, html.replace(link, `$1"${integrity}"`));
console.log(`  ${glue[0]} minified: ${source.length} → ${out.code.length} bytes`);
