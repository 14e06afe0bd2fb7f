// The ladder editor in Firefox or WebKit (ENGINE): a latch rung built by dragging from the
// palette with the pointer, a timer rung built with keys alone, both run scan by scan.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { suite, openApp, withSession, noErrors, shot, step, saved } from './harness.mjs';

const env = suite();

/** Adds a ladder PROGRAM `name` with `declarations` and returns its view. */
async function newLadderProgram(s, name, declarations) {
  await s.role('button', 'New ladder POU').click();
  await s.role('textbox', 'POU name').fill(name);
  await s.role('combobox', 'POU kind').select('PROGRAM');
  await s.role('button', 'Create').click();
  const view = s.role('region', `Ladder diagram ${name}`);
  await view.waitFor();
  const decls = view.role('textbox', 'Declarations');
  await decls.fill(declarations);
  await decls.press('Tab');
  return view;
}

const cell = (view, rung, row, col) => view.role('gridcell', new RegExp(`^Rung ${rung}, row ${row}, column ${col}: `));
const named = (view, label) => view.role('gridcell', label);

/** Drags a palette element onto a cell with the pointer, then types its operand. */
async function place(s, view, [rung, row, col], tool, operand) {
  await s.dragTo(view.role('button', tool), cell(view, rung, row, col));
  if (operand !== undefined) {
    const box = view.role('textbox', 'Operand');
    await box.fill(operand);
    await box.press('Enter');
    await box.waitFor({ state: 'hidden' });
  }
}

const focused = (s, label) => s.waitUntil((l) => document.activeElement?.getAttribute('aria-label') === l, label, { what: `focus on ${label}` });

const LATCH_DECLS = `VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
`;

test('a latch rung dragged from the palette runs scan by scan, and a drag and its undo move a coil', async () => {
  await withSession(openApp(env), async (s) => {
    const view = await newLadderProgram(s, 'Latch', LATCH_DECLS);
    await place(s, view, [1, 1, 1], 'NO contact', 'Start');
    await place(s, view, [1, 1, 2], 'NC contact', 'Stop');
    await place(s, view, [1, 1, 3], 'Coil', 'Motor');
    await place(s, view, [1, 2, 1], 'NO contact', 'Motor');
    await place(s, view, [1, 1, 2], 'Link down');
    await named(view, 'Rung 1, row 1, column 2: NC contact Stop, linked down').waitFor();
    assert.equal(await cell(view, 1, 1, 2).attr('aria-selected'), 'true', 'the cell dropped on is selected');

    // A placed element dragged to another cell; Undo puts it back, keys undo and redo.
    await s.dragTo(cell(view, 1, 1, 3), cell(view, 1, 1, 5));
    await named(view, 'Rung 1, row 1, column 5: coil Motor').waitFor();
    await view.role('button', 'Undo').click();
    await named(view, 'Rung 1, row 1, column 3: coil Motor').waitFor();
    await view.role('button', 'Undo').click();
    await named(view, 'Rung 1, row 1, column 2: NC contact Stop').waitFor();
    await s.press('Control+z');
    await named(view, 'Rung 1, row 2, column 1: empty').waitFor();
    await s.press('Control+Shift+Z');
    await named(view, 'Rung 1, row 2, column 1: NO contact Motor').waitFor();
    await view.role('button', 'Redo').click();
    await named(view, 'Rung 1, row 1, column 2: NC contact Stop, linked down').waitFor();

    // Scan by scan, the lamp and the cells' power tell the same story (once the last edit
    // is checked and saved: that check powers a fresh simulator on).
    await saved(s, /"operand":\s*"Stop"\s*\},\s*"link_down":\s*true/);
    await s.role('combobox', 'Program to run').select('Latch');
    const power = async () => Promise.all([[1, 1], [1, 2], [1, 3], [2, 1]].map(([row, col]) => cell(view, 1, row, col).attr('data-power')));
    await step(s);
    await s.role('img', 'Motor: OFF').waitFor();
    assert.deepEqual(await power(), ['off', 'off', 'off', 'off'], 'scan 1: nothing pressed');
    await s.role('checkbox', 'Start').check();
    await step(s);
    await s.role('img', 'Motor: ON').waitFor();
    assert.deepEqual(await power(), ['on', 'on', 'on', 'off'], 'scan 2: Start pressed');
    await step(s);
    assert.deepEqual(await power(), ['on', 'on', 'on', 'on'], 'scan 3: the Motor contact closed');
    await s.role('checkbox', 'Start').uncheck();
    await step(s);
    assert.deepEqual(await power(), ['off', 'on', 'on', 'on'], 'scan 4: Start released, the Motor contact holds');
    await s.role('img', 'Motor: ON').waitFor();
    await s.role('checkbox', 'Stop').check();
    await step(s);
    await s.role('img', 'Motor: OFF').waitFor();
    // Running freely: Start latches the motor again and Stop stops it.
    await s.role('button', 'Run').click();
    await s.role('checkbox', 'Stop').uncheck();
    await s.role('checkbox', 'Start').check();
    await s.role('img', 'Motor: ON').waitFor();
    await s.role('checkbox', 'Start').uncheck();
    await s.waitUntil(() => document.querySelector('[aria-label^="Rung 1, row 2, column 1:"]')?.getAttribute('data-power') === 'on', null, { what: 'the holding contact powered' });
    await s.screenshot(shot(env, 'ladder'));
    await s.role('checkbox', 'Stop').check();
    await s.role('img', 'Motor: OFF').waitFor();
    await s.role('button', 'Pause').click();
    await noErrors(s);
  });
});

