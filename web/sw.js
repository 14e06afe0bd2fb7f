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

/**
 * How many files the install fetches at a time. The browser gives a site a few connections;
 * fetching every file at once queued whatever the page and its workers asked for meanwhile
 * (the exercise the student opened, a chunk) behind the whole site.
 */
const AT_ONCE = 2;

/** The page's own address (the scope: the folder of this file), without a query. */
const PAGE = new URL('./', self.location.href);

self.addEventListener('install', (event) => {
  event.waitUntil(Promise.all([route(event), precache()]));
});

/**
 * Where the browser has the static routing API (Chromium), it answers from the cache itself,
 * without starting this worker's script or running its fetch handler, both for the page at
 * its plain address and for every file the page, its chunks and its workers ask for (a miss
 * goes to the network, as in the handler below). A second visit then waits for neither the
 * worker's start nor a round trip through it (docs/loading.md, "The service worker").
 * Elsewhere, and for the page with a query (`?exercise=…`), the fetch handler answers.
 */
async function route(event) {
  try {
    await event.addRoutes?.([
      { condition: { requestMode: 'navigate', urlPattern: { pathname: PAGE.pathname, search: '' } }, source: { cacheName: CACHE } },
      { condition: { requestMode: 'navigate' }, source: 'fetch-event' },
      { condition: { requestMethod: 'GET' }, source: { cacheName: CACHE } },
    ]);
  } catch {
    // A browser whose router takes other rules: the fetch handler answers everything.
  }
}

/** Fetches every file of the build into its cache, `AT_ONCE` at a time; fails if one fails. */
async function precache() {
  const cache = await caches.open(CACHE);
  const queue = [...FILES];
  let failed = null;
  const fetchSome = async () => {
    while (failed === null && queue.length > 0) {
      const file = queue.shift();
      try {
        // `reload`: from the server, never from the HTTP cache (which may hold another build).
        const response = await fetch(new Request(file, { cache: 'reload' }));
        if (!response.ok) throw new Error(`${file}: HTTP ${response.status}`);
        // The page also under its plain address, which the router looks up as it is.
        if (file === 'index.html') await cache.put(PAGE, response.clone());
        await cache.put(file, response);
      } catch (e) {
        failed ??= e;
      }
    }
  };
  await Promise.all(Array.from({ length: AT_ONCE }, fetchSome));
  if (failed !== null) {
    // Not installed: the next visit starts again from an empty cache.
    await caches.delete(CACHE);
    throw failed;
  }
}

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
