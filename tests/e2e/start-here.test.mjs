// A way in (issue 31): a first visit opens `Start here`, a guided lesson of five steps
// that moves on as the student does each thing; finished or skipped it stays closed after
// a reload, and `Help` opens it again (with the keyboard shortcuts and the problems page).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { mkdirSync } from 'node:fs';
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

async function openApp(context) {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { page, errors };
}

/** Drags with the mouse (pointer events) from the middle of one element to another's. */
async function drag(page, from, to) {
  const a = await from.boundingBox();
  const b = await to.boundingBox();
  await page.mouse.move(a.x + a.width / 2, a.y + a.height / 2);
  await page.mouse.down();
  await page.mouse.move(b.x + b.width / 2, b.y + b.height / 2, { steps: 8 });
  await page.mouse.up();
}

const cell = (view, rung, row, col) =>
  view.getByRole('gridcell', { name: new RegExp(`^Rung ${rung}, row ${row}, column ${col}: `) });

async function place(page, view, at, tool, operand) {
  await cell(view, ...at).waitFor();
  await drag(page, view.getByRole('button', { name: tool, exact: true }), cell(view, ...at));
  const box = view.getByRole('textbox', { name: 'Operand' });
  await box.fill(operand);
  await box.press('Enter');
}

const target = (page) => page.evaluate(() => document.documentElement.dataset.tourTarget ?? '');

test('a first visit walks Start here to its end by doing each step; it stays closed after a reload; Help opens it again', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const { page, errors } = await openApp(context);
  const tour = page.getByRole('region', { name: 'Start here' });
  await tour.waitFor();
  const at = (n) => tour.getByText(`Step ${n} of 5`, { exact: true }).waitFor();
  const shot = (n) => page.screenshot({ path: path.join(shots, `start-here-${n}.png`) });

  // 1. Flip an input and see a lamp.
  await at(1);
  await tour.getByRole('heading', { name: 'Flip an input and see a lamp' }).waitFor();
  assert.equal(await tour.getByRole('button', { name: 'Back' }).isDisabled(), true);
  assert.equal(await target(page), 'run io');
  await shot(1);
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor();
  await tour.getByText('✓ Done').waitFor();

  // 2. Change one line of ST.
  await at(2);
  assert.equal(await target(page), 'st');
  await shot(2);
  const editor = page.getByRole('textbox', { name: 'ST source' });
  const source = await editor.inputValue();
  assert.match(source, /Motor := \(Start OR Motor\) AND NOT Stop;/, 'the tour fits what a first visit opens');
  await editor.fill(source.replace('Motor := (Start OR Motor) AND NOT Stop;', 'Motor := Start AND NOT Stop;'));
  await page.getByRole('checkbox', { name: 'Start', exact: true }).uncheck();
  await page.getByRole('img', { name: 'Motor: OFF' }).waitFor();

  // 3. Draw one rung: a new ladder POU with a free name, a contact and a coil.
  await at(3);
  assert.equal(await target(page), 'ladder');
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  const dialog = page.getByRole('dialog', { name: 'New ladder POU' });
  assert.equal(await dialog.getByRole('textbox', { name: 'POU name' }).inputValue(), 'Ladder1');
  await dialog.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: 'Ladder diagram Ladder1' });
  await view.waitFor();
  await shot(3);
  await place(page, view, [1, 1, 1], 'NO contact', 'Start');
  await place(page, view, [1, 1, 2], 'Coil', 'Lamp');
  await page.getByRole('button', { name: 'Declare Start' }).click();
  await page.getByRole('button', { name: 'Declare Lamp' }).click();
  await page.getByText('No problems found.').waitFor();

  // 4. Press Step and read the timeline.
  await at(4);
  assert.equal(await target(page), 'step');
  await page.evaluate(() => window.scrollTo(0, 0));
  await shot(4);
  await page.getByRole('checkbox', { name: 'Chart Motor' }).check();
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await page.getByRole('img', { name: 'Timeline chart' }).waitFor();

  // 5. Open the first exercise.
  await at(5);
  assert.equal(await target(page), 'exercises');
  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  const list = page.getByRole('list', { name: 'Exercise list' });
  await list.waitFor();
  await shot(5);
  await list.getByRole('button', { name: 'Start/stop motor latch' }).click();
  await page.getByRole('region', { name: 'Exercise' }).getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();

  // The end.
  await tour.getByText('Finished', { exact: true }).waitFor();
  assert.equal(await target(page), '');
  await tour.getByRole('button', { name: 'Close tour' }).click();
  await tour.waitFor({ state: 'detached' });

  await page.reload();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.getByRole('region', { name: 'Exercise' }).waitFor();
  assert.equal(await tour.count(), 0, 'finished, it does not come back');

  // Help opens it again at its first step; Next and Back move by hand.
  await page.getByRole('button', { name: 'Help' }).click();
  await page.getByRole('menuitem', { name: 'Start here' }).click();
  await at(1);
  await tour.getByRole('button', { name: 'Next' }).click();
  await at(2);
  await tour.getByRole('button', { name: 'Back' }).click();
  await at(1);
  assert.deepEqual(errors, []);
  await context.close();
});

test('Skip tour closes it for good; Help lists the shortcuts and the problems page', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  const tour = page.getByRole('region', { name: 'Start here' });
  await tour.getByRole('button', { name: 'Skip tour' }).click();
  await tour.waitFor({ state: 'detached' });
  await page.reload();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.waitForTimeout(300);
  assert.equal(await tour.count(), 0);

  // The menu works from the keyboard: it opens on the first item, Escape closes it.
  const help = page.getByRole('button', { name: 'Help' });
  await help.focus();
  await page.keyboard.press('Enter');
  await page.waitForFunction(() => document.activeElement?.textContent === 'Start here');
  await page.keyboard.press('ArrowDown');
  await page.waitForFunction(() => document.activeElement?.textContent === 'Keyboard shortcuts');
  await page.keyboard.press('ArrowDown');
  const problems = page.getByRole('menuitem', { name: 'Problems explained' });
  assert.equal(await problems.getAttribute('href'), 'problems.html');
  await page.keyboard.press('Escape');
  await page.getByRole('menu', { name: 'Help' }).waitFor({ state: 'hidden' });
  assert.equal(await help.getAttribute('aria-expanded'), 'false');

  await help.click();
  await page.getByRole('menuitem', { name: 'Keyboard shortcuts' }).click();
  const dialog = page.getByRole('dialog', { name: 'Keyboard shortcuts' });
  await dialog.waitFor();
  const text = await dialog.textContent();
  for (const keys of ['Ctrl+Z', 'Ctrl+C / Ctrl+V', 'c / n', 'o / s / r', 'w / l', 'Enter or F2']) {
    assert.ok(text.includes(keys), `the shortcuts list ${keys}`);
  }
  await page.screenshot({ path: path.join(shots, 'keyboard-shortcuts.png') });
  await page.keyboard.press('Escape');
  await dialog.waitFor({ state: 'hidden' });
  assert.deepEqual(errors, []);
  await context.close();
});
