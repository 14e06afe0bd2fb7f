// The service worker: keeps one build of the site in a cache named after that build, so
// after one visit the trainer opens and works with the network off. scripts/build-web.sh
// writes the build id and the list of the build's files into dist/sw.js.
//
// Every file of the build is fetched into the cache when the worker installs, and while
// this worker is active the site's files come from that cache only: the page, its chunks
// and its workers are always of one build. A new deploy changes this file (its build id),
// so the browser installs the new worker beside the old one; it waits until the page's
// `Reload` (banner `New version available`, web/boot.js) tells it to take over, and then
// drops the old build's cache.
const BUILD = '%BUILD_ID%';
const FILES = %FILES%;
const CACHE = `plc-trainer-${BUILD}`;
const KNOWN = new Set(FILES);

self.addEventListener('install', (event) => {
  event.waitUntil(
    caches.open(CACHE).then((cache) =>
      // `reload`: from the server, never from the HTTP cache (which may hold another build).
      cache.addAll(FILES.map((file) => new Request(file, { cache: 'reload' })))),
  );
});

self.addEventListener('activate', (event) => {
  event.waitUntil(
    caches.keys().then((keys) => Promise.all(
      keys.filter((k) => k.startsWith('plc-trainer-') && k !== CACHE).map((k) => caches.delete(k)),
    )),
  );
});

self.addEventListener('message', (event) => {
  if (event.data === 'skip-waiting') self.skipWaiting();
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET') return;
  const url = new URL(request.url);
  const scope = new URL(self.registration.scope);
  if (url.origin !== scope.origin || !url.pathname.startsWith(scope.pathname)) return;
  // The page itself whatever its query (`?exercise=…`); other files by their path.
  let file = url.pathname.slice(scope.pathname.length);
  if (request.mode === 'navigate' && (file === '' || file === 'index.html')) file = 'index.html';
  if (!KNOWN.has(file)) return;
  event.respondWith(
    caches.open(CACHE)
      .then((cache) => cache.match(file))
      .then((hit) => hit ?? fetch(request)),
  );
});
