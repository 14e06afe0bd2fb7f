// A phone (issue 34): at 390 × 844 with touch, a tab bar shows the program or the
// simulation (and the exercise while one is open), the header's actions fold into `Menu`,
// the page never scrolls sideways and what a finger taps is at least 44 × 44 px. A student
// types the start/stop latch, taps `Simulation`, Run and Start, and sees the motor on
// without scrolling. Screenshots: docs/screenshots/phone-program.png, phone-simulation.png
// and phone-dark.png. On a laptop the exercise's task folds to its summary line and the
// timeline is tall enough to read.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { mkdirSync } from 'node:fs';
import { useApp, openPage, root, scrollsSideways } from './setup.mjs';

const app = useApp();
const shots = path.join(root, 'docs/screenshots');
const PHONE = { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true };

const LATCH = `PROGRAM Latch
VAR_INPUT
    Start : BOOL; (* start button *)
    Stop : BOOL;  (* stop button *)
END_VAR
VAR_OUTPUT
    Motor : BOOL; (* motor contactor *)
END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
`;

/** The element's box, for its size and whether it is on the first screen. */
const box = async (locator) => {
  const b = await locator.boundingBox();
  assert.ok(b, 'it is shown');
  return b;
};

async function assertTarget(locator, what) {
  const b = await box(locator);
  assert.ok(b.width >= 44 && b.height >= 44, `${what} is ${b.width.toFixed(0)} × ${b.height.toFixed(0)} px, at least 44 × 44`);
}

/** Types the latch into a new project (through Menu, as a phone shows it). */
async function newLatch(page) {
  const menu = page.getByRole('button', { name: 'Menu', exact: true });
  await menu.tap();
  await page.getByRole('button', { name: 'New project' }).tap();
  await page.getByRole('textbox', { name: 'ST source' }).fill(LATCH);
  // The check is debounced; the I/O panel appears once the program compiles.
  await page.waitForTimeout(700);
}

