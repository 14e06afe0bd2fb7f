// Messages that teach, as a student meets them in Chromium against the release build: a
// misspelled name says which declared name it probably means and offers to replace it; an
// undeclared one offers to declare it; both are one undo step of the editor they change;
// the ladder editor's operands get the same. The push-button box of an input says what it
// does in words on the page, not only in a tooltip.
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

async function openApp() {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { context, page, errors };
}

/** Puts the caret at the start of the line `END_PROGRAM` and types `line` there, as a
 * student adds a statement before the end of the program. */
async function typeBeforeEnd(page, line) {
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await editor.click();
  await page.keyboard.press('Control+End');
  await page.keyboard.press('ArrowUp');
  await page.keyboard.press('Home');
  await page.keyboard.type(line);
  await page.keyboard.press('Enter');
}

const problems = (page) => page.getByRole('list', { name: 'Problems' });
const source = (page) => page.getByRole('textbox', { name: 'ST source' }).inputValue();

test('Motr: did you mean Motor? Replace with Motor fixes it; Declare Lamp2 declares it; Undo takes each back', async () => {
  const { context, page, errors } = await openApp();
  const region = page.getByRole('region', { name: 'Problems of the project' });
  await region.getByText('No problems found.').waitFor();

  await typeBeforeEnd(page, 'Motr := TRUE;');
  const misspelt = problems(page).getByRole('button', { name: /E0100 +`Motr` is not declared; did you mean Motor\?$/ });
  await misspelt.waitFor();
  const replace = region.getByRole('button', { name: 'Replace with Motor' });
  await replace.waitFor();
  // The name is also offered for declaring, as it stands.
  await region.getByRole('button', { name: 'Declare Motr' }).waitFor();
  await page.screenshot({ path: path.join(shots, 'did-you-mean.png') });

  await replace.click();
  await region.getByText('No problems found.').waitFor();
  assert.match(await source(page), /\nMotor := TRUE;\nEND_PROGRAM/);
  // The caret stands after the replaced name, in the editor, ready for more typing.
  assert.equal(await page.evaluate(() => document.activeElement?.getAttribute('aria-label')), 'ST source');
  // Undo (the editor's button) brings the misspelling and its problem back; Redo fixes it again.
  const toolbar = page.locator('.editor .ed-toolbar');
  await toolbar.getByRole('button', { name: 'Undo' }).click();
  await misspelt.waitFor();
  assert.match(await source(page), /\nMotr := TRUE;\n/);
  await toolbar.getByRole('button', { name: 'Redo' }).click();
  await region.getByText('No problems found.').waitFor();

  // A name close to none: no guess, but Declare, with the type the statement implies; the
  // POU writes it, so it becomes an output and the I/O panel shows its lamp.
  await typeBeforeEnd(page, 'Lamp2 := Start AND NOT Stop;');
  await problems(page).getByRole('button', { name: /E0100 +`Lamp2` is not declared$/ }).waitFor();
  assert.equal(await region.getByRole('button', { name: /^Replace with/ }).count(), 0);
  await region.getByRole('button', { name: 'Declare Lamp2' }).click();
  await region.getByText('No problems found.').waitFor();
  assert.match(await source(page), /VAR_OUTPUT\n {4}Motor : BOOL; \(\* motor contactor \*\)\n {4}Lamp2 : BOOL;\nEND_VAR/);
  await page.getByRole('img', { name: 'Lamp2: OFF' }).waitFor();
  await toolbar.getByRole('button', { name: 'Undo' }).click();
  await problems(page).getByRole('button', { name: /`Lamp2` is not declared/ }).waitFor();
  assert.doesNotMatch(await source(page), /Lamp2 : BOOL/);

  // A narrowing says which way it does not convert and what to write.
  await page.getByRole('textbox', { name: 'ST source' }).fill(
    'PROGRAM Main\nVAR_OUTPUT Level : INT; END_VAR\nVAR r : REAL := 2.5; END_VAR\nLevel := r;\nEND_PROGRAM\n',
  );
  await problems(page)
    .getByRole('button', { name: /E0150 +REAL does not convert to INT without possible loss: convert it explicitly with REAL_TO_INT\(…\)$/ })
    .waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('a misspelled ladder operand: did you mean Motor? Replace with Motor puts it right, one undo step', async () => {
  const { context, page, errors } = await openApp();
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: 'Ladder latch' });
  const view = page.getByRole('region', { name: 'Ladder diagram Latch' });
  await view.waitFor();
  const coil = view.getByRole('gridcell', { name: /^Rung 1, row 1, column 3: coil Motor$/ });
  await coil.click();
  await page.keyboard.press('Enter');
  const box = view.getByRole('textbox', { name: 'Operand' });
  await box.fill('Motr');
  await box.press('Enter');
  await view.getByRole('gridcell', { name: /^Rung 1, row 1, column 3: coil Motr$/ }).waitFor();
  const region = page.getByRole('region', { name: 'Problems of the project' });
  await region
    .getByRole('button', { name: /Latch, rung 1, row 1, column 3 +E0418 +this coil's operand `Motr` is not declared; did you mean Motor\?$/ })
    .waitFor();
  await region.getByRole('button', { name: 'Declare Motr' }).waitFor();
  await region.getByRole('button', { name: 'Replace with Motor' }).click();
  await view.getByRole('gridcell', { name: /^Rung 1, row 1, column 3: coil Motor$/ }).waitFor();
  await page.waitForFunction(() => !document.querySelector('.problems')?.textContent.includes('E0418'));
  await view.getByRole('button', { name: 'Undo' }).click();
  await view.getByRole('gridcell', { name: /^Rung 1, row 1, column 3: coil Motr$/ }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('the push-button box of an input reads “hold”, and the panel says what it does', async () => {
  const { context, page, errors } = await openApp();
  const io = page.getByRole('region', { name: 'Inputs and outputs' });
  const hold = io.getByRole('checkbox', { name: 'Start: hold (push button)' });
  await hold.waitFor();
  assert.equal((await io.locator('label.push-mode').first().innerText()).trim(), 'hold');
  await io.getByText('“hold”: a push button, TRUE only while held down.').waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});
