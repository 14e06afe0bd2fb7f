// The rung grid as a person uses it (issue 34): a drop lands on the cell it was dropped on.
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
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { page, errors };
}

/** Adds a ladder PROGRAM named `name` with `declarations` and shows it. */
async function newLadderProgram(page, name, declarations) {
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill(name);
  await page.getByRole('combobox', { name: 'POU kind' }).selectOption('PROGRAM');
  await page.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: `Ladder diagram ${name}` });
  await view.waitFor();
  const decls = view.getByRole('textbox', { name: 'Declarations' });
  await decls.fill(declarations);
  await decls.press('Tab');
  return view;
}

const cell = (view, rung, row, col) =>
  view.getByRole('gridcell', { name: new RegExp(`^Rung ${rung}, row ${row}, column ${col}: `) });

const centre = async (loc) => {
  const b = await loc.boundingBox();
  return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
};

const steps = (from, to, n = 8) => Array.from({ length: n }, (_, i) => ({
  x: from.x + ((to.x - from.x) * (i + 1)) / n,
  y: from.y + ((to.y - from.y) * (i + 1)) / n,
}));

/** Drags with the mouse from the middle of one element to another's. */
async function mouseDrag(page, from, to) {
  const a = await centre(from);
  const b = await centre(to);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move(b.x, b.y, { steps: 8 });
  await page.mouse.up();
}

/** Drags with one finger from the middle of one element to another's. */
async function touchDrag(cdp, from, to) {
  const a = await centre(from);
  const b = await centre(to);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [a] });
  for (const p of steps(a, b)) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [p] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

async function operand(view, text) {
  const box = view.getByRole('textbox', { name: 'Operand' });
  await box.fill(text);
  await box.press('Enter');
  await box.waitFor({ state: 'detached' });
}

const LATCH_DECLS = `VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
`;

test('the lost drop: Link down dragged onto the NC contact Stop after a touch drag lands, ten times in a row', async () => {
  for (let attempt = 1; attempt <= 10; attempt++) {
    const context = await browser.newContext({ viewport: { width: 1400, height: 900 }, hasTouch: true });
    const { page, errors } = await openApp(context);
    const cdp = await context.newCDPSession(page);
    const view = await newLadderProgram(page, 'Latch', LATCH_DECLS);
    const tool = (name) => view.getByRole('button', { name, exact: true });
    await mouseDrag(page, tool('NO contact'), cell(view, 1, 1, 1));
    await operand(view, 'Start');
    await mouseDrag(page, tool('NC contact'), cell(view, 1, 1, 2));
    await operand(view, 'Stop');
    await mouseDrag(page, tool('Coil'), cell(view, 1, 1, 3));
    await operand(view, 'Motor');
    await touchDrag(cdp, tool('NO contact'), cell(view, 1, 2, 1));
    await operand(view, 'Motor');
    await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 1: NO contact Motor' }).waitFor();
    await mouseDrag(page, tool('Link down'), view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop' }));
    const linked = view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop, linked down' });
    await linked.waitFor({ timeout: 3000 }).catch(() => {});
    const names = await view.getByRole('gridcell').evaluateAll((cells) => cells.slice(0, 12).map((c) => c.getAttribute('aria-label')));
    assert.equal(await linked.count(), 1, `attempt ${attempt}: the link was not placed; cells: ${names.join(' | ')}`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