test('on a phone: tabs, Menu, no sideways scroll, and the latch runs with Run, Start and Motor on one screen', async () => {
  mkdirSync(shots, { recursive: true });
  const context = await app.browser.newContext({ ...PHONE, colorScheme: 'light' });
  const { page, errors } = await openPage(context, app.server.url);

  // The tab bar, by role and name; Program is chosen first.
  const tablist = page.getByRole('tablist');
  await tablist.waitFor();
  const program = tablist.getByRole('tab', { name: 'Program', exact: true });
  const simulation = tablist.getByRole('tab', { name: 'Simulation', exact: true });
  assert.equal(await tablist.getByRole('tab').count(), 2, 'no Exercise tab while no exercise is open');
  assert.equal(await program.getAttribute('aria-selected'), 'true');
  assert.equal(await simulation.getAttribute('aria-selected'), 'false');
  for (const tab of [program, simulation]) {
    const controls = await tab.getAttribute('aria-controls');
    assert.equal(await page.locator(`#${controls}`).count(), 1, `${controls} is the pane the tab shows`);
  }
  assert.equal(await page.getByRole('button', { name: 'Run', exact: true }).isVisible(), false, 'the simulation waits behind its tab');
  assert.equal(await scrollsSideways(page), false, 'no sideways scroll on the Program tab');

  // Menu: the header's actions in a panel; Esc closes it and gives the focus back.
  const menu = page.getByRole('button', { name: 'Menu', exact: true });
  assert.equal(await page.getByRole('button', { name: 'New project' }).isVisible(), false, 'the actions are folded');
  assert.equal(await menu.getAttribute('aria-expanded'), 'false');
  await assertTarget(menu, 'Menu');
  await menu.tap();
  assert.equal(await menu.getAttribute('aria-expanded'), 'true');
  for (const name of ['Exercises', 'Help', 'New project', 'Rename', 'Duplicate', 'Delete', 'Export', 'Import', 'Share']) {
    const action = page.getByRole('button', { name, exact: true });
    assert.ok(await action.isVisible(), `${name} is in the menu`);
    await assertTarget(action, `the menu's ${name}`);
  }
  for (const name of ['Open project', 'Open example', 'Theme']) {
    assert.ok(await page.getByRole('combobox', { name }).isVisible(), `${name} is in the menu`);
  }
  assert.equal(await scrollsSideways(page), false, 'no sideways scroll with the menu open');
  await page.waitForFunction(() => document.activeElement?.closest('#header-actions'));
  await page.keyboard.press('Escape');
  assert.equal(await menu.getAttribute('aria-expanded'), 'false');
  assert.equal(await page.getByRole('button', { name: 'New project' }).isVisible(), false);
  assert.ok(await menu.evaluate((e) => e === document.activeElement), 'the focus is back on Menu');

  await newLatch(page);
  assert.equal(await menu.getAttribute('aria-expanded'), 'false', 'an action taken closes the menu');
  assert.match(await page.getByRole('textbox', { name: 'ST source' }).inputValue(), /Motor := \(Start OR Motor\) AND NOT Stop;/);
  assert.equal(await scrollsSideways(page), false, 'long lines scroll inside the editor, not the page');
  await assertTarget(program, 'the Program tab');
  await assertTarget(simulation, 'the Simulation tab');
  await page.screenshot({ path: path.join(shots, 'phone-program.png') });

  // Simulation: Run, the inputs and the lamps on the first screen, no scrolling.
  await simulation.tap();
  assert.equal(await simulation.getAttribute('aria-selected'), 'true');
  assert.equal(await program.getAttribute('aria-selected'), 'false');
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).isVisible(), false, 'the editor waits behind its tab');
  const run = page.getByRole('button', { name: 'Run', exact: true });
  const start = page.getByRole('checkbox', { name: 'Start', exact: true });
  const lamp = page.getByRole('img', { name: /^Motor: (ON|OFF)$/ });
  await lamp.waitFor();
  assert.equal(await page.evaluate(() => window.scrollY), 0);
  for (const [what, l] of [['Run', run], ['Start', start], ['the Motor lamp', lamp]]) {
    const b = await box(l);
    assert.ok(b.y >= 0 && b.y + b.height <= 844, `${what} is on the first screen (y ${b.y.toFixed(0)})`);
  }
  assert.equal(await scrollsSideways(page), false, 'no sideways scroll on the Simulation tab');

  // What a finger taps.
  await assertTarget(run, 'Run');
  await assertTarget(page.getByRole('button', { name: 'Step', exact: true }), 'Step');
  await assertTarget(page.locator('label.switch').filter({ has: start }), "Start's switch");
  await assertTarget(page.locator('label.push-mode').filter({ has: page.getByRole('checkbox', { name: 'Start: hold (push button)' }) }), "Start's push-button box");

  await run.tap();
  await page.getByRole('slider', { name: 'Recorded scan' }).waitFor();
  await start.tap();
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor({ timeout: 5000 });
  await start.tap();
  await page.waitForTimeout(200);
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor({ timeout: 5000 });
  assert.equal(await page.evaluate(() => window.scrollY), 0, 'nothing scrolled');
  await page.waitForTimeout(300);
  await page.screenshot({ path: path.join(shots, 'phone-simulation.png') });

  // Back to the program: the code is as typed.
  await program.tap();
  assert.match(await page.getByRole('textbox', { name: 'ST source' }).inputValue(), /Motor := \(Start OR Motor\) AND NOT Stop;/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('on a phone: an exercise opens in its own tab; the arrow keys move among the tabs', async () => {
  const context = await app.browser.newContext({ ...PHONE, colorScheme: 'light' });
  const { page, errors } = await openPage(context, app.server.url);
  await page.getByRole('button', { name: 'Menu', exact: true }).tap();
  await page.getByRole('button', { name: 'Exercises', exact: true }).tap();
  await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: 'Start/stop motor latch' }).tap();
  const exercise = page.getByRole('tab', { name: 'Exercise', exact: true });
  await exercise.waitFor();
  assert.equal(await exercise.getAttribute('aria-selected'), 'true', 'the task shows first');
  assert.equal(await page.locator(`#${await exercise.getAttribute('aria-controls')}`).count(), 1);
  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  assert.ok(await panel.getByRole('table', { name: 'Interface' }).isVisible(), 'the task is unfolded in its tab');
  assert.equal(await scrollsSideways(page), false, 'no sideways scroll on the Exercise tab');
  await assertTarget(exercise, 'the Exercise tab');

  await exercise.focus();
  await page.keyboard.press('Home');
  const program = page.getByRole('tab', { name: 'Program', exact: true });
  assert.equal(await program.getAttribute('aria-selected'), 'true');
  assert.ok(await program.evaluate((e) => e === document.activeElement));
  assert.ok(await page.getByRole('textbox', { name: 'ST source' }).isVisible());
  assert.equal(await panel.isVisible(), false);
  await page.keyboard.press('ArrowRight');
  assert.equal(await page.getByRole('tab', { name: 'Simulation', exact: true }).getAttribute('aria-selected'), 'true');
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowLeft');
  assert.equal(await exercise.getAttribute('aria-selected'), 'true', 'ArrowLeft wraps to the last tab');
  assert.deepEqual(errors, []);
  await context.close();
});

