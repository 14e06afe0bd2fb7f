// How fast the trainer is usable, in headless Chromium against the release build in dist/
// (issue 32), each run in a fresh browser context (an empty cache, as a first visit):
//
//   first visit   navigation start → `New project` pressed as soon as it shows and done
//                 (the new project's ST editor on screen; both timed in the page, see
//                 `newProjectUsable`), on loopback and on two throttled profiles (CDP
//                 Network.emulateNetworkConditions and Emulation.setCPUThrottlingRate);
//   second visit  the same after the service worker cached the build, loopback;
//   ladder editor from `Create` in `New ladder POU` to the rung grid on screen, the first
//                 time in the page (its chunk fetched then), on the 9 Mbit/s profile.
//
// The files are served gzipped (-9), as a static host serves them and as the sizes are
// counted; `--raw` serves them uncompressed (the figures before 2026-12-06 were so).
//
// Prints each figure's median and slowest run. Usage: node scripts/first-render.mjs [runs]
// (default 5) [--only NAME] [--raw] where NAME is loopback, 9mbit, 1.6mbit, second or
// ladder.
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../tests/e2e/server.mjs';
import { launch } from '../tests/e2e/browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const runs = Number(args.find((a) => /^\d+$/.test(a)) ?? 5);
const only = args.includes('--only') ? args[args.indexOf('--only') + 1] : null;

const PROFILES = {
  loopback: null,
  '9mbit': { label: '9 Mbit/s, 60 ms RTT, CPU 4× slower', kbit: 9000, rtt: 60, cpu: 4 },
  '1.6mbit': { label: '1.6 Mbit/s, 150 ms RTT, CPU 4× slower', kbit: 1600, rtt: 150, cpu: 4 },
};

async function throttle(context, page, profile) {
  if (!profile) return;
  const cdp = await context.newCDPSession(page);
  await cdp.send('Network.enable');
  const bytes = (profile.kbit * 1000) / 8;
  await cdp.send('Network.emulateNetworkConditions', {
    offline: false, latency: profile.rtt, downloadThroughput: bytes, uploadThroughput: bytes,
  });
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: profile.cpu });
}

/**
 * Navigation start → `New project` pressed and its ST editor on screen, in ms, timed by the
 * page itself: a script in the page presses the button as soon as it is there (a click
 * queued as a task of its own, as a person's press waits for the task running), and marks
 * the first animation frame with the new project's editor on screen. Driving the press
 * from the test instead would add the driver's own round trips and polling (a locator
 * retries 100 and 500 ms apart), which are not the page's time.
 */
async function newProjectUsable(page, url) {
  await page.addInitScript(() => {
    const press = () => {
      const button = [...document.querySelectorAll('button')]
        .find((b) => b.textContent.trim() === 'New project' && !b.disabled);
      if (!button) return false;
      setTimeout(() => button.click(), 0);
      return true;
    };
    new MutationObserver((_, seen) => { if (press()) seen.disconnect(); })
      .observe(document, { childList: true, subtree: true });
    const usable = () => {
      const name = document.querySelector('.project-name')?.textContent ?? '';
      const editor = document.querySelector('textarea[aria-label="ST source"]');
      if (/^Untitled \d+$/.test(name) && editor && editor.offsetParent !== null) {
        window.__usable = performance.now();
      } else requestAnimationFrame(usable);
    };
    requestAnimationFrame(usable);
  });
  await page.goto(url, { waitUntil: 'commit' });
  const at = await page.waitForFunction(() => window.__usable, null, { timeout: 60000 });
  return at.jsonValue();
}

async function firstVisit(browser, url, profile) {
  const context = await browser.newContext();
  const page = await context.newPage();
  await throttle(context, page, profile);
  const ms = await newProjectUsable(page, url);
  await context.close();
  return ms;
}

async function secondVisit(browser, url) {
  const context = await browser.newContext();
  let page = await context.newPage();
  await newProjectUsable(page, url);
  await page.evaluate(async () => {
    const worker = (await navigator.serviceWorker.ready).active;
    if (worker.state !== 'activated') {
      await new Promise((done) => worker.addEventListener('statechange', () => {
        if (worker.state === 'activated') done();
      }));
    }
  });
  await page.close();
  page = await context.newPage();
  const ms = await newProjectUsable(page, url);
  const controlled = await page.evaluate(() => navigator.serviceWorker.controller !== null);
  await context.close();
  if (!controlled) throw new Error('the second visit was not served by the service worker');
  return ms;
}

async function ladderOpen(browser, url, profile) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  await throttle(context, page, profile);
  await newProjectUsable(page, url);
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Rungs');
  const create = page.getByRole('button', { name: 'Create' });
  await create.evaluate((b) => b.addEventListener('click', () => { window.__created = performance.now(); }, { once: true }));
  await create.click();
  // The first frame with a cell of the grid (watched on every frame, as above).
  const ms = await page.waitForFunction(() => {
    const grid = document.querySelector('[aria-label="Ladder diagram Rungs"] [role="gridcell"]');
    return grid && window.__created !== undefined ? performance.now() - window.__created : null;
  }, null, { timeout: 60000, polling: 'raf' }).then((h) => h.jsonValue());
  await context.close();
  return ms;
}

// Compressed as a static host sends it (gzip -9); `--raw` serves the files as they are.
const server = await startServer(path.join(root, 'dist'), '/trainer/', {}, { gzip: !args.includes('--raw') });
const browser = await launch();
const figures = [];
const measure = async (name, label, once) => {
  if (only && only !== name) return;
  const times = [];
  for (let i = 0; i < runs; i++) times.push(await once());
  times.sort((a, b) => a - b);
  const median = times[Math.floor(times.length / 2)];
  figures.push({ name, label, median, slowest: times[times.length - 1], runs: times.map(Math.round) });
  console.log(`${label}: median ${median.toFixed(0)} ms, slowest ${times[times.length - 1].toFixed(0)} ms (${runs} runs)`);
};
try {
  for (const [name, profile] of Object.entries(PROFILES)) {
    await measure(name, `first visit, New project usable, ${profile?.label ?? 'loopback'}`,
      () => firstVisit(browser, server.url, profile));
  }
  await measure('second', 'second visit (service worker cache), New project usable, loopback',
    () => secondVisit(browser, server.url));
  await measure('ladder', `first open of the ladder editor to its grid, ${PROFILES['9mbit'].label}`,
    () => ladderOpen(browser, server.url, PROFILES['9mbit']));
} finally {
  await browser.close();
  await server.close();
}
console.log(JSON.stringify(figures));
