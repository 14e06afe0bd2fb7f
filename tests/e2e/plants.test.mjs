// Plants (issue 17): a project whose settings name a plant PROGRAM runs it after the
// controller on every scan; the plant drives the controller's sensor and its own
// variables are in the variable table under its name.
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

const TANK = JSON.stringify({
  schema: 1,
  name: 'Tank',
  source: `PROGRAM Control
VAR_INPUT Level : INT; END_VAR
VAR_OUTPUT Fill : BOOL; END_VAR
IF Level < 40 THEN Fill := TRUE; ELSIF Level > 60 THEN Fill := FALSE; END_IF;
END_PROGRAM
PROGRAM Tank
VAR_INPUT Fill : BOOL; END_VAR
VAR_OUTPUT Level : INT; END_VAR
VAR Scans : INT; END_VAR
IF Fill THEN Level := Level + 5; ELSIF Level > 0 THEN Level := Level - 1; END_IF;
Scans := Scans + 1;
END_PROGRAM
`,
  settings: { cycle_ms: 10, traced: [], breakpoints: [], program: 'Control', plant: 'Tank' },
});

test('the plant named in the settings runs after the controller and drives its sensor', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  await page.getByLabel('Import project file').setInputFiles({
    name: 'tank.plcproj.json', mimeType: 'application/json', buffer: Buffer.from(TANK),
  });
  const vars = page.getByRole('region', { name: 'Variables' });
  await vars.getByRole('rowheader', { name: /Tank/ }).waitFor();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  for (let k = 0; k < 4; k += 1) await step.click();
  // Four scans of filling: the plant raised the level by 5 each, and the controller's
  // sensor reads it.
  const value = (name) => vars.getByRole('row').filter({ has: page.getByRole('rowheader', { name, exact: true }) }).getByRole('cell').nth(3);
  assert.equal((await value('Level').textContent()).trim(), '20');
  assert.equal((await value('Fill').textContent()).trim(), 'TRUE');
  await vars.getByRole('button', { name: 'Expand Tank' }).click();
  assert.equal((await value('Scans').textContent()).trim(), '4');
  assert.deepEqual(errors, []);
  await context.close();
});

test('the weighing plant: the scene\'s Start button starts a batch and the scale climbs to the set point', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: 'Weighing with its plant (Petri net and ST plant)' });
  const scene = page.getByRole('region', { name: 'Plant' });
  await scene.getByRole('img', { name: 'Scale: 0 g' }).waitFor();
  await scene.getByRole('img', { name: 'Feed valve: closed' }).waitFor();
  // Pressed while paused, the button holds Start until a scan has seen it.
  await scene.getByRole('button', { name: 'Start button' }).click();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  for (let k = 0; k < 3; k += 1) await step.click();
  await scene.getByRole('img', { name: 'Feed valve: open' }).waitFor();
  assert.equal(await scene.getByRole('button', { name: 'Start button' }).getAttribute('aria-pressed'), 'false');
  const scale = async () => Number((await scene.getByRole('img', { name: /^Scale: / }).getAttribute('aria-label')).match(/Scale: ([0-9.]+) g/)[1]);
  const before = await scale();
  for (let k = 0; k < 5; k += 1) await step.click();
  assert.ok(await scale() > before, 'the scale climbs while the feed valve is open');
  // 200 scans more: filled to the set point (50 g) and settling, the valve closed.
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('200');
  await page.getByRole('button', { name: 'Step N' }).click();
  await scene.getByRole('img', { name: 'Feed valve: closed' }).waitFor();
  const filled = await scale();
  assert.ok(filled >= 50 && filled <= 50.5, `the scale stops at the set point, not ${filled}`);
  await scene.getByRole('img', { name: 'Hopper: 50 %' }).waitFor();
  // After the 2 s settling time: discharging into the running mixer.
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('150');
  await page.getByRole('button', { name: 'Step N' }).click();
  await scene.getByRole('img', { name: 'Discharge valve: open' }).waitFor();
  await scene.getByRole('img', { name: 'Mixer: running' }).waitFor();
  await page.screenshot({ path: path.join(root, 'docs/screenshots/plant-weighing.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});
