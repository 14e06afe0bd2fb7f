// SCORM (issue 35): a package made by `plc exercise scorm` is served inside a test page
// that plays the LMS — it implements the SCORM 1.2 runtime API (and, in a second page, the
// SCORM 2004 one) in the parent frame and records every call — as an LMS launches it: the
// exercise opens alone; a failing Check sends a partial score and a status that is not
// passed; the reference pasted in and checked sends 100 and passed; a commit follows each;
// reloading the launch restores the attempt from suspend_data (also on another computer);
// the session finishes on unload. LMS errors are shown, never thrown; with no LMS the page
// is a plain exercise.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import os from 'node:os';
import { mkdtemp, mkdir, writeFile, readFile } from 'node:fs/promises';
import { execFileSync } from 'node:child_process';
import { deflateRawSync, inflateRawSync } from 'node:zlib';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';
import { unzip } from './zip.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let server;
let browser;
let launchHref;
let manifest;

function plc(...args) {
  return execFileSync('cargo', ['run', '-q', '-p', 'plc-core', '--bin', 'plc', '--', ...args], { cwd: root }).toString();
}

/** The parent page of an LMS: the runtime API of `edition` on window, every call in
 *  `window.calls`, the data model in `window.cmi`, and the SCO in a frame. */
function lmsPage(edition, launch) {
  const v12 = edition === '1.2';
  const names = v12
    ? { init: 'LMSInitialize', finish: 'LMSFinish', get: 'LMSGetValue', set: 'LMSSetValue', commit: 'LMSCommit',
        error: 'LMSGetLastError', text: 'LMSGetErrorString', diag: 'LMSGetDiagnostic', api: 'API' }
    : { init: 'Initialize', finish: 'Terminate', get: 'GetValue', set: 'SetValue', commit: 'Commit',
        error: 'GetLastError', text: 'GetErrorString', diag: 'GetDiagnostic', api: 'API_1484_11' };
  const status = v12 ? 'cmi.core.lesson_status' : 'cmi.completion_status';
  const limit = v12 ? 4096 : 64000;
  return `<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>Test LMS (SCORM ${edition})</title>
<style>body{margin:0;font:14px sans-serif} header{padding:6px 10px;background:#24324a;color:#fff}
iframe{border:0;width:100%;height:calc(100vh - 32px)}</style></head>
<body><header>Test LMS · SCORM ${edition} · course “PLC basics”</header>
<script>
  window.calls = [];
  window.cmi = { '${status}': 'not attempted', 'cmi.suspend_data': window.SEED || '' };
  window.refuse = {};           // element → [code, text]: SetValue answers "false"
  let last = '0';
  const texts = { '0': 'No error', '405': 'Incorrect Data Type', '301': 'Not initialized' };
  const record = (name, fn) => (...args) => { window.calls.push([name, ...args]); return fn(...args); };
  window['${names.api}'] = {
    ${names.init}: record('${names.init}', () => { last = '0'; return 'true'; }),
    ${names.finish}: record('${names.finish}', () => { last = '0'; return 'true'; }),
    ${names.get}: record('${names.get}', (k) => { last = '0'; return window.cmi[k] ?? ''; }),
    ${names.set}: record('${names.set}', (k, v) => {
      if (window.refuse[k]) { last = window.refuse[k][0]; texts[last] = window.refuse[k][1]; return 'false'; }
      if (k === 'cmi.suspend_data' && String(v).length > ${limit}) { last = '405'; return 'false'; }
      window.cmi[k] = String(v); last = '0'; return 'true';
    }),
    ${names.commit}: record('${names.commit}', () => { last = '0'; return 'true'; }),
    ${names.error}: record('${names.error}', () => last),
    ${names.text}: record('${names.text}', (c) => texts[c] ?? ''),
    ${names.diag}: record('${names.diag}', () => ''),
  };
</script>
<iframe id="sco" title="Activity" src="pkg/${launch}"></iframe>
</body></html>
`;
}

