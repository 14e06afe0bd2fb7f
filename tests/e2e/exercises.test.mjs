// Exercises (issue 15): a student opens the catalogue, opens an exercise, pastes a wrong
// solution, checks it and reads the failing scenario, the first wrong output and the
// timeline at that scan; fixes it, sees every scenario pass and the catalogue's tick;
// opens the same exercise from a #x= link in a fresh browser, and from ?exercise=URL.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { mkdtemp, writeFile, readFile } from 'node:fs/promises';
import os from 'node:os';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';
import { NO_SEAL } from './setup.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let server;
let course;
let browser;

before(async () => {
  server = await startServer(path.join(root, 'dist'));
  // Another origin that allows other sites to read its files, as an instructor's host.
  course = await startServer(path.join(root, 'exercises'), '/course/', { 'access-control-allow-origin': '*' });
  browser = await launch();
});
after(async () => {
  await browser?.close();
  await server?.close();
  await course?.close();
});

const RIGHT = NO_SEAL.replace('Motor := Start AND NOT Stop;', 'Motor := (Start OR Motor) AND NOT Stop;');

async function fresh(errors) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  page.on('pageerror', (e) => errors.push(e.message));
  return { context, page };
}

/** Types a whole program into the ST editor and waits until the project holds it. */
async function write(page, text) {
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await editor.fill(text);
  await page.waitForTimeout(400); // the debounced check and save
}

async function check(page) {
  await page.getByRole('button', { name: 'Check', exact: true }).click();
  const report = page.getByRole('region', { name: 'Report' });
  await report.waitFor();
  await page.getByRole('button', { name: 'Check', exact: true }).waitFor({ state: 'visible' });
  await page.waitForFunction(() => !document.querySelector('.exercise-actions button.primary')?.disabled);
  return report;
}

test('catalogue → exercise → wrong solution fails with its first wrong output and timeline → right one passes and is ticked', async () => {
  const errors = [];
  const { context, page } = await fresh(errors);
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();

  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  const list = page.getByRole('list', { name: 'Exercise list' });
  await list.waitFor();
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).isVisible(), false, 'the catalogue takes the place of the workspace');
  const items = list.getByRole('listitem');
  const total = await items.count();
  assert.ok(total >= 10, `the catalogue lists the shipped exercises (${total})`);
  // Filters: level 1 keeps the latch; a language it is not written in hides it.
  await page.getByRole('combobox', { name: 'Level' }).selectOption('1');
  assert.ok(await list.getByRole('button', { name: 'Start/stop motor latch' }).isVisible());
  assert.ok((await items.count()) < total);
  await page.getByRole('combobox', { name: 'Level' }).selectOption('0');
  await page.getByRole('combobox', { name: 'Language' }).selectOption('st');
  await page.getByRole('combobox', { name: 'Language' }).selectOption('');
  assert.equal(await items.count(), total);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/exercise-catalogue.png') });

  await list.getByRole('button', { name: 'Start/stop motor latch' }).click();
  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  const table = panel.getByRole('table', { name: 'Interface' });
  assert.match(await table.textContent(), /Motor.*BOOL.*VAR_OUTPUT/);
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'));

  // A wrong solution: no seal-in.
  await write(page, NO_SEAL);
  let report = await check(page);
  const failed = report.locator('.report-scenario.failed').first();
  assert.match(await failed.locator('.report-name').textContent(), /^Start, release, stop$/);
  assert.match(await failed.locator('.report-actual').textContent(), /Motor was FALSE at 0\.21 s \(scan 21\)/);
  assert.match(await failed.textContent(), /Hint: Does the motor hold itself/);
  const timeline = failed.getByRole('img', { name: /^Timeline of “Start, release, stop”/ });
  assert.equal(await timeline.getAttribute('data-cursor-time'), '0.21 s');
  assert.equal(await timeline.getAttribute('data-cursor-scan'), '21');
  assert.match(await timeline.getAttribute('aria-label'), /first wrong scan, 0\.21 s · scan 21/);
  await failed.locator('.tl-cursor').waitFor({ state: 'attached' });
  assert.ok((await failed.locator('.tl-wrong').count()) > 0, 'the wrong scans are marked');
  assert.match(await report.locator('.report-score').textContent(), /^Score 1 of 3 \(scenario weights: 2 \+ 1\)$/);
  assert.equal(await report.locator('.report-program').textContent(), 'Checked PROGRAM Main (ST)');
  await panel.screenshot({ path: path.join(root, 'docs/screenshots/exercise-report.png') });

  // Fixed: every scenario passes and the catalogue ticks the exercise.
  await write(page, RIGHT);
  report = await check(page);
  await report.getByText('Score 3 of 3: every scenario passes. Well done!').waitFor();
  assert.equal(await report.locator('.report-scenario.failed').count(), 0);
  await panel.getByRole('button', { name: 'All exercises' }).click();
  const latch = page.locator('.catalogue-item[data-exercise="latch"]');
  await latch.getByRole('img', { name: 'Passed' }).waitFor();

  // After a reload the attempt and the tick are still there.
  await page.reload();
  await page.getByRole('region', { name: 'Exercise' }).getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  assert.equal(await editor.inputValue(), RIGHT);
  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await page.locator('.catalogue-item[data-exercise="latch"]').getByRole('img', { name: 'Passed' }).waitFor();

  // Reset to starter asks first; declining keeps the work.
  await page.getByRole('button', { name: 'Back to the project' }).click();
  page.once('dialog', (d) => d.dismiss());
  await page.getByRole('button', { name: 'Reset to starter' }).click();
  assert.equal(await editor.inputValue(), RIGHT);
  page.once('dialog', (d) => d.accept());
  await page.getByRole('button', { name: 'Reset to starter' }).click();
  await page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'));
  assert.deepEqual(errors, []);
  await context.close();
});

