// Issue 31: exercises grade what the student wrote. A student opens the latch, chooses
// `Start in` Ladder, drags the rung from the palette and checks: 3 of 3, the report naming
// the ladder PROGRAM, nothing touched under Simulation. Started in ST the same; `Program to
// check` chooses another PROGRAM (the Simulation's `Program` follows). A Petri net
// exercise starts as a net with its interface declared.
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

async function fresh() {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { context, page, errors };
}

/** Opens a shipped exercise from the catalogue. */
async function openExercise(page, title) {
  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: title }).click();
  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: title }).waitFor();
  return panel;
}

async function check(page) {
  await page.getByRole('button', { name: 'Check', exact: true }).click();
  const report = page.getByRole('region', { name: 'Report' });
  await report.waitFor();
  await page.waitForFunction(() => !document.querySelector('.exercise-actions button.primary')?.disabled);
  return report;
}

const optionLabels = (select) => select.locator('option').evaluateAll((os) => os.map((o) => o.textContent));

/** Where an element is, scrolled into view, once it is on the page (the grid is redrawn
 * after each edit, so an element found may be replaced before it is measured). */
async function box(locator) {
  for (let tries = 0; ; tries += 1) {
    try {
      await locator.scrollIntoViewIfNeeded({ timeout: 2000 });
      const b = await locator.boundingBox();
      if (b) return b;
    } catch (e) {
      if (tries > 20) throw e;
    }
  }
}

/** Drags with the mouse (pointer events) from the middle of one element to another's. */
async function drag(page, from, to) {
  const a = await box(from);
  const b = await box(to);
  await page.mouse.move(a.x + a.width / 2, a.y + a.height / 2);
  await page.mouse.down();
  await page.mouse.move(b.x + b.width / 2, b.y + b.height / 2, { steps: 8 });
  await page.mouse.up();
}

const cell = (view, rung, row, col) =>
  view.getByRole('gridcell', { name: new RegExp(`^Rung ${rung}, row ${row}, column ${col}: `) });

/** Drags a palette element onto a cell, then types its operand. */
async function place(page, view, [rung, row, col], tool, operand) {
  const target = cell(view, rung, row, col);
  await box(target);
  await drag(page, view.getByRole('button', { name: tool, exact: true }), target);
  if (operand !== undefined) {
    const box = view.getByRole('textbox', { name: 'Operand' });
    await box.fill(operand);
    await box.press('Enter');
  }
}

test('the latch started in Ladder, drawn by drag and drop, scores 3 of 3 and the report names the ladder PROGRAM', async () => {
  const { context, page, errors } = await fresh();
  const panel = await openExercise(page, 'Start/stop motor latch');
  const startIn = panel.getByRole('combobox', { name: 'Start in' });
  assert.deepEqual(await optionLabels(startIn), ['Structured Text', 'Ladder']);
  assert.equal(await startIn.inputValue(), 'st', 'the attempt opens in the first language');
  // Untouched, the starter is swapped at once (no question).
  let asked = 0;
  page.on('dialog', (d) => { asked += 1; d.dismiss(); });
  await startIn.selectOption({ label: 'Ladder' });
  const view = page.getByRole('region', { name: 'Ladder diagram Main' });
  await view.waitFor();
  assert.equal(asked, 0);
  assert.equal(await startIn.inputValue(), 'ld');
  const decls = await view.getByRole('textbox', { name: 'Declarations' }).inputValue();
  assert.match(decls, /VAR_INPUT\n {4}Start : BOOL; \(\* start button \(NO\) \*\)\n {4}Stop : BOOL;/);
  assert.match(decls, /VAR_OUTPUT\n {4}Motor : BOOL; \(\* motor contactor \*\)/);
  const toCheck = panel.getByRole('combobox', { name: 'Program to check' });
  assert.deepEqual(await optionLabels(toCheck), ['Main (ladder)']);

  await place(page, view, [1, 1, 1], 'NO contact', 'Start');
  await place(page, view, [1, 1, 2], 'NC contact', 'Stop');
  await place(page, view, [1, 1, 3], 'Coil', 'Motor');
  await place(page, view, [1, 2, 1], 'NO contact', 'Motor');
  await place(page, view, [1, 1, 2], 'Link down');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop, linked down' }).waitFor();
  await page.waitForTimeout(500); // the debounced check and save

  const report = await check(page);
  assert.equal(await report.locator('.report-program').textContent(), 'Checked PROGRAM Main (ladder)');
  await report.getByText('Score 3 of 3: every scenario passes. Well done!').waitFor();
  // Nothing under Simulation was needed: with one PROGRAM it offers no choice at all.
  assert.equal(await page.getByRole('combobox', { name: 'Program to run' }).count(), 0);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/exercise-start-in-ladder.png'), fullPage: true });

  // Back to ST after drawing: the work would be lost, so it asks; declining keeps it all.
  await startIn.selectOption({ label: 'Structured Text' });
  assert.equal(asked, 1);
  assert.equal(await startIn.inputValue(), 'ld', 'the select shows the attempt’s language again');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil Motor' }).waitFor();
  // After a reload the ladder attempt and its language are still there.
  await page.reload();
  await page.getByRole('region', { name: 'Ladder diagram Main' }).getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil Motor' }).waitFor();
  assert.equal(await page.getByRole('combobox', { name: 'Start in' }).inputValue(), 'ld');
  assert.deepEqual(errors, []);
  await context.close();
});

