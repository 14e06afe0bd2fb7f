// The page stays responsive and within its memory budget whatever the program does
// (issue 11). These tests check behaviour (the page is not frozen, memory stops growing),
// with bounds far from the measured figures; the figures are in docs/reliability.md.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let server;
let browser;

before(async () => {
  server = await startServer(path.join(root, 'dist'));
  browser = await launch();
});
after(async () => {
  await browser?.close();
  await server?.close();
});

async function openApp(context) {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  // The wasm instance, for its memory size.
  await page.addInitScript(() => {
    addEventListener('TrunkApplicationStarted', (e) => { window.__wasm = e.detail.wasm; });
  });
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { page, errors };
}

async function typeProgram(page, text) {
  await page.getByRole('textbox', { name: 'ST source' }).fill(text);
  await page.waitForTimeout(700);
}

/** Starts sampling the gaps between timer callbacks (how long the page cannot react). */
const startGapProbe = (page) => page.evaluate(() => {
  window.__gaps = [];
  let last = performance.now();
  window.__probe = setInterval(() => {
    const now = performance.now();
    window.__gaps.push(now - last);
    last = now;
  }, 5);
});

const stopGapProbe = (page) => page.evaluate(() => {
  clearInterval(window.__probe);
  const g = window.__gaps.slice(1).sort((a, b) => a - b);
  return { max: g[g.length - 1], p99: g[Math.floor(g.length * 0.99)], count: g.length };
});

const HEAVY = `PROGRAM Heavy
VAR_OUTPUT Count : DINT; Sum : DINT; END_VAR
VAR i : DINT; END_VAR
(* about a million loop iterations in every scan, within the watchdog *)
FOR i := 1 TO 1000000 DO
    Sum := Sum + 1;
END_FOR;
Count := Count + 1;
END_PROGRAM
`;

test('a program with a million loop iterations per scan at Max speed does not freeze the page', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  await typeProgram(page, HEAVY);
  await page.getByRole('combobox', { name: 'Speed' }).selectOption('max');
  await page.getByRole('checkbox', { name: 'Chart Count' }).check();
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await startGapProbe(page);
  await page.waitForTimeout(3000);
  const gaps = await stopGapProbe(page);
  // A click is handled at once: Pause takes effect and the scan count stops.
  const clicked = Date.now();
  await page.getByRole('button', { name: 'Pause', exact: true }).click();
  await page.getByRole('status', { name: 'PLC state: Paused' }).waitFor({ timeout: 2000 });
  const pauseMs = Date.now() - clicked;
  const scans = Number(await page.getByLabel('Scan count').innerText());
  console.log(`heavy scans: ${scans} scans in 3 s; longest gap ${gaps.max.toFixed(0)} ms, p99 ${gaps.p99.toFixed(0)} ms over ${gaps.count} samples; pause took ${pauseMs} ms`);
  assert.ok(scans > 0, 'it ran');
  assert.ok(gaps.count > 30, `the page's timers ran (${gaps.count} samples in 3 s)`);
  assert.ok(gaps.max < 1000, `longest freeze ${gaps.max} ms (a batch of 256 such scans froze it for seconds)`);
  assert.deepEqual(errors, []);
  await context.close();
});

const LATCH_TIMER = `PROGRAM Main
VAR_INPUT Start : BOOL; END_VAR
VAR_OUTPUT Lamp : BOOL; Count : DINT; END_VAR
VAR Blink : TON; END_VAR
Blink(IN := NOT Blink.Q, PT := T#500ms);
IF Blink.Q THEN Lamp := NOT Lamp; Count := Count + 1; END_IF;
END_PROGRAM
`;

const wasmBytes = (page) => page.evaluate(() => window.__wasm.memory.buffer.byteLength);

test('one simulated hour with the timeline recording stays within the memory budget', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  await typeProgram(page, LATCH_TIMER);
  for (const v of ['Lamp', 'Count']) await page.getByRole('checkbox', { name: `Chart ${v}` }).check();
  await page.getByRole('combobox', { name: 'Speed' }).selectOption('max');
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  const virtualSeconds = async () => {
    const t = await page.getByLabel('Virtual time').innerText();
    const m = /T#(?:(\d+)h)?(?:(\d+)m(?!s))?(?:(\d+)s)?/.exec(t);
    return m ? (Number(m[1] ?? 0) * 3600 + Number(m[2] ?? 0) * 60 + Number(m[3] ?? 0)) : 0;
  };
  let half = null;
  const started = Date.now();
  for (;;) {
    await page.waitForTimeout(500);
    const s = await virtualSeconds();
    if (half === null && s >= 1800) half = await wasmBytes(page);
    if (s >= 3600) break;
    assert.ok(Date.now() - started < 300_000, `only ${s} virtual seconds after 5 minutes`);
  }
  await page.getByRole('button', { name: 'Pause', exact: true }).click();
  const end = await wasmBytes(page);
  const heap = await page.evaluate(() => performance.memory?.usedJSHeapSize ?? 0);
  console.log(`one simulated hour in ${((Date.now() - started) / 1000).toFixed(0)} s: wasm memory ${(half / 2 ** 20).toFixed(1)} MiB at 30 min, ${(end / 2 ** 20).toFixed(1)} MiB at 60 min; JS heap ${(heap / 2 ** 20).toFixed(1)} MiB`);
  assert.ok(end <= 96 * 2 ** 20, `wasm memory ${end} bytes is within the 96 MiB budget`);
  assert.ok(end - half <= 2 * 2 ** 20, `memory flat over the second half hour (${half} → ${end})`);
  assert.deepEqual(errors, []);
  await context.close();
});
