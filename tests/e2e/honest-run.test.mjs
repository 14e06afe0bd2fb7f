// Run is honest (issue 31): with errors on the screen, Run and Step never start the
// previous build silently. They say how many errors to fix, link to the first, and offer
// the last version that built as an explicit choice; the status says when that one runs.
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

const LATCH = `PROGRAM Main
VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
`;

// A new output, and a type error on line 10: an INT into a BOOL.
const BROKEN = LATCH.replace('    Motor : BOOL;\n', '    Motor : BOOL;\n    Lamp : BOOL;\n')
  .replace('Motor := (Start', 'Lamp := 3;\nMotor := (Start');
const FIXED = BROKEN.replace('Lamp := 3;', 'Lamp := Motor;');

const scanCount = async (page) => Number(await page.getByLabel('Scan count').textContent());

test('with a type error, Run says what to fix and runs the last version that built only when asked', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const { page, errors } = await openApp(context);
  await page.getByRole('button', { name: 'New project' }).click();
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await editor.fill(LATCH);
  await page.getByRole('img', { name: 'Motor: OFF' }).waitFor();

  // The error is typed and Run pressed at once, before the editor's own check.
  await editor.fill(BROKEN);
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  const alert = page.getByRole('alert');
  await alert.filter({ hasText: 'Fix 1 error to run your changes.' }).waitFor();
  const goTo = alert.getByRole('button', { name: 'Go to line 10' });
  await goTo.waitFor();
  const runOld = alert.getByRole('button', { name: 'Run the last version that built' });
  await runOld.waitFor();
  await page.waitForTimeout(500);
  assert.equal(await scanCount(page), 0, 'the old build did not start');
  await page.getByRole('status', { name: 'PLC state: Stopped' }).waitFor();
  // Step does not scan it either.
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await page.waitForTimeout(200);
  assert.equal(await scanCount(page), 0);
  // The simulator still holds the last version that built, and says so.
  const version = page.locator('.controls').getByRole('status').filter({ hasText: 'last version that built' });
  await version.filter({ hasText: 'The simulator holds the last version that built (before your latest edits)' }).waitFor();

  // The link shows the first problem: the caret is on line 10.
  await goTo.click();
  await page.waitForFunction(() => {
    const ta = document.querySelector('textarea[aria-label="ST source"]');
    return ta.value.slice(0, ta.selectionStart).split('\n').length === 10;
  });
  await page.screenshot({ path: path.join(shots, 'honest-run.png') });

  // Chosen explicitly, the old build runs, and the status says which version that is.
  await runOld.click();
  await page.getByRole('status', { name: 'PLC state: Running' }).waitFor();
  await page.waitForFunction(() => Number(document.querySelector('[aria-label="Scan count"]').textContent) > 5);
  await version.filter({ hasText: 'Running the last version that built (before your latest edits)' }).waitFor();
  assert.equal(await page.getByRole('img', { name: /^Lamp: / }).count(), 0, 'the old build has no Lamp');
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor();

  // Fixed, the new text runs at once and the status is back to normal.
  await editor.fill(FIXED);
  await page.getByRole('img', { name: 'Lamp: ON' }).waitFor();
  await version.waitFor({ state: 'hidden' });
  await page.getByRole('status', { name: 'PLC state: Running' }).waitFor();
  assert.equal(await page.getByRole('alert').filter({ hasText: 'to run your changes' }).count(), 0);

  // Broken again while running: it keeps running the last version, and says so; Pause
  // then Run asks again.
  await editor.fill(BROKEN);
  await version.filter({ hasText: 'Running the last version that built' }).waitFor();
  await page.getByRole('button', { name: 'Pause', exact: true }).click();
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await alert.filter({ hasText: 'Fix 1 error to run your changes.' }).waitFor();
  await page.getByRole('status', { name: 'PLC state: Paused' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('a program that never built offers only the fix', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  const project = {
    schema: 1, name: 'Never built', source: BROKEN.replace('Lamp := 3;', 'Lamp := ;'),
    settings: { cycle_ms: 10, traced: [], breakpoints: [] }, ladder: [], petri: [],
  };
  await page.getByLabel('Import project file').setInputFiles({
    name: 'never.plcproj.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(project)),
  });
  await page.getByRole('status', { name: 'PLC state: No program' }).waitFor();
  const run = page.getByRole('button', { name: 'Run', exact: true });
  assert.equal(await run.isEnabled(), true, 'Run stays pressable: it says what to fix');
  await run.click();
  const alert = page.getByRole('alert');
  await alert.filter({ hasText: /^Fix \d+ errors? to run your changes\./ }).waitFor();
  assert.equal(await alert.getByRole('button', { name: 'Run the last version that built' }).count(), 0);
  assert.equal(await alert.getByRole('button', { name: /^Go to line / }).count(), 1);
  assert.equal(await page.locator('.controls').getByRole('status').filter({ hasText: 'last version' }).count(), 0);
  assert.equal(await scanCount(page), 0);
  assert.deepEqual(errors, []);
  await context.close();
});