before(async () => {
  const dir = await mkdtemp(path.join(os.tmpdir(), 'plc-scorm-'));
  const zip = path.join(dir, 'latch.zip');
  plc('exercise', 'scorm', path.join(root, 'exercises/latch/latch.toml'), '--site', path.join(root, 'dist'), '--out', zip);
  const files = unzip(await readFile(zip));
  const lms = path.join(dir, 'lms');
  for (const [name, data] of files) {
    const file = path.join(lms, 'pkg', name);
    await mkdir(path.dirname(file), { recursive: true });
    await writeFile(file, data);
  }
  manifest = files.get('imsmanifest.xml').toString('utf8');
  // The LMS launches the resource's href, as it reads it from the manifest.
  launchHref = /adlcp:scormtype="sco" href="([^"]+)"/.exec(manifest)[1].replaceAll('&amp;', '&');
  await writeFile(path.join(lms, 'lms12.html'), lmsPage('1.2', launchHref));
  await writeFile(path.join(lms, 'lms2004.html'), lmsPage('2004', launchHref));
  server = await startServer(lms, '/lms/');
  browser = await launch();
});
after(async () => {
  await browser?.close();
  await server?.close();
});

const RIGHT = (await readFile(path.join(root, 'exercises/latch/reference.st'), 'utf8'));

async function fresh(errors, seed) {
  const context = await browser.newContext({ viewport: { width: 1400, height: 950 } });
  if (seed) await context.addInitScript((s) => { if (window === window.top) window.SEED = s; }, seed);
  const page = await context.newPage();
  page.on('pageerror', (e) => errors.push(e.message));
  return { context, page };
}

/** The activity's frame, once the exercise is open in it. */
async function activity(page) {
  const frame = page.frameLocator('#sco');
  await frame.getByRole('region', { name: 'Exercise' }).getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  return frame;
}

async function write(frame, text) {
  await frame.getByRole('textbox', { name: 'ST source' }).fill(text);
  await new Promise((r) => setTimeout(r, 400));
}

/** Checks, and waits until the LMS got the commit that ends the report. */
async function check(page, frame) {
  const before = await page.evaluate(() => window.calls.length);
  await frame.getByRole('button', { name: 'Check', exact: true }).click();
  await frame.getByRole('region', { name: 'Report' }).waitFor();
  await page.waitForFunction((n) => window.calls.slice(n).some((c) => /Commit$/.test(c[0])), before);
  return page.evaluate((n) => window.calls.slice(n), before);
}

const setOf = (calls) => Object.fromEntries(calls.filter((c) => /SetValue$/.test(c[0])).map((c) => [c[1], c[2]]));

/** The project a suspend_data value holds (`p=` + base64url of raw DEFLATE, as share links). */
function attemptIn(data) {
  assert.match(data, /^p=[A-Za-z0-9_-]+$/);
  return JSON.parse(inflateRawSync(Buffer.from(data.slice(2), 'base64url')).toString('utf8'));
}

test('the package manifest has what SCORM 1.2 requires and launches the exercise alone', () => {
  for (const part of ['<schema>ADL SCORM</schema>', '<schemaversion>1.2</schemaversion>', '<organizations default=',
    '<organization identifier=', '<item identifier=', 'identifierref=', '<resources>', 'adlcp:scormtype="sco"', '<file href="index.html"/>']) {
    assert.ok(manifest.includes(part), `${part} in the manifest`);
  }
  assert.equal(launchHref, 'index.html?exercise=exercise/latch.toml&scorm=1');
});

