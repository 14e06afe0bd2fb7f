// Minifies the app's JS (the wasm-bindgen glue plc-web.js, the chunks' link module
// __wasm_split.js, boot.js and worker.js) in the folder given, with terser.
import { readFileSync, writeFileSync, readdirSync } from 'node:fs';
import { join } from 'node:path';
import { minify } from 'terser';

const dir = process.argv[2] ?? 'target/site/app';
const files = readdirSync(dir).filter((f) => f.endsWith('.js'));
if (!files.includes('plc-web.js')) {
  console.error(`minify-js.mjs: no plc-web.js in ${dir}`);
  process.exit(1);
}
for (const name of files) {
  const file = join(dir, name);
  const source = readFileSync(file, 'utf8');
  const out = await minify(source, { module: true, compress: true, mangle: true });
  if (!out.code) {
    console.error(`minify-js.mjs: terser gave no code for ${file}`);
    process.exit(1);
  }
  writeFileSync(file, out.code);
  console.log(`  ${name} minified: ${source.length} → ${out.code.length} bytes`);
}
