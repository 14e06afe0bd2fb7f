// The editors on a phone (issue 34): at 390 × 844 with touch, a student builds the
// start/stop latch in the ladder editor by tapping a cell then a tool in the palette (a
// bottom sheet along the screen's edge) and by dragging tools with a finger, switches to
// the Simulation tab, taps Run and Start and sees the motor on without scrolling; two
// fingers zoom the rungs. Another draws a two-place Petri net with taps, pinches it and
// runs it. Screenshots: docs/screenshots/phone-ladder.png and phone-petri.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { useApp, openPage, root, cell, centre, operand, scrollsSideways } from './setup.mjs';

const app = useApp();
const shots = path.join(root, 'docs/screenshots');
const PHONE = { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true };

/** Scrolls `loc` to the middle of the screen, as a person brings what they touch into view. */
const bringIntoView = (loc) => loc.evaluate((el) => el.scrollIntoView({ block: 'center', inline: 'nearest' }));

/** One finger from `a` to `b` (client pixels). */
async function fingerDrag(cdp, a, b) {
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ ...a, id: 1 }] });
  for (let i = 1; i <= 8; i++) {
    const p = { x: a.x + ((b.x - a.x) * i) / 8, y: a.y + ((b.y - a.y) * i) / 8, id: 1 };
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [p] });
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

/** Two fingers put down `gap` px apart around `at`, moved apart to `spread` px. */
async function pinch(cdp, at, gap, spread) {
  const fingers = (d) => [{ x: at.x - d / 2, y: at.y, id: 1 }, { x: at.x + d / 2, y: at.y, id: 2 }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [fingers(gap)[0]] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: fingers(gap) });
  for (let i = 1; i <= 8; i++) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: fingers(gap + ((spread - gap) * i) / 8) });
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

/** Whether `locator` is on the screen as it is now (no scrolling). */
const onScreen = async (page, locator) => {
  const b = await locator.boundingBox();
  const { height } = page.viewportSize();
  return Boolean(b) && b.y >= 0 && b.y + b.height <= height;
};

/** A new project with a new POU of `kind` named `name` (through Menu, as a phone shows it). */
async function newPou(page, kind, name) {
  await page.getByRole('button', { name: 'Menu', exact: true }).tap();
  await page.getByRole('button', { name: 'New project' }).tap();
  await page.getByRole('button', { name: `New ${kind} POU` }).tap();
  await page.getByRole('textbox', { name: 'POU name' }).fill(name);
  if (kind === 'ladder') await page.getByRole('combobox', { name: 'POU kind' }).selectOption('PROGRAM');
  await page.getByRole('button', { name: 'Create' }).tap();
}

async function declare(view, text) {
  const decls = view.getByRole('textbox', { name: 'Declarations' });
  if (!(await decls.isVisible())) await view.getByText('Declarations', { exact: true }).first().tap();
  await decls.fill(text);
  await decls.press('Tab');
}

/** Runs the program `name` on the Simulation tab: Run, then Start pressed and released. */
async function runOnSimulationTab(page, name) {
  await page.getByRole('tab', { name: 'Simulation', exact: true }).tap();
  await page.getByRole('combobox', { name: 'Program to run' }).selectOption(name);
  await page.getByRole('button', { name: 'Run', exact: true }).tap();
}