test('SCORM 1.2: scores, status, commits, suspend_data, resume and finish, every call recorded', async () => {
  const errors = [];
  const { context, page } = await fresh(errors);
  await page.goto(`${server.url}lms12.html`);
  let frame = await activity(page);
  // Alone: no catalogue to leave it for; the LMS session started once.
  assert.equal(await frame.getByRole('button', { name: 'Exercises', exact: true }).isVisible(), false);
  assert.equal(await frame.getByRole('button', { name: 'All exercises' }).isVisible(), false);
  assert.equal(await frame.locator('html').getAttribute('data-lms'), 'scorm-1.2');
  let calls = await page.evaluate(() => window.calls);
  assert.deepEqual(calls[0], ['LMSInitialize', '']);
  assert.equal(calls.filter((c) => c[0] === 'LMSInitialize').length, 1);

  // The starter fails the first scenario: a partial score, not passed, then a commit.
  await frame.getByRole('textbox', { name: 'ST source' }).waitFor();
  calls = await check(page, frame);
  let set = setOf(calls);
  assert.equal(set['cmi.core.score.raw'], '33.33');
  assert.equal(set['cmi.core.score.min'], '0');
  assert.equal(set['cmi.core.score.max'], '100');
  assert.equal(set['cmi.core.lesson_status'], 'incomplete');
  assert.ok(set['cmi.suspend_data'].length <= 4096);
  assert.deepEqual(calls.at(-1), ['LMSCommit', '']);
  assert.ok(calls.findIndex((c) => c[0] === 'LMSCommit') > calls.findIndex((c) => c[1] === 'cmi.core.score.raw'));

  // The reference pasted in: 100 and passed, the attempt in suspend_data, a commit.
  await write(frame, RIGHT);
  calls = await check(page, frame);
  set = setOf(calls);
  assert.equal(set['cmi.core.score.raw'], '100');
  assert.equal(set['cmi.core.lesson_status'], 'passed');
  assert.deepEqual(calls.at(-1), ['LMSCommit', '']);
  assert.equal(attemptIn(set['cmi.suspend_data']).source, RIGHT);
  await frame.locator('html').evaluate(() => window.scrollTo(0, 0));
  await page.screenshot({ path: path.join(root, 'docs/screenshots/scorm-lms.png') });

  // Reloading the launch: the session ends (suspend, commit, finish), a new one starts and
  // the attempt comes back.
  const mark = await page.evaluate(() => window.calls.length);
  await page.locator('#sco').evaluate((f) => f.contentWindow.location.reload());
  frame = await activity(page);
  await frame.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.waitForFunction((n) => window.calls.slice(n).some((c) => c[1] === 'cmi.suspend_data' && c[0] === 'LMSGetValue'), mark);
  calls = await page.evaluate((n) => window.calls.slice(n), mark);
  const names = calls.map((c) => c[0]);
  const finish = names.indexOf('LMSFinish');
  assert.ok(finish > 0, 'LMSFinish on unload');
  assert.ok(names.lastIndexOf('LMSCommit', finish) > 0, 'a commit before the finish');
  assert.deepEqual(calls.find((c) => c[1] === 'cmi.core.exit'), ['LMSSetValue', 'cmi.core.exit', 'suspend']);
  assert.match(calls.find((c) => c[1] === 'cmi.core.session_time')[2], /^\d{4}:\d{2}:\d{2}\.\d{2}$/);
  assert.ok(names.indexOf('LMSInitialize') > finish, 'the new launch initializes after the old one finished');
  assert.equal(await frame.getByRole('textbox', { name: 'ST source' }).inputValue(), RIGHT);
  await context.close();
  assert.deepEqual(errors, []);
});

