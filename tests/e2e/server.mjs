// A tiny static server for the built site (dist/), mounted under a sub-path to prove the
// site works from any sub-path. Only listens on the loopback interface.
import http from 'node:http';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { gzipSync } from 'node:zlib';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.wasm': 'application/wasm',
  '.css': 'text/css', '.svg': 'image/svg+xml', '.json': 'application/json', '.png': 'image/png',
};

/** What a static host compresses (gzip -9, as `scripts/site.mjs` counts the sizes). */
const COMPRESSED = new Set(['.html', '.js', '.wasm', '.css', '.svg', '.json']);

/**
 * Serves `root` under `prefix`; `headers` go on every answer (e.g. CORS for another origin).
 * With `gzip`, text and wasm go compressed to a browser that accepts it, as a static host
 * sends them (`scripts/first-render.mjs` times the page so).
 */
export async function startServer(root, prefix = '/trainer/', headers = {}, { gzip = false } = {}) {
  const compressed = new Map(); // file → its gzip, made once (a host keeps it so)
  const server = http.createServer(async (req, res) => {
    const url = new URL(req.url, 'http://localhost');
    if (!url.pathname.startsWith(prefix)) { res.writeHead(404); res.end(); return; }
    let rel = decodeURIComponent(url.pathname.slice(prefix.length)) || 'index.html';
    const file = path.join(root, path.normalize(rel).replace(/^(\.\.[/\\])+/, ''));
    try {
      let body = await readFile(file);
      const type = { 'content-type': TYPES[path.extname(file)] ?? 'application/octet-stream' };
      if (gzip && COMPRESSED.has(path.extname(file)) && /\bgzip\b/.test(req.headers['accept-encoding'] ?? '')) {
        if (!compressed.has(file)) compressed.set(file, gzipSync(body, { level: 9 }));
        body = compressed.get(file);
        type['content-encoding'] = 'gzip';
      }
      res.writeHead(200, { ...headers, ...type });
      res.end(body);
    } catch {
      res.writeHead(404); res.end('not found');
    }
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  return { url: `http://127.0.0.1:${port}${prefix}`, close: () => new Promise((r) => server.close(r)) };
}