test('on a phone: the latch built in the ladder editor by tap and by touch drag runs, and two fingers zoom the rungs', async () => {
  const context = await app.browser.newContext(PHONE);
  const { page, errors } = await openPage(context, app.server.url);
  const cdp = await context.newCDPSession(page);
  await newPou(page, 'ladder', 'Latch');
  const view = page.getByRole('region', { name: 'Ladder diagram Latch' });
  await view.waitFor();
  await declare(view, 'VAR_INPUT\n    Start : BOOL;\n    Stop : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Motor : BOOL;\nEND_VAR\n');

  // The palette is a bottom sheet: along the screen's bottom edge, one row of tools a
  // finger hits, scrolled sideways inside itself.
  const palette = view.getByRole('toolbar', { name: 'Palette' });
  const sheet = await palette.boundingBox();
  assert.ok(Math.abs(sheet.y + sheet.height - 844) < 1 && sheet.x === 0 && Math.round(sheet.width) === 390, `the palette is the bottom sheet: ${JSON.stringify(sheet)}`);
  const tool = (name) => palette.getByRole('button', { name, exact: true });
  // The sheet scrolls sideways: a tool is brought into it before a finger drags it.
  const toolAt = async (name) => {
    await tool(name).evaluate((el) => el.scrollIntoView({ block: 'nearest', inline: 'nearest' }));
    return centre(tool(name));
  };
  const noContact = await tool('NO contact').boundingBox();
  assert.ok(noContact.width >= 44 && noContact.height >= 44, `a tool is ${noContact.width} × ${noContact.height} px`);
  assert.equal(await scrollsSideways(page), false, 'the palette scrolls inside itself, not the page');

  // Tap a cell, then a tool: the element goes there and asks for its operand.
  await cell(view, 1, 1, 1).tap();
  await tool('NO contact').tap();
  await operand(view, 'Start');
  // A tool dragged with a finger onto a cell.
  await bringIntoView(cell(view, 1, 1, 2));
  await fingerDrag(cdp, await toolAt('NC contact'), await centre(cell(view, 1, 1, 2)));
  await operand(view, 'Stop');
  await cell(view, 1, 1, 3).tap();
  await tool('Coil').tap();
  await operand(view, 'Motor');
  await bringIntoView(cell(view, 1, 2, 1));
  await fingerDrag(cdp, await toolAt('NO contact'), await centre(cell(view, 1, 2, 1)));
  await operand(view, 'Motor');
  await cell(view, 1, 1, 2).tap();
  await tool('Link down').tap();
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop, linked down' }).waitFor();
  await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 1: NO contact Motor' }).waitFor();
  assert.equal(await scrollsSideways(page), false, 'the rungs scroll in their own box');
  await page.screenshot({ path: path.join(shots, 'phone-ladder.png') });

  // Two fingers spread on the rungs zoom them in (the zoom is shown beside its buttons).
  const zoomShown = view.locator('.ld-zoom-value');
  const before = await zoomShown.textContent();
  await pinch(cdp, await centre(cell(view, 1, 1, 1)), 60, 110);
  await page.waitForFunction((b) => document.querySelector('.ld-zoom-value')?.textContent !== b, before);
  assert.ok(parseInt(await zoomShown.textContent(), 10) > parseInt(before, 10), `${before} → ${await zoomShown.textContent()}`);
  // The pinch changed nothing in the rung.
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 1: NO contact Start' }).waitFor();
  assert.equal(await view.getByRole('button', { name: 'Redo' }).isDisabled(), true);

  // The Simulation tab: Run, Start and the motor's lamp on one screen.
  await page.waitForTimeout(700);
  await runOnSimulationTab(page, 'Latch');
  const start = page.getByRole('checkbox', { name: 'Start', exact: true });
  await start.tap();
  const motor = page.getByRole('img', { name: 'Motor: ON', exact: true });
  await motor.waitFor({ timeout: 5000 });
  await start.tap();
  await page.waitForTimeout(200);
  assert.equal(await motor.count(), 1, 'the latch holds the motor on');
  for (const [what, loc] of [['Run', page.getByRole('button', { name: 'Pause', exact: true })], ['Start', start], ['the Motor lamp', motor]]) {
    assert.ok(await onScreen(page, loc), `${what} is on the first screen`);
  }
  assert.equal(await page.evaluate(() => window.scrollY), 0, 'nothing was scrolled');
  assert.deepEqual(errors, []);
  await context.close();
});