const RIGHT = `PROGRAM Main
VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
`;
const OTHER = `
PROGRAM Other
VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
Motor := Start AND NOT Stop;
END_PROGRAM
`;

test('the latch started in ST scores 3 of 3; Program to check grades another PROGRAM and Simulation follows', async () => {
  const { context, page, errors } = await fresh();
  const panel = await openExercise(page, 'Start/stop motor latch');
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'));
  await editor.fill(RIGHT);
  await page.waitForTimeout(500);
  let report = await check(page);
  assert.equal(await report.locator('.report-program').textContent(), 'Checked PROGRAM Main (ST)');
  await report.getByText('Score 3 of 3: every scenario passes. Well done!').waitFor();

  // A second PROGRAM, without the seal-in, chosen in the exercise panel.
  await editor.fill(RIGHT + OTHER);
  await page.waitForTimeout(500);
  const toCheck = panel.getByRole('combobox', { name: 'Program to check' });
  assert.deepEqual(await optionLabels(toCheck), ['Main (ST)', 'Other (ST)']);
  assert.equal(await toCheck.inputValue(), 'Main');
  await toCheck.selectOption('Other');
  report = await check(page);
  assert.equal(await report.locator('.report-program').textContent(), 'Checked PROGRAM Other (ST)');
  assert.equal(await report.locator('.report-score').textContent(), 'Score 1 of 3 (scenario weights: 2 + 1)');
  // One setting: the simulator runs the PROGRAM chosen, and choosing there is seen here.
  const toRun = page.getByRole('combobox', { name: 'Program to run' });
  assert.equal(await toRun.inputValue(), 'Other');
  await toRun.selectOption('Main');
  await page.waitForFunction(() => document.querySelector('select[aria-label="Program to check"]')?.value === 'Main');
  report = await check(page);
  assert.equal(await report.locator('.report-program').textContent(), 'Checked PROGRAM Main (ST)');
  await page.screenshot({ path: path.join(root, 'docs/screenshots/exercise-start-in-st.png') });
  assert.deepEqual(errors, []);
  await context.close();
});

test('a Petri net exercise starts as a net with its interface declared, and in ST on request', async () => {
  const { context, page, errors } = await fresh();
  const panel = await openExercise(page, 'Weighing process as one sequence');
  const startIn = panel.getByRole('combobox', { name: 'Start in' });
  assert.deepEqual(await optionLabels(startIn), ['Petri net', 'Structured Text']);
  assert.equal(await startIn.inputValue(), 'petri');
  const view = page.getByRole('region', { name: 'Petri net Weighing' });
  await view.getByRole('group', { name: 'Net canvas' }).waitFor();
  await page.screenshot({ path: path.join(root, 'docs/screenshots/exercise-start-in-petri.png'), fullPage: true });
  await view.locator('summary', { hasText: 'Declarations' }).click();
  const decls = await view.getByRole('textbox', { name: 'Declarations' }).inputValue();
  assert.match(decls, /Start : BOOL;/);
  assert.match(decls, /Weight : INT\(0\.\.1000\);/);
  // The net holds the starter's initial place only.
  assert.equal(await view.locator('.pn-place').count(), 1);
  assert.equal(await view.locator('.pn-transition').count(), 0);
  assert.deepEqual(await optionLabels(panel.getByRole('combobox', { name: 'Program to check' })), ['Weighing (Petri net)']);

  await startIn.selectOption({ label: 'Structured Text' });
  await page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.startsWith('PROGRAM Weighing\nVAR_INPUT\n'));
  const source = await page.getByRole('textbox', { name: 'ST source' }).inputValue();
  assert.match(source, /Setpoint : INT; \(\* target weight, 0\.\.1000 \*\)/);
  assert.equal(await startIn.inputValue(), 'st');
  const report = await check(page);
  assert.equal(await report.locator('.report-program').textContent(), 'Checked PROGRAM Weighing (ST)');
  assert.deepEqual(errors, []);
  await context.close();
});
