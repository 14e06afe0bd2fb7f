// The ladder editor (issue 13): a student builds rungs in a new project with the palette,
// keys and the operand box, runs them, undoes and redoes, and finds them after a reload.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { readFile, writeFile, mkdtemp } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import os from 'node:os';
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

/** Drags with the mouse (pointer events) from the middle of one element to another's. */
async function drag(page, from, to) {
  const a = await from.boundingBox();
  const b = await to.boundingBox();
  await page.mouse.move(a.x + a.width / 2, a.y + a.height / 2);
  await page.mouse.down();
  await page.mouse.move(b.x + b.width / 2, b.y + b.height / 2, { steps: 8 });
  await page.mouse.up();
}

/** Drags a palette element onto a cell, then types its operand. */
async function place(page, view, [rung, row, col], tool, operand) {
  await drag(page, view.getByRole('button', { name: tool, exact: true }), cell(view, rung, row, col));
  if (operand !== undefined) {
    const box = view.getByRole('textbox', { name: 'Operand' });
    await box.fill(operand);
    await box.press('Enter');
  }
}

const LATCH_DECLS = `VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
`;

test('a start/stop latch dragged from the palette in a new project runs, undoes, redoes and survives a reload', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  const view = await newLadderProgram(page, 'Latch', LATCH_DECLS);
  await place(page, view, [1, 1, 1], 'NO contact', 'Start');
  await place(page, view, [1, 1, 2], 'NC contact', 'Stop');
  await place(page, view, [1, 1, 3], 'Coil', 'Motor');
  await place(page, view, [1, 2, 1], 'NO contact', 'Motor');
  await place(page, view, [1, 1, 2], 'Link down');
  await cell(view, 1, 1, 2).and(page.getByRole('gridcell', { name: 'NC contact Stop, linked down' })).waitFor();
  assert.equal(await cell(view, 1, 1, 3).getAttribute('aria-selected'), 'false');
  assert.equal(await cell(view, 1, 1, 2).getAttribute('aria-selected'), 'true');
  // A placed element is dragged to another cell, and the move undone.
  await drag(page, cell(view, 1, 1, 3), cell(view, 1, 1, 5));
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 5: coil Motor' }).waitFor();
  await view.getByRole('button', { name: 'Undo' }).click();
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil Motor' }).waitFor();

  // Undo takes back the link, then the Motor contact; redo puts both back.
  await view.getByRole('button', { name: 'Undo' }).click();
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop' }).waitFor();
  await page.keyboard.press('Control+z');
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 1: empty' }).waitFor();
  await page.keyboard.press('Control+Shift+Z');
  await view.getByRole('button', { name: 'Redo' }).click();
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop, linked down' }).waitFor();
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 1: NO contact Motor' }).waitFor();

  // The ST beside the rungs: the selected rung's line is lit.
  const side = view.getByRole('complementary', { name: 'ST beside the rungs of Latch' });
  const line = side.locator('.ld-st-line', { hasText: 'Motor := (Start OR Motor) AND NOT Stop;' });
  await line.waitFor();
  await cell(view, 1, 1, 1).click();
  assert.match(await line.getAttribute('class'), /\blit\b/);

  // Run it: the ladder PROGRAM is chosen under Simulation.
  await page.waitForTimeout(700);
  await page.getByRole('combobox', { name: 'Program to run' }).selectOption('Latch');
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await view.locator('[role="gridcell"][data-power]').first().waitFor();
  assert.equal(await cell(view, 1, 1, 3).getAttribute('data-power'), 'off');
  await page.getByRole('img', { name: 'Motor: OFF', exact: true }).waitFor();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON', exact: true }).waitFor({ timeout: 5000 });
  await view.locator('[role="gridcell"][data-power="on"]').first().waitFor();
  assert.equal(await cell(view, 1, 1, 3).getAttribute('data-power'), 'on');
  await page.getByRole('checkbox', { name: 'Start', exact: true }).uncheck();
  await page.waitForTimeout(300);
  await page.getByRole('img', { name: 'Motor: ON', exact: true }).waitFor();
  assert.equal(await cell(view, 1, 2, 1).getAttribute('data-power'), 'on', 'the Motor contact holds');
  await page.getByRole('checkbox', { name: 'Stop', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: OFF', exact: true }).waitFor({ timeout: 5000 });
  await page.screenshot({ path: path.join(root, 'docs/screenshots/ladder-editor.png'), fullPage: true });

  // A reload finds the rungs as they were; so does a fresh browser opening the share link.
  await page.reload();
  await page.getByRole('button', { name: 'Ladder diagram Latch' }).click();
  await page.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop, linked down' }).waitFor();
  await page.getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil Motor' }).waitFor();
  const names = await page.getByRole('gridcell').evaluateAll((cells) => cells.map((c) => c.getAttribute('aria-label')));
  await page.getByRole('button', { name: 'Share' }).click();
  const link = await page.getByRole('textbox', { name: 'Share link' }).inputValue();
  const other = await browser.newContext();
  const shared = await other.newPage();
  await shared.goto(link);
  await shared.getByRole('button', { name: 'Ladder diagram Latch' }).click();
  await shared.getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil Motor' }).waitFor();
  assert.deepEqual(await shared.getByRole('gridcell').evaluateAll((cells) => cells.map((c) => c.getAttribute('aria-label'))), names);
  await other.close();

  // Exported as PLCopen XML, the rungs read back: `plc run` runs the ladder PROGRAM.
  const download = page.waitForEvent('download');
  await page.getByRole('button', { name: 'Export PLCopen XML' }).click();
  const xml = await readFile(await (await download).path(), 'utf8');
  assert.match(xml, /<project xmlns="http:\/\/www\.plcopen\.org\/xml\/tc6_0201"/);
  assert.match(xml, /<pou name="Latch" pouType="program">/);
  const plc = path.join(root, 'target/debug/plc');
  if (existsSync(plc)) {
    const file = path.join(await mkdtemp(path.join(os.tmpdir(), 'plc-')), 'latch.xml');
    await writeFile(file, xml);
    const out = execFileSync(plc, ['run', file, '--program', 'Latch', '--cycles', '2', '--set', 'Start=TRUE', '--json']).toString();
    assert.equal(JSON.parse(out).vars.Motor, true, out);
  }
  assert.deepEqual(errors, []);
  await context.close();
});

test('keys alone build a rung, Escape takes a placement back, and a block gets an instance and pins', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  const view = await newLadderProgram(page, 'Delay', 'VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Lamp : BOOL;\nEND_VAR\n');
  await cell(view, 1, 1, 1).focus();
  await page.keyboard.press('c');
  await page.keyboard.type('Go');
  await page.keyboard.press('Enter');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('o');
  await page.keyboard.press('Escape');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: empty' }).waitFor();
  // `b` opens the block picker; typing picks TON and Enter puts it into the cell.
  await page.keyboard.press('b');
  await view.getByRole('combobox', { name: 'Block type' }).waitFor();
  await page.keyboard.type('TON');
  await page.keyboard.press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: TON T1' }).waitFor();
  const pt = view.getByRole('textbox', { name: 'PT of T1' });
  assert.equal(await pt.inputValue(), 'T#1s', 'a timer starts with a preset');
  await pt.fill('T#2s');
  await pt.press('Tab');
  assert.match(await view.getByRole('textbox', { name: 'Declarations' }).inputValue(), /T1 : TON;/);
  await cell(view, 1, 1, 3).click();
  await page.keyboard.press('o');
  await page.keyboard.type('Lamp');
  await page.keyboard.press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil Lamp' }).waitFor();
  await view.getByRole('textbox', { name: 'Comment of rung 1' }).fill('Lamp 2 s after Go');
  await view.getByRole('textbox', { name: 'Comment of rung 1' }).press('Enter');
  // Step the clock: Lamp comes on after 2 s, not before.
  await page.waitForTimeout(700);
  await page.getByRole('combobox', { name: 'Program to run' }).selectOption('Delay');
  await page.getByRole('checkbox', { name: 'Go', exact: true }).check();
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('199');
  await page.getByRole('button', { name: 'Step N' }).click();
  await page.getByRole('img', { name: 'Lamp: OFF', exact: true }).waitFor();
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('2');
  await page.getByRole('button', { name: 'Step N' }).click();
  await page.getByRole('img', { name: 'Lamp: ON', exact: true }).waitFor();
  assert.equal(await view.getByRole('textbox', { name: 'Comment of rung 1' }).inputValue(), 'Lamp 2 s after Go');
  // The POU is renamed, then deleted (after confirming).
  await view.getByRole('button', { name: 'Rename POU' }).click();
  await page.getByRole('textbox', { name: 'New POU name' }).fill('Timer');
  await page.getByRole('textbox', { name: 'New POU name' }).press('Enter');
  const renamed = page.getByRole('region', { name: 'Ladder diagram Timer' });
  await renamed.waitFor();
  page.once('dialog', (d) => d.accept());
  await renamed.getByRole('button', { name: 'Delete POU' }).click();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  assert.equal(await page.getByRole('button', { name: 'Ladder diagram Timer' }).count(), 0);
  assert.deepEqual(errors, []);
  await context.close();
});

