// First render on loopback: how long from navigation start until the ST editor is on the
// screen, in headless Chromium against the release build in dist/, each run in a fresh
// browser context (an empty cache, as a first visit). Prints the median and the slowest
// of the runs. Usage: node scripts/first-render.mjs [runs]
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../tests/e2e/server.mjs';
import { launch } from '../tests/e2e/browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const runs = Number(process.argv[2] ?? 10);
const server = await startServer(path.join(root, 'dist'));
const browser = await launch();
const times = [];
for (let i = 0; i < runs; i++) {
  const context = await browser.newContext();
  const page = await context.newPage();
  await page.addInitScript(() => {
    new MutationObserver((_, observer) => {
      if (document.querySelector('textarea[aria-label="ST source"]')) {
        window.__firstRender = performance.now();
        observer.disconnect();
      }
    }).observe(document, { childList: true, subtree: true });
  });
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  times.push(await page.evaluate(() => window.__firstRender));
  await context.close();
}
await browser.close();
await server.close();
times.sort((a, b) => a - b);
const median = times[Math.floor(times.length / 2)];
console.log(`first render (navigation start to the editor on screen), ${runs} runs: median ${median.toFixed(0)} ms, slowest ${times[times.length - 1].toFixed(0)} ms`);
