// The Petri net editor (issue 14): a student draws a net in a new project with the canvas
// tools, sets its marking and guards in the properties panel, sees the generated CASE OF
// code, runs it scan by scan, moves a place and undoes the move.
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

/** Client pixels of net point (x, y) on the canvas (through its viewBox and size). */
async function at(canvas, x, y) {
  const box = await canvas.boundingBox();
  const [vx, vy, vw, vh] = (await canvas.getAttribute('viewBox')).split(' ').map(Number);
  return { x: box.x + ((x - vx) * box.width) / vw, y: box.y + ((y - vy) * box.height) / vh };
}

async function centre(locator) {
  const b = await locator.boundingBox();
  return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
}

test('a three-place cycle drawn in a new project generates CASE code, runs scan by scan, and a move undoes', async () => {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.getByRole('button', { name: 'New Petri net POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Cycle');
  await page.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: 'Petri net Cycle' });
  await view.waitFor();
  const decls = view.getByRole('textbox', { name: 'Declarations' });
  await decls.fill('VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Busy : BOOL;\nEND_VAR\n');
  await decls.press('Tab');
  const canvas = view.getByRole('group', { name: 'Net canvas' });

  // Places and transitions where clicked (snapped to the grid), named in creation order.
  const tool = (name) => view.getByRole('button', { name, exact: true });
  await tool('Place').click();
  assert.equal(await tool('Place').getAttribute('aria-pressed'), 'true');
  for (const [x, y] of [[100, 100], [300, 100], [300, 260]]) {
    const p = await at(canvas, x, y);
    await page.mouse.click(p.x, p.y);
  }
  await tool('Transition').click();
  for (const [x, y] of [[200, 100], [300, 180], [200, 260]]) {
    const p = await at(canvas, x, y);
    await page.mouse.click(p.x, p.y);
  }
  const place = (id) => view.locator(`.pn-place[data-id="${id}"]`);
  const transition = (id) => view.locator(`.pn-transition[data-id="${id}"]`);
  for (const id of ['P1', 'P2', 'P3']) await place(id).waitFor();
  for (const id of ['T1', 'T2', 'T3']) await transition(id).waitFor();
  assert.equal(await place('P1').getAttribute('aria-label'), 'Place P1: 0 tokens');

  // Arcs: press on one element and release on the other, or click one and then the other.
  await tool('Arc').click();
  const join = async (a, b, clicks) => {
    const from = await centre(a);
    const to = await centre(b);
    if (clicks) {
      await page.mouse.click(from.x, from.y);
      await page.mouse.click(to.x, to.y);
    } else {
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      await page.mouse.move(to.x, to.y, { steps: 6 });
      await page.mouse.up();
    }
  };
  await join(place('P1'), transition('T1'), false);
  await join(transition('T1'), place('P2'), true);
  await join(place('P2'), transition('T2'), false);
  await join(transition('T2'), place('P3'), true);
  await join(place('P3'), transition('T3'), false);
  await join(transition('T3'), place('P1'), false);
  assert.equal(await view.locator('.pn-arc').count(), 6);
  await page.keyboard.press('Escape');
  assert.equal(await tool('Select').getAttribute('aria-pressed'), 'true', 'Escape returns to Select');

  // Properties: one token in P1, the guard Go on T1, an action in P2.
  await place('P1').click();
  const props = view.getByRole('group', { name: 'Properties' });
  await props.getByRole('spinbutton', { name: 'Initial tokens' }).fill('1');
  await props.getByRole('spinbutton', { name: 'Initial tokens' }).press('Tab');
  await place('P1').and(page.locator('[data-tokens="1"]')).waitFor();
  await transition('T1').click();
  await props.getByRole('textbox', { name: 'Guard' }).fill('Go');
  await props.getByRole('textbox', { name: 'Guard' }).press('Tab');
  await place('P2').click();
  await props.getByRole('textbox', { name: 'Actions' }).fill('Busy := TRUE;');
  await props.getByRole('textbox', { name: 'Actions' }).press('Tab');

  // The generated CASE OF code, and the net runs scan by scan.
  const code = view.locator('.pn-code');
  await code.filter({ hasText: 'CASE' }).waitFor();
  await code.filter({ hasText: 'Busy := TRUE;' }).waitFor();
  await page.getByText('No problems found.').waitFor();
  await page.getByRole('combobox', { name: 'Program to run' }).selectOption('Cycle');
  const scans = page.getByLabel('Scan count');
  const step = async () => {
    const before = Number(await scans.textContent());
    await page.getByRole('button', { name: 'Step', exact: true }).click();
    await page.waitForFunction((n) => Number(document.querySelector('[aria-label="Scan count"]').textContent) === n + 1, before);
  };
  const tokens = async () => Promise.all(['P1', 'P2', 'P3'].map((id) => place(id).getAttribute('data-tokens')));
  await step();
  assert.deepEqual(await tokens(), ['1', '0', '0'], 'T1 waits for Go');
  assert.equal(await transition('T1').getAttribute('aria-label'), 'Transition T1, enabled', 'marked, waiting for its guard');
  await page.getByRole('checkbox', { name: 'Go', exact: true }).check();
  await step();
  assert.deepEqual(await tokens(), ['0', '1', '0'], 'Go fires T1');
  assert.equal(await transition('T1').getAttribute('aria-label'), 'Transition T1, fired');
  assert.equal(await place('P2').getAttribute('aria-label'), 'Place P2: 1 token');
  await step();
  await page.waitForFunction(() => /^2:/.test(document.querySelector('.code-active')?.dataset.text ?? ''));
  assert.equal(await page.getByRole('img', { name: 'Busy: ON', exact: true }).count(), 1, 'the P2 branch ran');
  assert.deepEqual(await tokens(), ['0', '0', '1'], 'T2 has no guard: it fires on the next scan');
  await step();
  assert.deepEqual(await tokens(), ['1', '0', '0'], 'T3 closes the cycle');

  // Move P2 with the mouse: its arcs follow; undo puts it back.
  const arcEnds = () => view.locator('.pn-arc').evaluateAll((ls) => ls.map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(',')).sort().join(' '));
  const before = await arcEnds();
  const p2 = await centre(place('P2'));
  const target = await at(canvas, 440, 100);
  await page.mouse.move(p2.x, p2.y);
  await page.mouse.down();
  await page.mouse.move(target.x, target.y, { steps: 8 });
  await page.mouse.up();
  await page.waitForFunction((b) => b !== [...document.querySelectorAll('.pn-arc')].map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(',')).sort().join(' '), before);
  const moved = await centre(place('P2'));
  assert.ok(Math.abs(moved.x - target.x) < 12 && Math.abs(moved.y - target.y) < 12, 'P2 is where it was dropped');
  const ends = (await arcEnds()).split(' ').map((e) => e.split(',').map(Number));
  const near = (x, y) => ends.some(([x1, y1, x2, y2]) => Math.hypot(x1 - x, y1 - y) < 30 || Math.hypot(x2 - x, y2 - y) < 30);
  assert.ok(near(440, 100), 'arcs end at the moved place');
  await view.getByRole('button', { name: 'Undo' }).click();
  await page.waitForFunction((b) => b === [...document.querySelectorAll('.pn-arc')].map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(',')).sort().join(' '), before);

  // Keys: arrows move the focused place by a grid step; Delete deletes it with its arcs.
  await place('P3').focus();
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.activeElement?.dataset.id === 'P3');
  await page.keyboard.press('Delete');
  await place('P3').waitFor({ state: 'detached' });
  assert.equal(await view.locator('.pn-arc').count(), 4);
  await page.keyboard.press('Control+z');
  await place('P3').waitFor();
  assert.equal(await view.locator('.pn-arc').count(), 6);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/petri-editor.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});