test('on a phone: a two-place Petri net drawn with taps runs, and two fingers zoom the net', async () => {
  const context = await app.browser.newContext(PHONE);
  const { page, errors } = await openPage(context, app.server.url);
  const cdp = await context.newCDPSession(page);
  await newPou(page, 'Petri net', 'Blink');
  const view = page.getByRole('region', { name: 'Petri net Blink' });
  await view.waitFor();
  await declare(view, 'VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Busy : BOOL;\nEND_VAR\n');
  const canvas = view.getByRole('group', { name: 'Net canvas' });
  const tool = (name) => view.getByRole('button', { name, exact: true });
  const place = (id) => view.locator(`.pn-place[data-id="${id}"]`);
  const transition = (id) => view.locator(`.pn-transition[data-id="${id}"]`);
  const at = async (x, y) => {
    const box = await canvas.boundingBox();
    const [vx, vy, vw, vh] = (await canvas.getAttribute('viewBox')).split(' ').map(Number);
    return { x: box.x + ((x - vx) * box.width) / vw, y: box.y + ((y - vy) * box.height) / vh };
  };
  // A finger taps the net at (x, y) in its own units, the canvas brought into view first.
  const tapAt = async (x, y) => {
    await bringIntoView(canvas);
    const p = await at(x, y);
    await page.touchscreen.tap(p.x, p.y);
  };

  // Tap a tool, then the canvas: two places and two transitions.
  await tool('Place').tap();
  await tapAt(100, 100);
  await place('P1').waitFor();
  await tapAt(100, 260);
  await place('P2').waitFor();
  await tool('Transition').tap();
  await tapAt(40, 180);
  await transition('T1').waitFor();
  await tapAt(160, 180);
  await transition('T2').waitFor();
  // Arcs: tap one element, then the other.
  await tool('Arc').tap();
  for (const [a, b] of [[place('P1'), transition('T2')], [transition('T2'), place('P2')], [place('P2'), transition('T1')], [transition('T1'), place('P1')]]) {
    const arcs = await view.locator('.pn-arc').count();
    await bringIntoView(canvas);
    const from = await centre(a);
    const to = await centre(b);
    await page.touchscreen.tap(from.x, from.y);
    await page.touchscreen.tap(to.x, to.y);
    await view.locator('.pn-arc').nth(arcs).waitFor({ state: 'attached' });
  }
  await tool('Select').tap();
  await bringIntoView(canvas);
  const p1 = await centre(place('P1'));
  await page.touchscreen.tap(p1.x, p1.y);
  const props = view.getByRole('group', { name: 'Properties' });
  await props.getByRole('textbox', { name: 'Initial tokens' }).fill('1');
  await props.getByRole('textbox', { name: 'Initial tokens' }).press('Tab');
  await place('P1').and(page.locator('[data-tokens="1"]')).waitFor();
  await bringIntoView(canvas);
  const p2 = await centre(place('P2'));
  await page.touchscreen.tap(p2.x, p2.y);
  await props.getByRole('textbox', { name: 'Actions' }).fill('Busy := TRUE;');
  await props.getByRole('textbox', { name: 'Actions' }).press('Tab');
  // Go moves the token to P2, releasing Go moves it back.
  for (const [id, guard] of [['T2', 'Go'], ['T1', 'NOT Go']]) {
    await bringIntoView(canvas);
    const t = await centre(transition(id));
    await page.touchscreen.tap(t.x, t.y);
    await props.getByRole('textbox', { name: 'Guard' }).fill(guard);
    await props.getByRole('textbox', { name: 'Guard' }).press('Tab');
  }
  // On a phone the code is below the net.
  await view.locator('.pn-code').filter({ hasText: 'CASE' }).waitFor();
  const net = await view.locator('.pn-net').boundingBox();
  const code = await view.locator('.pn-code').boundingBox();
  assert.ok(code.y >= net.y + net.height, 'the code is below the net');
  assert.equal(await scrollsSideways(page), false);

  // Two fingers spread on the net zoom it in; the net is unchanged.
  const width = Number(await canvas.getAttribute('width'));
  await bringIntoView(canvas);
  await pinch(cdp, await at(100, 180), 50, 100);
  await page.waitForFunction((w) => Number(document.querySelector('.pn-svg').getAttribute('width')) > w * 1.3, width);
  assert.equal(await view.locator('.pn-place').count(), 2, 'the pinch placed nothing');
  assert.equal(await view.locator('.pn-arc').count(), 4);
  // The net checks clean once its guards are typed (the check waits for typing to stop).
  await page.getByText('No problems found.').waitFor({ state: 'attached' });
  assert.equal(await view.locator('.has-err').count(), 0);
  await page.screenshot({ path: path.join(shots, 'phone-petri.png') });

  // It runs: Go moves the token from P1 to P2, whose action lights Busy; the token stays
  // while Go is held.
  await page.waitForTimeout(700);
  await runOnSimulationTab(page, 'Blink');
  const go = page.getByRole('checkbox', { name: 'Go', exact: true });
  await go.tap();
  const busy = page.getByRole('img', { name: 'Busy: ON', exact: true });
  await busy.waitFor({ timeout: 5000 });
  assert.ok(await onScreen(page, busy), 'the Busy lamp is on the first screen');
  assert.deepEqual(errors, []);
  await context.close();
});