test('SCORM 1.2 on another computer: the attempt comes from suspend_data; LMS errors and a too big attempt are shown', async () => {
  const errors = [];
  const project = {
    schema: 1, name: 'Exercise: Start/stop motor latch',
    source: RIGHT.replace('(* Reference', '(* Kept by the LMS. Reference'),
    settings: { cycle_ms: 10, traced: [], breakpoints: [] },
  };
  const seed = `p=${deflateRawSync(Buffer.from(JSON.stringify(project))).toString('base64url')}`;
  const { context, page } = await fresh(errors, seed);
  await page.goto(`${server.url}lms12.html`);
  const frame = await activity(page);
  const editor = frame.getByRole('textbox', { name: 'ST source' });
  await frame.getByText('Your attempt kept by the course is open.').waitFor();
  assert.match(await editor.inputValue(), /Kept by the LMS/);

  // The LMS refuses the score: the page says so in its banner, and nothing is thrown.
  await page.evaluate(() => { window.refuse['cmi.core.score.raw'] = ['405', 'Incorrect Data Type']; });
  await check(page, frame);
  await frame.getByRole('alert').filter({ hasText: 'The course (LMS) did not accept cmi.core.score.raw: 405 Incorrect Data Type' }).waitFor();
  await page.evaluate(() => { window.refuse = {}; });

  // An attempt too big for SCORM 1.2's 4,096 characters: the score goes, the page says
  // why the attempt cannot be kept, and the LMS keeps the last one that fitted.
  let x = 7;
  const hex = Array.from({ length: 8000 }, () => { x = (Math.imul(x, 1103515245) + 12345) >>> 0; return ((x >>> 24) & 15).toString(16); }).join('');
  await write(frame, RIGHT.replace('END_PROGRAM', `(* ${hex} *)\nEND_PROGRAM`));
  const calls = await check(page, frame);
  assert.equal(setOf(calls)['cmi.core.score.raw'], '100');
  assert.equal(setOf(calls)['cmi.suspend_data'], undefined, 'not sent');
  await frame.getByRole('alert').filter({ hasText: /Your attempt is too big for the course to keep \(\d+ characters compressed; SCORM 1\.2 keeps 4,096\)/ }).waitFor();
  assert.match(attemptIn(await page.evaluate(() => window.cmi['cmi.suspend_data'])).source, /Kept by the LMS/);
  await context.close();
  assert.deepEqual(errors, []);
});

test('SCORM 2004: scaled score, success and completion, Commit after each, Terminate on unload', async () => {
  const errors = [];
  const { context, page } = await fresh(errors);
  await page.goto(`${server.url}lms2004.html`);
  const frame = await activity(page);
  assert.equal(await frame.locator('html').getAttribute('data-lms'), 'scorm-2004');
  assert.deepEqual((await page.evaluate(() => window.calls))[0], ['Initialize', '']);
  let calls = await check(page, frame);
  let set = setOf(calls);
  assert.equal(set['cmi.score.scaled'], '0.3333');
  assert.equal(set['cmi.score.raw'], '33.33');
  assert.equal(set['cmi.success_status'], 'failed');
  assert.equal(set['cmi.completion_status'], 'incomplete');
  assert.deepEqual(calls.at(-1), ['Commit', '']);
  await write(frame, RIGHT);
  calls = await check(page, frame);
  set = setOf(calls);
  assert.equal(set['cmi.score.scaled'], '1.0000');
  assert.equal(set['cmi.score.raw'], '100');
  assert.equal(set['cmi.success_status'], 'passed');
  assert.equal(set['cmi.completion_status'], 'completed');
  assert.deepEqual(calls.at(-1), ['Commit', '']);
  // Leaving the activity: suspend, Commit, Terminate.
  const mark = await page.evaluate(() => window.calls.length);
  await page.locator('#sco').evaluate((f) => { f.src = 'about:blank'; });
  await page.waitForFunction((n) => window.calls.slice(n).some((c) => c[0] === 'Terminate'), mark);
  calls = await page.evaluate((n) => window.calls.slice(n), mark);
  assert.deepEqual(calls.find((c) => c[1] === 'cmi.exit'), ['SetValue', 'cmi.exit', 'suspend']);
  assert.match(calls.find((c) => c[1] === 'cmi.session_time')[2], /^PT\d+H\d+M\d+\.\d{2}S$/);
  assert.deepEqual(calls.at(-1), ['Terminate', '']);
  assert.equal(calls.at(-2)[0], 'Commit');
  await context.close();
  assert.deepEqual(errors, []);
});

test('with no LMS the launch is a plain exercise', async () => {
  const errors = [];
  const { context, page } = await fresh(errors);
  await page.goto(`${server.url}pkg/${launchHref}`);
  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  assert.equal(await page.locator('html').getAttribute('data-lms'), null);
  assert.ok(await page.getByRole('button', { name: 'Exercises', exact: true }).isVisible());
  await page.getByRole('button', { name: 'Check', exact: true }).click();
  await page.getByRole('region', { name: 'Report' }).getByText(/^Score 1 of 3/).waitFor();
  await context.close();
  assert.deepEqual(errors, []);
});
