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
