// How long the page takes to show a recorded scan (issue 36: ≤ 100 ms in Chromium on the
// shipped build), in headless Chromium against the release build in dist/: an example runs
// "As fast as possible" for a while, is paused, then the `Recorded scan` slider is set to
// twelve scans spread over the recording; each time is from the slider's input event to the
// page showing that scan (the banner `Showing scan N of M` and the scan read-out).
//
// Usage: node scripts/recorded-jump.mjs ["EXAMPLE TITLE"] [--run-ms N] (default: the new
// project's latch, 5000 ms of running).
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../tests/e2e/server.mjs';
import { launch } from '../tests/e2e/browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const runAt = args.indexOf('--run-ms');
const runMs = runAt >= 0 ? Number(args[runAt + 1]) : 5000;
const example = args.find((a, i) => !a.startsWith('--') && i !== runAt + 1);

const server = await startServer(path.join(root, 'dist'));
const browser = await launch();
try {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  if (example) {
    await page.getByRole('combobox', { name: /example/i }).selectOption({ label: example });
    await page.getByText('Opened the example').waitFor();
    await page.waitForTimeout(1500);
  }
  await page.getByRole('combobox', { name: 'Speed' }).selectOption({ label: 'As fast as possible' });
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await page.waitForTimeout(runMs);
  await page.getByRole('button', { name: 'Pause', exact: true }).click();
  const slider = page.getByRole('slider', { name: 'Recorded scan' });
  const [lo, hi] = await slider.evaluate((e) => [Number(e.min), Number(e.max)]);
  const times = [];
  for (let i = 0; i < 12; i++) {
    const target = Math.floor(lo + (((i * 7919) % 1000) / 1000) * (hi - lo));
    const ms = await page.evaluate(
      (n) =>
        new Promise((resolve) => {
          const input = document.querySelector('input[aria-label="Recorded scan"]');
          const t0 = performance.now();
          const shown = () =>
            [...document.querySelectorAll('[role=status]')].some((e) => e.textContent.includes(`Showing scan ${n} of`)) &&
            new RegExp(`Scan\\s*${n}(?!\\d)`).test(document.querySelector('.sim-pane').textContent);
          const observer = new MutationObserver(() => {
            if (shown()) {
              observer.disconnect();
              resolve(performance.now() - t0);
            }
          });
          observer.observe(document.body, { subtree: true, childList: true, characterData: true });
          input.value = String(n);
          input.dispatchEvent(new Event('input', { bubbles: true }));
        }),
      target,
    );
    times.push(ms);
  }
  times.sort((a, b) => a - b);
  const fmt = (x) => x.toFixed(1);
  console.log(`recorded scans ${lo}–${hi}; jump to a scan: median ${fmt(times[6])} ms, slowest ${fmt(times[11])} ms`);
} finally {
  await browser.close();
  await server.close();
}
