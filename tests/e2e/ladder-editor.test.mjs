// The ladder editor (issue 13): a student builds rungs in a new project with the palette,
// keys and the operand box, runs them, undoes and redoes, and finds them after a reload.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { readFile, writeFile, mkdtemp } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
import os from 'node:os';
import { root, useApp, openPage, newLadderProgram, cell } from './setup.mjs';

const app = useApp();
const openApp = (context) => openPage(context, app.server.url);

/** Drags with the mouse (pointer events) from the middle of one element to another's,
 * once the target is in view (the rung grid is drawn at a readable size, issue 34, so a
 * lower row can be below the window's edge: a person scrolls to it first). */
async function drag(page, from, to) {
  await to.scrollIntoViewIfNeeded();
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
  const context = await app.browser.newContext();
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
  // Under it, the rung as Instruction List (issue 18), lit the same way.
  const ilLine = side.getByRole('region', { name: 'IL view' }).locator('.ld-st-line', { hasText: 'ANDN Stop' });
  await ilLine.waitFor();
  assert.match(await ilLine.getAttribute('class'), /\blit\b/);

  // Run it scan by scan: the ladder PROGRAM is chosen under Simulation, each Step is one
  // scan, and after each the lamp and the cells' power tell the same story.
  await page.waitForTimeout(700);
  await page.getByRole('combobox', { name: 'Program to run' }).selectOption('Latch');
  const scans = page.getByLabel('Scan count');
  const step = async () => {
    const before = Number(await scans.textContent());
    await page.getByRole('button', { name: 'Step', exact: true }).click();
    await page.waitForFunction((n) => Number(document.querySelector('[aria-label="Scan count"]').textContent) === n + 1, before);
  };
  const power = async () => Promise.all([[1, 1, 1], [1, 1, 2], [1, 1, 3], [1, 2, 1]].map(([r, row, col]) => cell(view, r, row, col).getAttribute('data-power')));
  await step();
  await page.getByRole('img', { name: 'Motor: OFF', exact: true }).waitFor();
  assert.deepEqual(await power(), ['off', 'off', 'off', 'off'], 'scan 1: nothing pressed');
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await step();
  await page.getByRole('img', { name: 'Motor: ON', exact: true }).waitFor();
  assert.deepEqual(await power(), ['on', 'on', 'on', 'off'], 'scan 2: Start pressed, the Motor contact still open');
  await step();
  assert.deepEqual(await power(), ['on', 'on', 'on', 'on'], 'scan 3: the Motor contact closed behind the coil');
  await page.getByRole('checkbox', { name: 'Start', exact: true }).uncheck();
  await step();
  await page.getByRole('img', { name: 'Motor: ON', exact: true }).waitFor();
  assert.deepEqual(await power(), ['off', 'on', 'on', 'on'], 'scan 4: Start released, the Motor contact holds');
  await page.getByRole('checkbox', { name: 'Stop', exact: true }).check();
  await step();
  await page.getByRole('img', { name: 'Motor: OFF', exact: true }).waitFor();
  assert.deepEqual(await power(), ['off', 'off', 'off', 'on'], 'scan 5: Stop opens the rung; the Motor contact reads the last scan');
  await step();
  assert.deepEqual(await power(), ['off', 'off', 'off', 'off'], 'scan 6: all off');
  // And running freely it stays off until Stop is released and Start pressed again.
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await page.getByRole('checkbox', { name: 'Stop', exact: true }).uncheck();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON', exact: true }).waitFor({ timeout: 5000 });
  await page.getByRole('checkbox', { name: 'Start', exact: true }).uncheck();
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
  const other = await app.browser.newContext();
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

test('a check that marks or clears a problem leaves the rung in place (a drag can still find its cells)', async () => {
  // The check runs after the edit, later on a busy machine: a rung drawn again then
  // replaced the cell a drag had just found (its bounding box null in loaded full runs).
  const context = await app.browser.newContext();
  const { page, errors } = await openApp(context);
  const view = await newLadderProgram(page, 'Kept', 'VAR\n    a : BOOL;\nEND_VAR\n');
  await place(page, view, [1, 1, 1], 'NO contact', 'b');
  await place(page, view, [1, 1, 2], 'Coil', 'a');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: coil a' }).waitFor();
  // The mark of the undeclared b (its title names it).
  const mark = view.locator('rect.ld-diag', { has: page.locator('title', { hasText: /\bb\b/ }) });
  await mark.first().waitFor();
  const grid = await view.getByRole('grid').first().elementHandle();
  const contact = await cell(view, 1, 1, 1).elementHandle();
  // Declaring b clears the problem: its mark goes, the rung's cells stay.
  const decls = view.getByRole('textbox', { name: 'Declarations' });
  await decls.fill('VAR\n    a, b : BOOL;\nEND_VAR\n');
  await decls.press('Tab');
  await mark.first().waitFor({ state: 'detached' });
  assert.equal(await grid.evaluate((e) => e.isConnected), true, 'the rung was drawn again');
  assert.equal(await contact.evaluate((e) => e.isConnected), true, 'the cell was drawn again');
  // Undeclaring it marks the cell again, still without drawing the rung again.
  await decls.fill('VAR\n    a : BOOL;\nEND_VAR\n');
  await decls.press('Tab');
  await mark.first().waitFor();
  assert.equal(await contact.evaluate((e) => e.isConnected), true, 'the cell was drawn again');
  assert.deepEqual(errors, []);
  await context.close();
});

test('keys alone build a rung Start, TON and Lamp, Escape takes a placement back, and the timer delays the lamp', async () => {
  const context = await app.browser.newContext();
  const { page, errors } = await openApp(context);
  const view = await newLadderProgram(page, 'Delay', 'VAR_INPUT\n    Start : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Lamp : BOOL;\nEND_VAR\n');
  // Into the grid as Tab brings a keyboard user there (the selected cell holds the focus).
  await cell(view, 1, 1, 1).focus();
  await page.keyboard.press('c');
  await page.keyboard.type('Start');
  await page.keyboard.press('Enter');
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('o');
  await page.keyboard.press('Escape');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: empty' }).waitFor();
  // `b` opens the block picker; typing picks TON and Enter puts it into the cell. (A person
  // types once the list is open and has the focus.)
  const focused = (label) => page.waitForFunction((l) => document.activeElement?.getAttribute('aria-label') === l, label);
  await page.keyboard.press('b');
  await focused('Block type');
  await page.keyboard.type('TON');
  await page.keyboard.press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: TON T1' }).waitFor();
  const pt = view.getByRole('textbox', { name: 'PT of T1' });
  assert.equal(await pt.inputValue(), 'T#1s', 'a timer starts with a preset');
  // Enter on the block goes to its first pin; Enter there sets it and comes back.
  await page.keyboard.press('Enter');
  await focused('PT of T1');
  await page.keyboard.type('T#2s');
  await page.keyboard.press('Enter');
  await focused('Rung 1, row 1, column 2: TON T1');
  assert.equal(await pt.inputValue(), 'T#2s');
  assert.match(await view.getByRole('textbox', { name: 'Declarations' }).inputValue(), /T1 : TON;/);
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('o');
  await page.keyboard.type('Lamp');
  await page.keyboard.press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil Lamp' }).waitFor();
  // A block typed by name in the picker is the one named, not the first letter's.
  await focused('Rung 1, row 1, column 3: coil Lamp');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('b');
  await focused('Block type');
  await page.keyboard.type('TOF');
  await page.keyboard.press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 3: TOF T2' }).waitFor();
  await page.keyboard.press('Delete');
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 3: empty' }).waitFor();
  await view.getByRole('textbox', { name: 'Comment of rung 1' }).fill('Lamp 2 s after Start');
  await view.getByRole('textbox', { name: 'Comment of rung 1' }).press('Enter');
  // Step the clock (10 ms scans): Lamp comes on after 2 s, not before.
  await page.waitForTimeout(700);
  await page.getByRole('combobox', { name: 'Program to run' }).selectOption('Delay');
  await page.getByRole('checkbox', { name: 'Start', exact: true }).press('Space');
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('199');
  await page.getByRole('button', { name: 'Step N' }).press('Enter');
  await page.waitForFunction(() => document.querySelector('[aria-label="Virtual time"]').textContent === 'T#1s990ms');
  await page.getByRole('img', { name: 'Lamp: OFF', exact: true }).waitFor();
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('2');
  await page.getByRole('button', { name: 'Step N' }).press('Enter');
  await page.getByRole('img', { name: 'Lamp: ON', exact: true }).waitFor();
  assert.equal(await view.getByRole('textbox', { name: 'Comment of rung 1' }).inputValue(), 'Lamp 2 s after Start');
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
  const context = await app.browser.newContext();
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
  const context = await app.browser.newContext();
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

test('the operand box offers the variables of the right type, and the declarations editor marks and reveals its problems', async () => {
  const context = await app.browser.newContext();
  const { page, errors } = await openApp(context);
  const decls = 'VAR_INPUT\n    Start : BOOL;\n    Level : INT;\nEND_VAR\nVAR_OUTPUT\n    Motor : BOOL;\nEND_VAR\nVAR\n    T1 : TON;\nEND_VAR\n';
  const view = await newLadderProgram(page, 'Pick', decls);
  await cell(view, 1, 1, 1).focus();
  await page.keyboard.press('c');
  // The box stays a plain textbox named Operand; its choices are a list beside it.
  await view.getByRole('textbox', { name: 'Operand' }).waitFor();
  const choices = view.getByRole('listbox', { name: 'Operand choices' });
  const offered = () => choices.getByRole('option').evaluateAll((os) => os.map((o) => o.querySelector('.mono').textContent));
  assert.deepEqual(await offered(), ['Start', 'Motor', 'T1.Q'], 'a contact reads any BOOL, not the INT Level');
  await page.keyboard.type('t');
  assert.deepEqual(await offered(), ['T1.Q', 'Start', 'Motor'], 'what starts with the text comes first');
  await page.keyboard.press('ArrowDown');
  await page.keyboard.press('ArrowDown');
  assert.equal(await view.getByRole('textbox', { name: 'Operand' }).getAttribute('aria-activedescendant'), 'ld-choice-1');
  await page.keyboard.press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 1: NO contact Start' }).waitFor();
  // A coil is offered only what a rung may write; a click takes a choice.
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('o');
  assert.deepEqual(await offered(), ['Motor']);
  await choices.getByRole('option', { name: /^Motor/ }).click();
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: coil Motor' }).waitFor();
  // Placing the coil and choosing its operand was one step.
  await view.getByRole('button', { name: 'Undo' }).click();
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: empty' }).waitFor();
  await view.getByRole('button', { name: 'Redo' }).click();

  // A wrong type in the declarations: the problem names its line and column, the editor
  // marks the word and its line, and clicking the problem puts the caret on it.
  const box = view.getByRole('textbox', { name: 'Declarations' });
  await box.fill(decls.replace('T1 : TON;', 'T1 : TONN;'));
  await box.press('Tab');
  const problem = page.getByRole('button', { name: /^Pick, declarations line 9, column 10 / });
  await problem.waitFor();
  await view.getByText('(1 problem)').waitFor();
  assert.equal(await view.locator('.ld-decls .code-field .ed-hl .sq-err').first().textContent(), 'TONN');
  assert.match(await view.locator('.ld-decls .code-field .ed-gutter .ln-err').textContent(), /^9/);
  await problem.click();
  await page.waitForFunction(() => document.activeElement?.getAttribute('aria-label') === 'Declarations');
  const caret = await page.evaluate(() => {
    const el = document.activeElement;
    return { label: el.getAttribute('aria-label'), at: el.selectionStart, word: el.value.slice(el.selectionStart, el.selectionStart + 4) };
  });
  assert.equal(caret.label, 'Declarations');
  assert.equal(caret.word, 'TONN');
  // Fixed, the problem goes; undo brings the wrong text back as one step.
  await box.fill(decls);
  await box.press('Tab');
  await page.getByText('No problems found.').waitFor();
  await view.getByRole('button', { name: 'Undo' }).click();
  await problem.waitFor();
  assert.match(await box.inputValue(), /T1 : TONN;/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('touch and pen drag from the palette as the mouse does, and Ctrl or Alt drag copies an element', async () => {
  const context = await app.browser.newContext({ hasTouch: true });
  const { page, errors } = await openApp(context);
  const view = await newLadderProgram(page, 'Hands', 'VAR\n    a, b : BOOL;\nEND_VAR\n');
  const cdp = await context.newCDPSession(page);
  const centre = async (loc) => {
    const b = await loc.boundingBox();
    return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
  };
  const path = (from, to, steps = 8) => Array.from({ length: steps }, (_, i) => ({
    x: from.x + ((to.x - from.x) * (i + 1)) / steps,
    y: from.y + ((to.y - from.y) * (i + 1)) / steps,
  }));
  const operand = async (text) => {
    const box = view.getByRole('textbox', { name: 'Operand' });
    await box.fill(text);
    await box.press('Enter');
  };
  // A finger drags the NO contact onto rung 1, row 1, column 1.
  let from = await centre(view.getByRole('button', { name: 'NO contact', exact: true }));
  let to = await centre(cell(view, 1, 1, 1));
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [from] });
  for (const p of path(from, to)) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [p] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await operand('a');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 1: NO contact a' }).waitFor();
  // A pen drags a coil onto column 3.
  from = await centre(view.getByRole('button', { name: 'Coil', exact: true }));
  to = await centre(cell(view, 1, 1, 3));
  const pen = (type, p) => cdp.send('Input.dispatchMouseEvent', { type, x: p.x, y: p.y, button: 'left', buttons: type === 'mouseReleased' ? 0 : 1, clickCount: 1, pointerType: 'pen' });
  await pen('mousePressed', from);
  for (const p of path(from, to)) await pen('mouseMoved', p);
  await pen('mouseReleased', to);
  await operand('b');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil b' }).waitFor();
  // Ctrl-drag copies the contact a row down; Alt-drag copies the coil; a plain drag moves.
  await page.keyboard.down('Control');
  await drag(page, cell(view, 1, 1, 1), cell(view, 1, 2, 1));
  await page.keyboard.up('Control');
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 1: NO contact a' }).waitFor();
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 1: NO contact a' }).waitFor();
  await page.keyboard.down('Alt');
  await drag(page, cell(view, 1, 1, 3), cell(view, 1, 2, 3));
  await page.keyboard.up('Alt');
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 3: coil b' }).waitFor();
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 3: coil b' }).waitFor();
  await drag(page, cell(view, 1, 2, 3), cell(view, 1, 2, 4));
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 4: coil b' }).waitFor();
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 3: empty' }).waitFor();
  // A label and a taller block are edits too.
  await view.getByRole('textbox', { name: 'Label of rung 1' }).fill('Top');
  await view.getByRole('textbox', { name: 'Label of rung 1' }).press('Enter');
  await cell(view, 1, 3, 2).click();
  await page.keyboard.press('b');
  await view.getByRole('combobox', { name: 'Block type' }).selectOption('TON');
  await view.getByRole('gridcell', { name: 'Rung 1, row 3, column 2: TON T1' }).waitFor();
  await view.getByRole('spinbutton', { name: 'Height of T1' }).fill('2');
  await view.getByRole('spinbutton', { name: 'Height of T1' }).press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 4, column 2: covered' }).waitFor();
  await view.getByRole('button', { name: 'Undo' }).click();
  await view.getByRole('gridcell', { name: 'Rung 1, row 4, column 2: empty' }).waitFor();
  assert.equal(await view.getByRole('textbox', { name: 'Label of rung 1' }).inputValue(), 'Top');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a function block ladder POU shows the live values of its first instance', async () => {
  const context = await app.browser.newContext();
  const { page, errors } = await openApp(context);
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Seal');
  await page.getByRole('combobox', { name: 'POU kind' }).selectOption('FUNCTION_BLOCK');
  await page.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: 'Ladder diagram Seal' });
  await view.waitFor();
  const box = view.getByRole('textbox', { name: 'Declarations' });
  await box.fill('VAR_INPUT\n    Set1 : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Out1 : BOOL;\nEND_VAR\n');
  await box.press('Tab');
  await cell(view, 1, 1, 1).focus();
  for (const [key, text] of [['c', 'Set1'], ['ArrowRight'], ['o', 'Out1']]) {
    await page.keyboard.press(key);
    if (text) {
      await page.keyboard.type(text);
      await page.keyboard.press('Enter');
    }
  }
  await page.getByRole('button', { name: 'Structured Text source' }).click();
  await page.getByRole('textbox', { name: 'ST source' }).fill(
    'PROGRAM Main\nVAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Lamp : BOOL;\nEND_VAR\nVAR\n    S1 : Seal;\nEND_VAR\nS1(Set1 := Go);\nLamp := S1.Out1;\nEND_PROGRAM\n');
  await page.getByRole('img', { name: 'Lamp: OFF', exact: true }).waitFor();
  await page.getByRole('button', { name: 'Ladder diagram Seal' }).click();
  await view.getByText('Live values of instance S1 in PROGRAM Main.').waitFor();
  const coil = view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: coil Out1' });
  assert.equal(await coil.getAttribute('data-power'), 'off');
  await page.getByRole('checkbox', { name: 'Go', exact: true }).check();
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await page.getByRole('img', { name: 'Lamp: ON', exact: true }).waitFor();
  await view.locator('[role=gridcell][data-power=on]').first().waitFor();
  assert.equal(await coil.getAttribute('data-power'), 'on');
  assert.deepEqual(errors, []);
  await context.close();
});
