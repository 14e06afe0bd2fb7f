// Puts a strict Content-Security-Policy into the built dist/index.html (issue 11: hostile
// content stays inert). Trunk starts the app with an inline module script; the policy
// allows exactly that script by its SHA-256 and nothing else inline.
import { readFileSync, writeFileSync } from 'node:fs';
import { createHash } from 'node:crypto';

const file = process.argv[2] ?? 'dist/index.html';
let html = readFileSync(file, 'utf8');
const scripts = [...html.matchAll(/<script\b[^>]*>([\s\S]*?)<\/script>/g)].map((m) => m[1]);
if (scripts.length !== 1) {
  console.error(`csp.mjs: expected one inline script in ${file}, found ${scripts.length}`);
  process.exit(1);
}
const hash = createHash('sha256').update(scripts[0], 'utf8').digest('base64');
const policy = [
  "default-src 'none'",
  `script-src 'self' 'wasm-unsafe-eval' 'sha256-${hash}'`,
  "style-src 'self' 'unsafe-inline'",
  // Exercise statements may show images from the exercise's own host, and `?exercise=URL`
  // fetches an exercise file (data, never run) from any host that allows it (CORS).
  "img-src 'self' data: blob: https:",
  "connect-src 'self' https: http:",
  "manifest-src 'self'",
  "base-uri 'none'",
  "form-action 'none'",
  "object-src 'none'",
].join('; ');
const meta = `<meta http-equiv="Content-Security-Policy" content="${policy}">`;
html = html.replace(/<meta http-equiv="Content-Security-Policy"[^>]*>\n?/g, '');
// Trunk's minified index.html writes `<meta charset=utf-8>`.
const charset = /<meta charset="?utf-8"?>/i;
if (!charset.test(html)) {
  console.error(`csp.mjs: no <meta charset="utf-8"> in ${file} to put the policy after`);
  process.exit(1);
}
html = html.replace(charset, (m) => `${m}\n  ${meta}`);
writeFileSync(file, html);
console.log(`  Content-Security-Policy set (inline start-up script sha256-${hash})`);
