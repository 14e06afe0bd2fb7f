// The built site (dist/) served under a sub-path on the loopback interface, as
// tests/e2e/server.mjs does, and a switch that takes the server off the network: while
// offline every connection is dropped unanswered, which every engine sees as a network
// failure (the same for all, unlike each automation protocol's own offline emulation).
import http from 'node:http';
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.css': 'text/css', '.svg': 'image/svg+xml', '.json': 'application/json',
  '.webmanifest': 'application/manifest+json', '.png': 'image/png', '.toml': 'text/plain; charset=utf-8',
};

/**
 * Serves `root` under `prefix`; `headers` go on every answer (e.g. CORS). With `delayMs`,
 * every answer waits that long first, as over a network with that much latency.
 */
export async function startServer(root, prefix = '/trainer/', headers = {}, { delayMs = 0 } = {}) {
  let offline = false;
  const sockets = new Set();
  const server = http.createServer(async (req, res) => {
    if (delayMs > 0) await new Promise((r) => setTimeout(r, delayMs));
    if (offline) { req.socket.destroy(); return; }
    const url = new URL(req.url, 'http://localhost');
    if (!url.pathname.startsWith(prefix)) { res.writeHead(404); res.end(); return; }
    const rel = decodeURIComponent(url.pathname.slice(prefix.length)) || 'index.html';
    const file = path.join(root, path.normalize(rel).replace(/^(\.\.[/\\])+/, ''));
    try {
      const body = await readFile(file);
      res.writeHead(200, { ...headers, 'content-type': TYPES[path.extname(file)] ?? 'application/octet-stream' });
      res.end(body);
    } catch {
      res.writeHead(404); res.end('not found');
    }
  });
  server.on('connection', (socket) => {
    if (offline) { socket.destroy(); return; }
    sockets.add(socket);
    socket.on('close', () => sockets.delete(socket));
  });
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  return {
    url: `http://127.0.0.1:${port}${prefix}`,
    /** Off the network (true) or back on it (false). */
    setOffline(on) {
      offline = on;
      if (on) for (const s of sockets) s.destroy();
    },
    close: () => new Promise((r) => {
      for (const s of sockets) s.destroy();
      server.close(r);
    }),
  };
}