test('on a phone in the dark: the simulation tab is readable', async () => {
  const context = await app.browser.newContext({ ...PHONE, colorScheme: 'dark' });
  const { page, errors } = await openPage(context, app.server.url);
  await newLatch(page);
  await page.getByRole('tab', { name: 'Simulation', exact: true }).tap();
  await page.getByRole('button', { name: 'Run', exact: true }).tap();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).tap();
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor({ timeout: 5000 });
  assert.equal(await page.evaluate(() => getComputedStyle(document.documentElement).colorScheme), 'dark');
  assert.equal(await scrollsSideways(page), false);
  await page.waitForTimeout(300);
  await page.screenshot({ path: path.join(shots, 'phone-dark.png') });
  assert.deepEqual(errors, []);
  await context.close();
});

test('on a laptop: the exercise task folds to its summary line, the editor is on the first screen, the timeline is readable', async () => {
  const context = await app.browser.newContext({ viewport: { width: 1280, height: 800 } });
  const { page, errors } = await openPage(context, app.server.url);
  assert.equal(await page.getByRole('tablist').isVisible(), false, 'no tab bar on a wide screen');
  assert.equal(await page.getByRole('button', { name: 'Menu', exact: true }).isVisible(), false, 'no Menu button');

  // The empty timeline: at least 120 px tall, its tick labels at least 11 px.
  const chart = page.getByRole('img', { name: 'Timeline chart' });
  await chart.waitFor();
  await page.waitForFunction(() => document.querySelector('svg.timeline-chart')?.getBoundingClientRect().height >= 120);
  const ticks = await chart.evaluate((svg) => {
    const k = svg.getBoundingClientRect().width / svg.viewBox.baseVal.width;
    return [...svg.querySelectorAll('.tl-tick')].map((t) => parseFloat(getComputedStyle(t).fontSize) * k);
  });
  assert.ok(ticks.length > 0, 'the time axis has ticks');
  assert.ok(ticks.every((px) => px >= 10.95), `tick labels are ${ticks.map((p) => p.toFixed(1)).join(', ')} px`);

  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: 'Start/stop motor latch' }).click();
  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  const task = panel.locator('details.exercise-task');
  assert.equal(await task.evaluate((d) => d.open), false, 'the task is folded');
  assert.ok(await panel.getByText('Task', { exact: true }).isVisible(), 'its summary line is shown');
  const editor = await box(page.getByRole('textbox', { name: 'ST source' }));
  assert.ok(editor.y < 800 - 100, `the editor starts on the first screen (y ${editor.y.toFixed(0)})`);
  // Unfolded on demand.
  await panel.getByText('Task', { exact: true }).click();
  assert.ok(await panel.getByRole('table', { name: 'Interface' }).isVisible());
  assert.deepEqual(errors, []);
  await context.close();
});
