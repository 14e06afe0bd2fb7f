// Back in time and "why is this on?" (issue 36): the simulator records its history, the
// page steps back through it (`Step back`, `Step`, the `Recorded scan` slider) and shows
// the recorded scan everywhere, with the banner `Showing scan N of M — Return to now`;
// `Why?` buttons open the `Explanation` region for the scan shown.
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

const LATCH = JSON.stringify({
  schema: 1,
  name: 'Latch',
  source: `PROGRAM Main
VAR_INPUT Start : BOOL; Stop : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
`,
  settings: { cycle_ms: 10, traced: ['Motor', 'Start'], breakpoints: [] },
});

async function openPage() {
  const context = await browser.newContext({ viewport: { width: 1280, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  return { context, page, errors };
}

async function openExample(title) {
  const opened = await openPage();
  await opened.page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: title });
  return opened;
}

/** The table's value of a variable. */
function valueOf(page, name) {
  const vars = page.getByRole('region', { name: 'Variables' });
  return vars.getByRole('row').filter({ has: page.getByRole('rowheader', { name, exact: true }) }).getByRole('cell').nth(3);
}

async function stepN(page, n) {
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill(String(n));
  await page.getByRole('button', { name: 'Step N' }).click();
}

/**
 * Runs the latch through the story with the I/O panel's switches, one Step at a
 * time: scans 1–2 idle, Start on for scan 3 (Motor turns on), off from scan 4, Stop on for
 * scan 6 (Motor turns off), off for scan 7.
 */
async function pressStartAndStop(page) {
  const io = page.getByRole('region', { name: 'Inputs and outputs' });
  const step = page.getByRole('button', { name: 'Step', exact: true });
  const start = io.getByRole('checkbox', { name: 'Start', exact: true });
  const stop = io.getByRole('checkbox', { name: 'Stop', exact: true });
  await step.click();
  await step.click();
  await start.check();
  await step.click();
  await start.uncheck();
  await step.click();
  await step.click();
  await stop.check();
  await step.click();
  await stop.uncheck();
  await step.click();
  await page.getByRole('status').filter({ hasText: 'Paused' }).waitFor();
  assert.equal(await page.getByLabel('Scan count').textContent(), '7');
}

test('ST latch: step back to the scan Motor turned on, ask why, follow it, jump with the slider, and start a new future', async () => {
  const { context, page, errors } = await openPage();
  await page.getByLabel('Import project file').setInputFiles({
    name: 'latch.plcproj.json', mimeType: 'application/json', buffer: Buffer.from(LATCH),
  });
  await page.getByRole('region', { name: 'Variables' }).getByRole('rowheader', { name: 'Motor', exact: true }).waitFor();
  // The latch runs (recording is on while it runs), then is reset for the story.
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await page.getByRole('status').filter({ hasText: 'Running' }).waitFor();
  await page.getByRole('button', { name: 'Reset', exact: true }).click();
  await pressStartAndStop(page);
  assert.equal((await valueOf(page, 'Motor').textContent()).trim(), 'FALSE');

  // Paused: Step back four times, to scan 3, where Motor turned on.
  const back = page.getByRole('button', { name: 'Step back' });
  for (let k = 0; k < 4; k += 1) await back.click();
  const banner = page.getByRole('status').filter({ hasText: 'Showing scan' });
  assert.equal((await banner.textContent()).replace(/\s+/g, ' ').trim(), 'Showing scan 3 of 7 — Return to now');
  assert.equal((await valueOf(page, 'Motor').textContent()).trim(), 'TRUE');
  assert.equal((await valueOf(page, 'Start').textContent()).trim(), 'TRUE');
  const io = page.getByRole('region', { name: 'Inputs and outputs' });
  await io.getByRole('img', { name: 'Motor: ON' }).waitFor();
  assert.equal(await io.getByRole('checkbox', { name: 'Start', exact: true }).isChecked(), true);
  assert.equal(await page.getByLabel('Scan count').textContent(), '3');
  assert.equal(await page.getByRole('slider', { name: 'Recorded scan' }).inputValue(), '3');

  // Why is Motor TRUE? The statement on line 4, with Start TRUE.
  await page.getByRole('region', { name: 'Variables' }).getByRole('button', { name: 'Why is Motor TRUE?' }).click();
  const why = page.getByRole('region', { name: 'Explanation' });
  await why.getByText('Motor is TRUE at scan 3').waitFor();
  const text = async () => (await why.textContent()).replace(/\s+/g, ' ');
  assert.match(await text(), /Written by Main line 4: Motor := \(Start OR Motor\) AND NOT Stop/);
  assert.match(await text(), /Start TRUE \(since scan 3\)/);
  assert.match(await text(), /Stop FALSE/);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/why-st-latch.png') });
  // Its link shows the line; the editor's status line then offers the line's own Why.
  await why.getByRole('button', { name: 'Go to line 4' }).click();
  await page.locator('.ed-status').getByRole('button', { name: 'Why is Motor TRUE?' }).waitFor();
  assert.equal(await page.locator('.ed-status').getByText('Ln 4, Col 1').count(), 1);

  // A later scan: the explanation follows the scan shown; Motor holds itself (seal-in).
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await why.getByText('Motor is TRUE at scan 4').waitFor();
  assert.match(await text(), /Start FALSE \(since scan 4\)/);
  assert.match(await text(), /Motor TRUE \(since scan 3\)/);
  // Following the operand Motor goes back to the scan it got its value: scan 3.
  await why.getByRole('button', { name: 'Why is Motor TRUE?' }).click();
  await why.getByText('Motor is TRUE at scan 3').waitFor();
  assert.match(await banner.textContent(), /Showing scan 3 of 7/);
  // And Start there is the input, held from outside.
  await why.getByRole('button', { name: 'Why is Start TRUE?' }).click();
  await why.getByText('Start is TRUE at scan 3').waitFor();

  // The slider jumps to scan 6, where Stop turned Motor off.
  await page.getByRole('slider', { name: 'Recorded scan' }).fill('6');
  await banner.filter({ hasText: 'Showing scan 6 of 7' }).waitFor();
  assert.equal((await valueOf(page, 'Motor').textContent()).trim(), 'FALSE');
  await page.getByRole('region', { name: 'Variables' }).getByRole('button', { name: 'Why is Motor FALSE?' }).click();
  await why.getByText('Motor is FALSE at scan 6').waitFor();
  assert.match(await text(), /Stop TRUE \(since scan 6\)/);
  // When did Motor change? Before scan 6: scan 3; jump there.
  await why.getByRole('button', { name: 'When did Motor change?' }).click();
  await why.getByRole('button', { name: 'Go to scan 3' }).click();
  await banner.filter({ hasText: 'Showing scan 3 of 7' }).waitFor();

  // Return to now.
  await page.getByRole('button', { name: 'Return to now' }).click();
  await banner.waitFor({ state: 'detached' });
  assert.equal(await page.getByLabel('Scan count').textContent(), '7');

  // Changing an input in the past starts a new future from there.
  for (let k = 0; k < 3; k += 1) await back.click();
  await banner.filter({ hasText: 'Showing scan 4 of 7' }).waitFor();
  await io.getByRole('checkbox', { name: 'Stop', exact: true }).check();
  await banner.waitFor({ state: 'detached' });
  await page.getByRole('alert').filter({ hasText: 'Continued from scan 4: scans 5 to 7 were dropped.' }).waitFor();
  assert.equal(await page.getByLabel('Scan count').textContent(), '4');
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  assert.equal(await page.getByLabel('Scan count').textContent(), '5');
  assert.equal((await valueOf(page, 'Motor').textContent()).trim(), 'FALSE');
  assert.deepEqual(errors, []);
  await context.close();
});

test('ladder latch: the coil is powered at the scan Motor turned on, rung 1 explains it, and later the seal-in contact holds it', async () => {
  const { context, page, errors } = await openExample('Ladder latch');
  const cell = (at) => page.locator(`.ld-cell[data-at="${at}"]`);
  await cell('0-0-2').waitFor();
  await pressStartAndStop(page);
  const back = page.getByRole('button', { name: 'Step back' });
  for (let k = 0; k < 4; k += 1) await back.click();
  await page.getByRole('status').filter({ hasText: 'Showing scan 3 of 7' }).waitFor();
  // The coil and the Start contact pass power; the seal-in contact does not yet.
  assert.equal(await cell('0-0-2').getAttribute('data-power'), 'on');
  assert.equal(await cell('0-0-0').getAttribute('data-power'), 'on');
  assert.equal(await cell('0-1-0').getAttribute('data-power'), 'off');
  await cell('0-0-2').getByRole('button', { name: 'Why is Motor TRUE?' }).click();
  const why = page.getByRole('region', { name: 'Explanation' });
  await why.getByText('Motor is TRUE at scan 3').waitFor();
  const text = async () => (await why.textContent()).replace(/\s+/g, ' ');
  assert.match(await text(), /Latch rung 1/);
  assert.match(await text(), /Start TRUE/);
  await why.getByRole('button', { name: 'Show rung 1 of Latch' }).waitFor();
  await page.screenshot({ path: path.join(root, 'docs/screenshots/why-ladder-latch.png') });
  // Scan 5: Start released, Motor holds itself through the seal-in contact.
  await page.getByRole('slider', { name: 'Recorded scan' }).fill('5');
  await why.getByText('Motor is TRUE at scan 5').waitFor();
  assert.equal(await cell('0-1-0').getAttribute('data-power'), 'on');
  assert.equal(await cell('0-0-0').getAttribute('data-power'), 'off');
  assert.match(await text(), /Start FALSE/);
  assert.match(await text(), /NO contact Motor \(row 2, column 1\): power passes/);
  // The contact has its own Why.
  await cell('0-1-0').getByRole('button', { name: 'Why is Motor TRUE?' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('weighing with its plant: a place names the transition that fired, and the discharge valve is followed back to the set point', async () => {
  const { context, page, errors } = await openExample('Weighing with its plant (Petri net and ST plant)');
  const scene = page.getByRole('region', { name: 'Plant' });
  await scene.getByRole('button', { name: 'Start button' }).click();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  for (let k = 0; k < 3; k += 1) await step.click();
  // The token is in the filling place: why?
  await page.getByRole('button', { name: 'Why does P31 hold a token?' }).click();
  const why = page.getByRole('region', { name: 'Explanation' });
  await why.getByText(/^P31 holds a token at scan 3/).waitFor();
  const text = async () => (await why.textContent()).replace(/\s+/g, ' ');
  assert.match(await text(), /transition T2/);
  assert.match(await text(), /Start AND NOT Fault/);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/why-petri-place.png') });

  // Run until the discharge valve opens, a few scans more.
  const io = page.getByRole('region', { name: 'Inputs and outputs' });
  for (let k = 0; k < 80 && !(await io.getByRole('img', { name: 'DischargeValve: ON' }).count()); k += 1) {
    await stepN(page, 10);
  }
  await io.getByRole('img', { name: 'DischargeValve: ON' }).waitFor();
  await page.getByRole('region', { name: 'Variables' }).getByRole('button', { name: 'Why is DischargeValve TRUE?' }).click();
  await why.getByText(/^DischargeValve is TRUE at scan/).waitFor();
  assert.match(await text(), /place P33/);
  // Follow the step variable back until a guard names the set point.
  const visited = new Set();
  for (let k = 0; k < 8 && !/Setpoint/.test(await text()); k += 1) {
    const buttons = why.getByRole('button', { name: /^Why is p \d+\?$/ });
    let clicked = false;
    for (let b = 0; b < await buttons.count(); b += 1) {
      const name = (await buttons.nth(b).textContent()).trim();
      if (visited.has(name)) continue;
      visited.add(name);
      await buttons.nth(b).click();
      await why.getByText(name.replace(/^Why is (\S+) (\S+)\?$/, '$1 is $2 at scan')).waitFor();
      clicked = true;
      break;
    }
    if (!clicked) break;
  }
  assert.match(await text(), /Weight >= Setpoint/);
  await why.getByRole('button', { name: /^Why is Setpoint \d+\?$/ }).waitFor();
  await page.screenshot({ path: path.join(root, 'docs/screenshots/why-weighing.png') });
  assert.deepEqual(errors, []);
  await context.close();
});
