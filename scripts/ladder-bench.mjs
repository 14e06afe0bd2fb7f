// Ladder editor latency: a POU of 100 rungs in headless Chromium (release build in dist/);
// the time from a key press that puts an element into a cell to the next painted frame,
// over N presses (`w` for a wire, then Delete, alternately). Goal ≤ 50 ms (issue 13).
// Usage: node scripts/ladder-bench.mjs [presses]
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer } from '../tests/e2e/server.mjs';
import { launch } from '../tests/e2e/browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const presses = Number(process.argv[2] ?? 20);
const rung = () => ({
  comment: '',
  label: null,
  cells: Array.from({ length: 8 }, (_, r) => Array.from({ length: 10 }, (_, c) => ({
    element: r === 0 && c === 0 ? { type: 'Contact', kind: 'NormallyOpen', operand: 'a' }
      : r === 0 && c === 1 ? { type: 'Coil', kind: 'Normal', operand: 'q' } : { type: 'Empty' },
    link_down: false,
  }))),
});
const project = {
  schema: 1,
  name: 'Hundred rungs',
  source: '',
  ladder: [{ name: 'Big', kind: 'Program', declarations: 'VAR a, q : BOOL; END_VAR\n', rungs: Array.from({ length: 100 }, rung) }],
};
const server = await startServer(path.join(root, 'dist'));
const browser = await launch();
const page = await (await browser.newContext({ viewport: { width: 1280, height: 900 } })).newPage();
await page.goto(server.url);
await page.getByRole('textbox', { name: 'ST source' }).waitFor();
await page.getByLabel('Import project file').setInputFiles({ name: 'big.plcproj.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(project)) });
const view = page.getByRole('region', { name: 'Ladder diagram Big' });
await page.getByRole('button', { name: 'Ladder diagram Big' }).click();
await view.getByRole('gridcell', { name: 'Rung 50, row 1, column 5: empty' }).focus();
await page.evaluate(() => {
  window.__lat = [];
  document.addEventListener('keydown', () => {
    const t0 = performance.now();
    const grid = document.querySelector('.ld-rungs');
    const observer = new MutationObserver(() => {
      observer.disconnect();
      requestAnimationFrame(() => window.__lat.push(performance.now() - t0));
    });
    observer.observe(grid, { subtree: true, childList: true, attributes: true });
  }, true);
});
for (let i = 0; i < presses; i++) {
  await page.keyboard.press(i % 2 === 0 ? 'w' : 'Delete');
  await page.waitForTimeout(400);
}
const lat = (await page.evaluate(() => window.__lat)).sort((a, b) => a - b);
await browser.close();
await server.close();
console.log(`ladder editor, 100 rungs: key press to the next frame over ${lat.length} presses: median ${lat[Math.floor(lat.length / 2)].toFixed(0)} ms, slowest ${lat[lat.length - 1].toFixed(0)} ms (goal ≤ 50 ms)`);
