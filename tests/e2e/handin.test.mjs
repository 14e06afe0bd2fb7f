// Hand-ins and the class report (issue 35): a student hands in the latch exercise (the page
// asks once for the name) and another exercise; `plc grade` grades the hand-in with the
// student's name and gives the other exercise's hand-in its own row with the reason. The
// class report of a reversing-motor class opens from disk and is pictured. `Export SCORM
// package` downloads a package made in the page.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import os from 'node:os';
import { mkdtemp, writeFile, readFile } from 'node:fs/promises';
import { execFileSync } from 'node:child_process';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';
import { unzip } from './zip.mjs';

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

function plc(...args) {
  return execFileSync('cargo', ['run', '-q', '-p', 'plc-core', '--bin', 'plc', '--', ...args], { cwd: root }).toString();
}

async function fresh(errors) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 }, acceptDownloads: true });
  const page = await context.newPage();
  page.on('pageerror', (e) => errors.push(e.message));
  return { context, page };
}

async function openExercise(page, title) {
  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: title }).click();
  await page.getByRole('region', { name: 'Exercise' }).getByRole('heading', { name: title }).waitFor();
}

/** Runs `action` and saves the download it starts into `dir`; its file name. */
async function downloadFrom(page, action, dir) {
  const download = page.waitForEvent('download');
  await action();
  const d = await download;
  await d.saveAs(path.join(dir, d.suggestedFilename()));
  return d.suggestedFilename();
}

test('Hand in asks once for the name and downloads a .plcsub that plc grade grades with it', async () => {
  const errors = [];
  const dir = await mkdtemp(path.join(os.tmpdir(), 'plc-handins-'));
  const { context, page } = await fresh(errors);
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await openExercise(page, 'Start/stop motor latch');
  await page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'));
  await page.getByRole('textbox', { name: 'ST source' }).fill(await readFile(path.join(root, 'exercises/latch/reference.st'), 'utf8'));
  await page.waitForTimeout(400);

  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('button', { name: 'Hand in', exact: true }).click();
  const dialog = page.getByRole('dialog', { name: 'Hand in' });
  await dialog.waitFor();
  const name = dialog.getByRole('textbox', { name: 'Your name' });
  assert.ok(await name.evaluate((e) => e === document.activeElement), 'the name field has the focus');
  // No name (or only spaces): the browser refuses the form and the dialog stays.
  await name.fill('   ');
  await dialog.getByRole('button', { name: 'Download hand-in' }).click();
  assert.ok(await dialog.isVisible());
  assert.equal(await name.evaluate((e) => e.validity.valid), false);
  // Escape closes it without a download; Hand in asks again (no name is kept yet).
  await name.press('Escape');
  await dialog.waitFor({ state: 'hidden' });
  await panel.getByRole('button', { name: 'Hand in', exact: true }).click();
  await dialog.waitFor();
  await name.fill('Ada Lovelace');
  await page.screenshot({ path: path.join(root, 'docs/screenshots/hand-in.png') });
  let file = await downloadFrom(page, () => name.press('Enter'), dir);
  assert.equal(file, 'latch--Ada-Lovelace.plcsub');
  assert.equal(await dialog.count(), 0, 'the dialog closes');
  await page.getByRole('alert').filter({ hasText: 'Downloaded latch--Ada-Lovelace.plcsub' }).waitFor();
  const handIn = JSON.parse(await readFile(path.join(dir, file), 'utf8'));
  assert.equal(handIn.hand_in.exercise, 'latch');
  assert.equal(handIn.hand_in.name, 'Ada Lovelace');
  assert.match(handIn.hand_in.handed_in, /^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z$/);
  assert.equal(handIn.score, undefined, 'no score in a hand-in');

  // Another exercise: the name is asked only once.
  await openExercise(page, 'Blinker with timers');
  file = await downloadFrom(page, () => page.getByRole('region', { name: 'Exercise' }).getByRole('button', { name: 'Hand in', exact: true }).click(), dir);
  assert.equal(file, 'blinker--Ada-Lovelace.plcsub');
  assert.equal(await page.getByRole('dialog', { name: 'Hand in' }).count(), 0);
  await context.close();
  assert.deepEqual(errors, []);

  const text = plc('grade', path.join(root, 'exercises/latch/latch.toml'), dir);
  assert.match(text, /latch--Ada-Lovelace\.plcsub \(Ada Lovelace\): 3\/3/);
  assert.match(text, /blinker--Ada-Lovelace\.plcsub \(Ada Lovelace\): cannot be graded: this is a hand-in of exercise “blinker”, not of “latch”/);
  const csv = plc('grade', path.join(root, 'exercises/latch/latch.toml'), dir, '--format', 'csv').trim().split('\n');
  assert.ok(csv.some((l) => /latch--Ada-Lovelace\.plcsub,3,3,2,0,,,Main,Ada Lovelace,/.test(l)), csv.join('\n'));
});

