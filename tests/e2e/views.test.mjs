// Ladder and Petri net POUs in the browser: shown, run live, and located problems.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { mkdirSync, readFileSync } from 'node:fs';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const shots = path.join(root, 'docs/screenshots');
let server;
let browser;

before(async () => {
  server = await startServer(path.join(root, 'dist'));
  browser = await launch();
  mkdirSync(shots, { recursive: true });
});
after(async () => {
  await browser?.close();
  await server?.close();
});

async function openApp() {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  return { context, page, errors };
}

async function openExample(page, title) {
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: title });
  await page.getByRole('alert').filter({ hasText: `Opened the example “${title}”` }).waitFor();
}

test('the ladder latch runs live: clicking Start powers the Motor coil, which holds itself', async () => {
  const { context, page, errors } = await openApp();
  await openExample(page, 'Ladder latch');
  const view = page.getByRole('region', { name: 'Ladder diagram Latch' });
  await view.waitFor();
  const coil = view.locator('[data-cell="0-0-2"]');
  await page.getByRole('img', { name: 'Coil Motor: OFF' }).waitFor();
  assert.equal(await coil.locator('.ld-wire.powered').count(), 0, 'nothing is powered before Start');

  await page.getByRole('button', { name: 'Run', exact: true }).click();
  const start = view.getByRole('button', { name: 'Contact Start' });
  await start.click();
  await page.getByRole('img', { name: 'Coil Motor: ON' }).waitFor({ timeout: 5000 });
  assert.equal(await start.getAttribute('aria-pressed'), 'true');
  await view.locator('[data-cell="0-0-2"].powered').waitFor();
  // Both wires of the coil (in and out) and the wire to the right rail carry power.
  assert.equal(await coil.locator('.ld-wire.powered').count(), 2);
  assert.ok(await view.locator('svg[aria-label="Rung 1"] .ld-wire.powered').count() >= 5);
  assert.equal(await page.getByRole('img', { name: 'Motor: ON', exact: true }).count(), 1, 'the I/O panel agrees');

  // Release Start: the self-holding contact keeps the coil powered.
  await start.click();
  await page.waitForFunction(() => document.querySelector('[aria-label="Contact Start"]')?.getAttribute('aria-pressed') === 'false');
  await page.waitForTimeout(300);
  await page.getByRole('img', { name: 'Coil Motor: ON' }).waitFor();
  assert.equal(await view.locator('[data-cell="0-0-0"].powered').count(), 0, 'the Start contact is open');
  assert.equal(await view.locator('[data-cell="0-1-0"].powered').count(), 1, 'the Motor contact holds');
  // The timer block shows its elapsed time.
  await view.getByRole('img', { name: 'Block LampDelay: TON' }).locator('text', { hasText: 'ET = T#' }).first().waitFor();
  await page.waitForTimeout(500);
  await page.screenshot({ path: path.join(shots, 'ladder-latch.png'), fullPage: true });

  // The ST view of the same POU.
  await view.getByRole('button', { name: 'ST view' }).click();
  await view.getByLabel('Latch as Structured Text').filter({ hasText: 'Motor' }).waitFor();
  await view.getByRole('region', { name: 'IL view' }).filter({ hasText: 'ANDN Stop' }).first().waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('the sequential weighing net: Start moves the token from P1 to P31 and lights the P31 branch', async () => {
  const { context, page, errors } = await openApp();
  await openExample(page, 'Weighing (sequential Petri net)');
  const view = page.getByRole('region', { name: 'Petri net Weighing' });
  await view.waitFor();
  const place = (id) => view.locator(`.pn-place[data-id="${id}"]`);
  await place('P1').and(page.locator('.marked')).waitFor();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  await step.click();
  assert.equal(await place('P1').getAttribute('aria-label'), 'Place P1: 1 token');
  assert.match(await view.locator('.code-active').first().getAttribute('data-text'), /^1: \(\* P1/);

  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await step.click();
  await place('P31').and(page.locator('.marked')).waitFor();
  assert.equal(await place('P1').getAttribute('aria-label'), 'Place P1: 0 tokens');
  // T2 = T(P1,P30) fired on that scan; the macro-place P30 is marked through P31.
  await view.locator('.pn-transition[data-id="T2"].fired').waitFor();
  assert.equal(await view.locator('.pn-transition.fired').count(), 1);
  assert.equal(await view.locator('.pn-macro[data-id="P30"].marked').count(), 1);

  // The place marked during a scan runs its branch from the next scan on.
  await step.click();
  await page.waitForFunction(() => /^31:/.test(document.querySelector('.code-active')?.dataset.text ?? ''));
  assert.equal(await view.locator('.pn-transition.fired').count(), 0, 'nothing fired on this scan');
  assert.equal(await view.locator('.pn-transition[data-id="T5"].enabled').count(), 1, 'P31 enables T5');
  assert.equal(await page.getByRole('img', { name: 'FeedValve: ON', exact: true }).count(), 1);

  await view.locator('.pn-analysis summary').click();
  await view.locator('.pn-verdicts').filter({ hasText: 'Safe' }).waitFor();
  await page.screenshot({ path: path.join(shots, 'petri-weighing.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});

test('a Petri net shows its generated code beside it from 1100 px wide, below it on a tablet', async () => {
  const { context, page, errors } = await openApp();
  await openExample(page, 'Weighing (sequential Petri net)');
  const view = page.getByRole('region', { name: 'Petri net Weighing' });
  await view.waitFor();
  const boxes = async () => ({
    net: await view.locator('.pn-net').boundingBox(),
    code: await view.locator('.pn-code').boundingBox(),
  });
  for (const width of [1100, 1180, 1259, 1260, 1280, 1440, 1920]) {
    await page.setViewportSize({ width, height: 900 });
    await page.waitForTimeout(100);
    const { net, code } = await boxes();
    assert.ok(Math.abs(code.y - net.y) < 2 && code.x >= net.x + net.width, `at ${width} px the code is beside the net: ${JSON.stringify({ net, code })}`);
    assert.ok(code.width >= 280, `at ${width} px the code has room: ${code.width}`);
    // The simulation stays on the page: beside the program, or below it.
    assert.ok(await page.getByRole('button', { name: 'Run', exact: true }).isVisible());
    assert.equal(await page.evaluate(() => document.documentElement.scrollWidth <= window.innerWidth), true, `no sideways scroll at ${width} px`);
  }
  // A tablet in portrait: the code below the net, both the full width.
  await page.setViewportSize({ width: 768, height: 1024 });
  await page.waitForTimeout(100);
  const { net, code } = await boxes();
  assert.ok(code.y >= net.y + net.height, `at 768 px the code is below the net: ${JSON.stringify({ net, code })}`);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a ladder problem is listed at its rung, row and column, and clicking it shows the cell', async () => {
  const { context, page, errors } = await openApp();
  const project = JSON.parse(readFileSync(path.join(root, 'examples/latch-ladder.plcproj.json'), 'utf8'));
  project.name = 'Broken latch';
  project.ladder[0].rungs[0].cells[0][2].element.operand = '';
  await page.getByLabel('Import project file').setInputFiles({
    name: 'broken.plcproj.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(project)),
  });
  const problem = page.getByRole('list', { name: 'Problems' }).getByRole('button').filter({ hasText: 'E0403' });
  await problem.waitFor();
  assert.match(await problem.textContent(), /^Latch, rung 1, row 1, column 3 {2}E0403 {2}/);
  // The code links to its explanation, a static page of the site.
  const help = page.getByRole('link', { name: 'Explain E0403' });
  assert.equal(await help.getAttribute('href'), 'problems.html#E0403');
  const explained = await context.newPage();
  await explained.goto(new URL('problems.html#E0403', page.url()).href);
  const section = explained.locator('section#E0403');
  assert.match(await section.textContent(), /contact, coil or block pin without an operand[\s\S]*Wrong:[\s\S]*Right:/);
  await explained.close();
  await page.getByRole('button', { name: 'Structured Text source' }).click();
  await problem.click();
  const view = page.getByRole('region', { name: 'Ladder diagram Latch' });
  await view.locator('.ld-focus').waitFor();
  assert.equal(await view.locator('.ld-diag.err').count(), 1);
  // The problem's cell is selected and holds the focus: keys act on it at once.
  await view.getByRole('gridcell', { name: /^Rung 1, row 1, column 3: / }).and(page.locator('[aria-selected="true"]')).waitFor();
  await page.waitForFunction(() => /^Rung 1, row 1, column 3: /.test(document.activeElement?.getAttribute('aria-label') ?? ''));
  assert.equal(await page.getByRole('button', { name: 'Ladder diagram Latch' }).getAttribute('aria-pressed'), 'true');
  await page.screenshot({ path: path.join(shots, 'ladder-problem.png'), fullPage: true });
  // Nothing of the previous project runs: its inputs and outputs are gone.
  assert.equal(await page.getByRole('img', { name: 'Motor: OFF', exact: true }).count(), 0);
  await page.getByRole('status', { name: 'PLC state: No program' }).waitFor();
  // The broken project is open and kept, as imported.
  assert.equal(await page.locator('.project-name').textContent(), 'Broken latch');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a project with several PROGRAMs runs the one chosen, and PLCopen XML imports', async () => {
  const { context, page, errors } = await openApp();
  await page.getByLabel('Import project file').setInputFiles(path.join(root, 'examples/ladder-five-rungs.xml'));
  await page.getByRole('alert').filter({ hasText: 'PLCopen XML' }).waitFor();
  const chooser = page.getByRole('combobox', { name: 'Program to run' });
  await chooser.waitFor();
  assert.equal(await chooser.locator('option').count(), 5);
  await chooser.selectOption('PartCounter');
  await page.getByRole('button', { name: 'Ladder diagram PartCounter' }).click();
  const view = page.getByRole('region', { name: 'Ladder diagram PartCounter' });
  await view.waitFor();
  assert.equal(await view.locator('.view-note').count(), 0, 'the chosen PROGRAM is live');
  await page.getByRole('button', { name: 'Ladder diagram Latch' }).click();
  await page.getByRole('region', { name: 'Ladder diagram Latch' }).locator('.view-note', { hasText: 'runs PROGRAM PartCounter' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});
