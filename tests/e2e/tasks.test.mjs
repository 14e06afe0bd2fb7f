// Configurations (issue 18): a program with a CONFIGURATION of two tasks runs each program
// instance under its task on the one virtual clock; the Variables panel shows both
// instances, each under its name with its task, and the I/O panel drives the global input.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
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

test('a configuration of two tasks runs both program instances, each in the variable table', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: 'Bottling two tasks (ST)' });
  // The configuration is what runs.
  const program = page.getByRole('combobox', { name: 'Program to run' });
  await page.waitForFunction(() => document.querySelector('select[aria-label="Program to run"]')?.value === 'Bottling');
  assert.deepEqual(await program.locator('option').allTextContents(), ['Bottling', 'Counting', 'Statistics']);
  const vars = page.getByRole('region', { name: 'Variables' });
  // A row header is the name, after the disclosure button (`Expand NAME`) of an
  // expandable row.
  const row = (name) => vars.getByRole('row').filter({ has: page.getByRole('rowheader', { name: new RegExp(`^(Expand \\S+ )?${name}$`) }) });
  const value = async (name) => (await row(name).getByRole('cell').nth(3).textContent()).trim();
  // Both instances, expanded, each with its task.
  await row('Line').waitFor();
  await row('Stats').waitFor();
  assert.match(await row('Line').textContent(), /task Fast: every 10 ms, priority 1/);
  assert.match(await row('Stats').textContent(), /task Slow: every 1 s, priority 5/);
  assert.equal(await vars.getByRole('button', { name: 'Expand Line', exact: true }).getAttribute('aria-expanded'), 'true');
  await row('Count').waitFor();
  await row('PerSecond').waitFor();
  // Four bottles pass the barrier, one scan each way (the fast task sees every edge).
  const barrier = page.getByRole('region', { name: 'Inputs and outputs' }).getByRole('checkbox', { name: 'Barrier', exact: true });
  const step = page.getByRole('button', { name: 'Step', exact: true });
  for (let k = 0; k < 4; k += 1) {
    await barrier.check();
    await step.click();
    await barrier.uncheck();
    await step.click();
  }
  assert.equal(await value('Count'), '4');
  assert.equal(await value('Bottles'), '4');
  // A VAR_EXTERNAL is the global: listed once, not under each instance.
  assert.equal(await vars.getByRole('rowheader', { name: 'Bottles', exact: true }).count(), 1);
  // The slow task has run once, on the first tick, after the fast one (priority 5 after
  // 1): it saw the first bottle.
  assert.equal(await value('PerSecond'), '1');
  // 100 scans more: the slow task's second run (at 1 s) sees the three bottles since.
  await page.getByRole('spinbutton', { name: 'Scans per step' }).fill('100');
  await page.getByRole('button', { name: 'Step N' }).click();
  assert.equal(await value('PerSecond'), '3');
  assert.equal(await value('Count'), '4');
  // The same as plc run prints for the same inputs, keyed by instance.
  const cli = JSON.parse(execFileSync('cargo', ['run', '-q', '-p', 'plc-core', '--bin', 'plc', '--', 'run',
    path.join(root, 'examples/bottling-two-tasks.st'), '--cycles', '1', '--set', 'Barrier=TRUE', '--json'], { cwd: root }).toString());
  assert.deepEqual(Object.keys(cli.vars).sort(), ['Barrier', 'Bottles', 'Line', 'Stats']);
  assert.equal(cli.vars.Line.Count, 1);
  assert.equal(cli.vars.Stats.PerSecond, 1);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/configuration-two-tasks.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});