test('plc grade --format html: the class report opens from disk with its rows, pass rates, histogram and common failures', async () => {
  const dir = await mkdtemp(path.join(os.tmpdir(), 'plc-class-'));
  const ex = path.join(root, 'exercises/reversing');
  const src = (f) => readFile(path.join(ex, f), 'utf8');
  const reference = await src('reference.st');
  const students = [
    ['Ada Lovelace', reference],
    ['Grace Hopper', reference],
    ['Alan Turing', await src('mutants/no-interlock.st')],
    ['Edsger Dijkstra', await src('mutants/no-interlock.st')],
    ['Barbara Liskov', await src('mutants/stop-ignored.st')],
    ['Niklaus Wirth', await src('mutants/forward-not-held.st')],
    ['Ken Thompson', await src('starter.st')],
    ['Margaret Hamilton', reference.replace('NOT Stop', 'NOT Stopp')],
  ];
  for (const [name, source] of students) {
    const project = { schema: 1, name: 'Exercise: Reversing motor with interlock', source, settings: { cycle_ms: 10, traced: [], breakpoints: [] } };
    const body = { hand_in: { exercise: 'reversing', name, handed_in: '2025-03-04T10:15:00.000Z' }, ...project };
    await writeFile(path.join(dir, `reversing--${name.replace(' ', '-')}.plcsub`), JSON.stringify(body, null, 2));
  }
  await writeFile(path.join(dir, 'broken.plcproj.json'), '{ "schema": 1, "name": ');
  const report = path.join(dir, 'report.html');
  await writeFile(report, plc('grade', path.join(ex, 'reversing.toml'), dir, '--format', 'html'));
  const context = await browser.newContext({ viewport: { width: 1200, height: 1000 }, offline: true });
  const page = await context.newPage();
  const requests = [];
  page.on('request', (r) => requests.push(r.url()));
  await page.goto(`file://${report}`);
  await page.getByRole('heading', { name: 'Class report — Reversing motor with interlock' }).waitFor();
  assert.deepEqual(requests, [`file://${report}`], 'nothing else is loaded');
  const rows = page.getByRole('table').last().getByRole('row');
  assert.equal(await rows.count(), students.length + 2, 'a header and a row per submission');
  assert.match(await rows.filter({ hasText: 'Alan Turing' }).textContent(), /1 \/ 2.*Random presses never run both directions.*2\.65 s/);
  assert.match(await rows.filter({ hasText: 'broken.plcproj.json' }).textContent(), /not graded/);
  await page.getByRole('img', { name: 'Submissions per score: 0: 1, 1: 5, 2: 2' }).waitFor();
  const rates = page.getByRole('table').first();
  assert.match(await rates.getByRole('row').nth(1).textContent(), /Forward, stop, reverse.*4 \/ 8 \(50 %\)/);
  assert.match(await rates.getByRole('row').nth(2).textContent(), /Random presses never run both directions.*5 \/ 8 \(63 %\)/);
  const common = page.getByRole('table').nth(1);
  assert.match(await common.getByRole('row').nth(1).textContent(), /“Forward, stop, reverse”: expected MotorFwd AND NOT MotorRev stays TRUE.*2 of 8/);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/class-report.png'), fullPage: true });
  await context.close();
});

test('Export SCORM package downloads a package made in the page: the site, the exercise, its starter', async () => {
  const errors = [];
  const dir = await mkdtemp(path.join(os.tmpdir(), 'plc-export-'));
  const { context, page } = await fresh(errors);
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await openExercise(page, 'Start/stop motor latch');
  const file = await downloadFrom(page, () => page.getByRole('button', { name: 'Export SCORM package' }).click(), dir);
  assert.equal(file, 'latch-scorm.zip');
  const files = unzip(await readFile(path.join(dir, file)));
  for (const name of ['imsmanifest.xml', 'index.html', 'exercise/latch.toml', 'exercise/starter.st', 'sw.js', 'manifest.json']) {
    assert.ok(files.has(name), `${name} in the package`);
  }
  for (const name of ['boot.js', 'worker.js', 'plc-web_bg.wasm', 'split_exercise_worker.wasm']) {
    assert.ok([...files.keys()].some((n) => /^app-[^/]+\//.test(n) && n.endsWith(`/${name}`)), `the app's ${name}`);
  }
  assert.equal([...files.keys()].some((n) => /reference|mutants/.test(n)), false);
  const manifest = files.get('imsmanifest.xml').toString('utf8');
  assert.match(manifest, /adlcp:scormtype="sco" href="index\.html\?exercise=exercise\/latch\.toml&amp;scorm=1"/);
  assert.deepEqual(files.get('index.html'), await readFile(path.join(root, 'dist/index.html')));
  await page.getByRole('alert').filter({ hasText: 'Downloaded latch-scorm.zip (SCORM 1.2)' }).waitFor();
  await context.close();
  assert.deepEqual(errors, []);
});