test('Share exercise gives a #x= link that opens the exercise with its starter in a fresh browser', async () => {
  const errors = [];
  const first = await fresh(errors);
  await first.page.goto(server.url);
  await first.page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await first.page.getByRole('button', { name: 'Reversing motor with interlock' }).click();
  const panel = first.page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: 'Reversing motor with interlock' }).waitFor();
  await panel.getByRole('button', { name: 'Share exercise' }).click();
  const link = await first.page.getByRole('textbox', { name: 'Exercise link' }).inputValue();
  assert.match(link, /#x=[A-Za-z0-9_-]+$/);
  await first.context.close();

  const second = await fresh(errors);
  await second.page.goto(link);
  const opened = second.page.getByRole('region', { name: 'Exercise' });
  await opened.getByRole('heading', { name: 'Reversing motor with interlock' }).waitFor();
  await second.page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('MotorRev'));
  assert.ok(!second.page.url().includes('#x='), 'the fragment is cleared once the exercise is open');
  // The classic bug: the random scenario finds both directions on and gives its seed.
  await write(second.page, (await readFile(path.join(root, 'exercises/reversing/mutants/no-interlock.st'), 'utf8')));
  const report = await check(second.page);
  const random = report.locator('.report-scenario.failed', { hasText: 'Random presses never run both directions' });
  assert.match(await random.locator('.report-actual').textContent(), /MotorFwd AND MotorRev was TRUE at .* random run with seed \d+ \(replay: random = \{ runs = 1, seed = \d+ \}\)/);
  assert.deepEqual(errors, []);
  await second.context.close();
});

test('?exercise=URL opens an exercise file from another host; a broken file or link changes nothing', async () => {
  const errors = [];
  const { context, page } = await fresh(errors);
  const url = `${course.url}latch/latch.toml`;
  await page.goto(`${server.url}?exercise=${encodeURIComponent(url)}`);
  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  await page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'));

  // A hostile file: raw HTML in the statement stays text, and a malformed file is refused.
  const dir = await mkdtemp(path.join(os.tmpdir(), 'plc-ex-'));
  await writeFile(path.join(dir, 'evil.toml'), 'id = "evil"\ntitle = "Evil"\nlevel = 1\nstatement = "<img src=x onerror=alert(1)><script>alert(2)</script> [x](javascript:alert(3))"\n');
  await writeFile(path.join(dir, 'broken.toml'), 'id = "broken"\ntitle = 3\n');
  const host = await startServer(dir, '/h/', { 'access-control-allow-origin': '*' });
  let dialogs = 0;
  page.on('dialog', (d) => { dialogs += 1; d.dismiss(); });
  await page.goto(`${server.url}?exercise=${encodeURIComponent(`${host.url}evil.toml`)}`);
  await page.getByRole('region', { name: 'Exercise' }).getByRole('heading', { name: 'Evil' }).waitFor();
  const statement = page.locator('.statement');
  assert.match(await statement.textContent(), /<script>alert\(2\)<\/script>/);
  assert.equal(await statement.locator('img, script').count(), 0);
  assert.equal(await statement.locator('a[href^="javascript"]').count(), 0);
  const before = await page.getByRole('textbox', { name: 'ST source' }).inputValue();
  await page.goto(`${server.url}?exercise=${encodeURIComponent(`${host.url}broken.toml`)}`);
  await page.getByRole('alert').getByText(/Could not open the exercise: the exercise file cannot be used: line 2/).waitFor();
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).inputValue(), before);
  await page.goto(`${server.url}#x=AAAA`);
  await page.getByRole('alert').getByText(/damaged/).waitFor();
  assert.equal(dialogs, 0);
  assert.deepEqual(errors, []);
  await host.close();
  await context.close();
});

test('the grader and the report come at the first Check; when they cannot be fetched Check says so and works the next time', async () => {
  const errors = [];
  const context = await browser.newContext({ serviceWorkers: 'block', viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  page.on('pageerror', (e) => errors.push(e.message));
  const chunks = [];
  context.on('request', (r) => { if (r.url().endsWith('.wasm')) chunks.push(r.url().split('/').pop()); });
  let offline = true;
  await context.route('**/split_exercise_report.wasm', (route) => (offline ? route.abort() : route.continue()));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: 'Start/stop motor latch' }).click();
  await page.getByRole('button', { name: 'Check', exact: true }).waitFor();
  for (const chunk of ['split_exercise_grader.wasm', 'split_exercise_report.wasm']) {
    assert.ok(!chunks.includes(chunk), `${chunk} is not fetched to open an exercise (${chunks.join(' ')})`);
  }
  await write(page, RIGHT);

  await page.getByRole('button', { name: 'Check', exact: true }).click();
  await page.getByText('Could not check: a part of the app could not be loaded (is the network off?)').waitFor();
  assert.equal(await page.getByRole('region', { name: 'Report' }).count(), 0);
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).inputValue(), RIGHT, 'the attempt is kept');

  offline = false;
  const report = await check(page);
  await report.getByText('Score 3 of 3: every scenario passes. Well done!').waitFor();
  assert.ok(chunks.includes('split_exercise_grader.wasm'), 'the worker fetched the grader');
  assert.deepEqual(errors, []);
  await context.close();
});
