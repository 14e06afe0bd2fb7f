// Starts the app: loads its module (the page's own wasm; the views that are not on the first
// screen come as chunks of it, see docs/loading.md), says where the app's files are (the
// workers start from the same folder), and registers the service worker that keeps the site
// for offline use and offers a new version when one is deployed.
import init, * as bindings from './plc-web.js';

// A trap in the app's wasm stops the page: in the release build a panic is one (it traps at
// once, with no panic hook: scripts/wasm-build.sh). Marked here, so that leaving the page
// then does not count as a clean exit (web/src/state/projects.rs, `stopped`).
const trapped = (error) => {
  if (error instanceof WebAssembly.RuntimeError) globalThis.plcStopped = true;
};
addEventListener('error', (event) => trapped(event.error));
addEventListener('unhandledrejection', (event) => trapped(event.reason));

// The folder of this build's files (`app-<build id>/`), for the workers and the chunks.
globalThis.plcAppBase = new URL('./', import.meta.url).href;
const wasm = await init();
window.wasmBindings = bindings;
dispatchEvent(new CustomEvent('TrunkApplicationStarted', { detail: { wasm } }));

/** Shows the `New version available` banner; `Reload` lets the waiting build take over. */
function offer(worker) {
  if (document.querySelector('.update-banner')) return;
  const banner = document.createElement('div');
  banner.className = 'banner banner-info update-banner';
  banner.setAttribute('role', 'status');
  const text = document.createElement('span');
  text.textContent = 'New version available';
  const reload = document.createElement('button');
  reload.className = 'link';
  reload.textContent = 'Reload';
  reload.addEventListener('click', () => worker.postMessage('skip-waiting'));
  banner.append(text, reload);
  document.body.prepend(banner);
}

if ('serviceWorker' in navigator) {
  const container = navigator.serviceWorker;
  let reloading = false;
  // The new build took over (after `Reload`): load the page from it, all of it.
  container.addEventListener('controllerchange', () => {
    if (!reloading) { reloading = true; location.reload(); }
  });
  const register = async () => {
    let registration;
    try {
      registration = await container.register('./sw.js');
    } catch {
      // Service workers refused (a browser setting, a private window): the page works
      // online as it does without them.
      return;
    }
    if (!registration) return;
    // A first visit has no controller: the build being cached is the one on screen.
    const waiting = (worker) => { if (worker && container.controller) offer(worker); };
    waiting(registration.waiting);
    registration.addEventListener('updatefound', () => {
      const worker = registration.installing;
      worker?.addEventListener('statechange', () => {
        if (worker.state === 'installed') waiting(worker);
      });
    });
  };
  // After the first screen, so caching the rest of the site never delays it.
  if (document.readyState === 'complete') register();
  else addEventListener('load', () => register(), { once: true });
}