test('keys alone build Start, TON and Lamp; the timer delays the lamp by its preset', async () => {
  await withSession(openApp(env), async (s) => {
    const view = await newLadderProgram(s, 'Delay', 'VAR_INPUT\n    Start : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Lamp : BOOL;\nEND_VAR\n');
    await cell(view, 1, 1, 1).focus();
    await s.press('c');
    await focused(s, 'Operand');
    await s.type('Start');
    await s.press('Enter');
    await named(view, 'Rung 1, row 1, column 1: NO contact Start').waitFor();
    await focused(s, 'Rung 1, row 1, column 1: NO contact Start');
    await s.press('ArrowRight');
    await s.press('o');
    await focused(s, 'Operand');
    await s.press('Escape');
    await named(view, 'Rung 1, row 1, column 2: empty').waitFor();
    await focused(s, 'Rung 1, row 1, column 2: empty');
    await s.press('b');
    await focused(s, 'Block type');
    await s.type('TON');
    await s.press('Enter');
    await named(view, 'Rung 1, row 1, column 2: TON T1').waitFor();
    assert.equal(await view.role('textbox', 'PT of T1').value(), 'T#1s', 'a timer starts with a preset');
    await focused(s, 'Rung 1, row 1, column 2: TON T1');
    await s.press('Enter');
    await focused(s, 'PT of T1');
    await s.press('Control+a');
    await s.type('T#2s');
    await s.press('Enter');
    await focused(s, 'Rung 1, row 1, column 2: TON T1');
    assert.equal(await view.role('textbox', 'PT of T1').value(), 'T#2s');
    assert.match(await view.role('textbox', 'Declarations').value(), /T1 : TON;/);
    await s.press('ArrowRight');
    await s.press('o');
    await focused(s, 'Operand');
    await s.type('Lamp');
    await s.press('Enter');
    await named(view, 'Rung 1, row 1, column 3: coil Lamp').waitFor();

    // 10 ms scans: the lamp comes on 2 s after Start, not before.
    await saved(s, /"type":\s*"Coil"[^}]*"operand":\s*"Lamp"/);
    await s.role('combobox', 'Program to run').select('Delay');
    await s.role('checkbox', 'Start').press('Space');
    await s.waitUntil(() => [...document.querySelectorAll('input[type=checkbox]')].some((c) => c.checked && c.closest('label')?.textContent.trim() === 'Start'), null, { what: 'Start switched on by Space' });
    await s.role('spinbutton', 'Scans per step').fill('199');
    await s.role('spinbutton', 'Scans per step').press('Tab');
    await s.role('button', 'Step N').press('Enter');
    await s.role('status', 'Virtual time').waitForText('T#1s990ms');
    await s.role('img', 'Lamp: OFF').waitFor();
    await s.role('spinbutton', 'Scans per step').fill('2');
    await s.role('spinbutton', 'Scans per step').press('Tab');
    await s.role('button', 'Step N').press('Enter');
    await s.role('img', 'Lamp: ON').waitFor();
    await s.screenshot(shot(env, 'ladder-keys'));
    await noErrors(s);
  });
});