test('twenty mixed edits undo one by one to the exact earlier grids and redo to the last', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  const view = await newLadderProgram(page, 'Mixed', 'VAR\n    a, b, c, q : BOOL;\nEND_VAR\n');
  const grid = () => view.getByRole('gridcell').evaluateAll((cells) => cells.map((c) => c.getAttribute('aria-label')).join('|'));
  const snapshots = [await grid()];
  const keys = [
    ['c', 'a'], ['ArrowRight'], ['n', 'b'], ['ArrowRight'], ['o', 'q'], ['ArrowDown'], ['w'],
    ['ArrowLeft'], ['l'], ['ArrowLeft'], ['c', 'c'], ['Delete'], ['s', 'q'], ['r', 'q'],
    ['ArrowDown'], ['w'], ['ArrowRight'], ['n', 'c'],
  ];
  await cell(view, 1, 1, 1).focus();
  for (const [key, operand] of keys) {
    await page.keyboard.press(key);
    if (operand) {
      await page.keyboard.type(operand);
      await page.keyboard.press('Enter');
    }
    if (!key.startsWith('Arrow')) {
      const now = await grid();
      assert.notEqual(now, snapshots[snapshots.length - 1], `the key ${key} changed the rung`);
      snapshots.push(now);
    }
  }
  // Rung and grid buttons until there are twenty edits (a button that changes nothing here,
  // such as Move rung up on the first rung, is no edit).
  for (const action of ['Add rung', 'Insert row', 'Insert column', 'Delete column', 'Move rung up', 'Delete row', 'Add rung', 'Delete rung', 'Move rung down', 'Insert row', 'Insert column']) {
    if (snapshots.length > 20) break;
    await view.getByRole('button', { name: action, exact: true }).click();
    const now = await grid();
    if (now !== snapshots[snapshots.length - 1]) snapshots.push(now);
  }
  assert.equal(snapshots.length, 21, 'twenty edits');
  for (let i = snapshots.length - 2; i >= 0; i--) {
    await view.getByRole('button', { name: 'Undo' }).click();
    assert.equal(await grid(), snapshots[i], `after undoing back to step ${i}`);
  }
  // The one step before them typed the declarations; then nothing is left to undo.
  await view.getByRole('button', { name: 'Undo' }).click();
  assert.equal(await grid(), snapshots[0]);
  assert.equal(await view.getByRole('button', { name: 'Undo' }).isDisabled(), true);
  await view.getByRole('button', { name: 'Redo' }).click();
  for (let i = 1; i < snapshots.length; i++) {
    await view.getByRole('button', { name: 'Redo' }).click();
    assert.equal(await grid(), snapshots[i], `after redoing step ${i}`);
  }
  assert.equal(await view.getByRole('button', { name: 'Redo' }).isDisabled(), true);
  assert.deepEqual(errors, []);
  await context.close();
});

test('an undeclared operand is declared from its problem with the type its use implies', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Fresh');
  await page.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: 'Ladder diagram Fresh' });
  await view.waitFor();
  await cell(view, 1, 1, 1).click();
  await page.keyboard.press('c');
  await page.keyboard.type('Button');
  await page.keyboard.press('Enter');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('o');
  await page.keyboard.type('Light');
  await page.keyboard.press('Enter');
  await page.getByRole('button', { name: 'Declare Button' }).click();
  await page.getByRole('button', { name: 'Declare Light' }).click();
  const decls = await view.getByRole('textbox', { name: 'Declarations' }).inputValue();
  assert.match(decls, /VAR_INPUT\s+Button : BOOL;\s+END_VAR/);
  assert.match(decls, /VAR_OUTPUT\s+Light : BOOL;\s+END_VAR/);
  await page.getByText('No problems found.').waitFor();
  // The declaration is an edit of the POU: undo takes it back.
  await view.getByRole('button', { name: 'Undo' }).click();
  await page.getByRole('button', { name: 'Declare Light' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});
