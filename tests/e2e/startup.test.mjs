// The first screen before the engine (issue 32): the checker and the compiler are a chunk
// the page fetches as it starts (`engine`, docs/loading.md), so the editor and the panels
// come first. Until the chunk is here the panels say it is loading (never "No program" or
// "No problems found", which would not be true yet), Run is offered and, pressed, runs
// once the engine has checked the program.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let browser;
let server;

before(async () => {
  browser = await launch();
  server = await startServer(path.join(root, 'dist'));
});
after(async () => {
  await browser?.close();
  await server?.close();
});

/** Holds back every request for `pattern` until `release()`; `asked()` counts them. */
async function holdBack(context, pattern) {
  let release;
  const held = new Promise((resolve) => { release = resolve; });
  let asked = 0;
  await context.route(pattern, async (route) => {
    asked++;
    await held;
    await route.continue();
  });
  return { release, asked: () => asked };
}

/** Adds the ladder PROGRAM `Latch` to the open project and waits until it is stored. */
async function addStoredLadderPou(page) {
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Latch');
  await page.getByRole('combobox', { name: 'POU kind' }).selectOption('PROGRAM');
  await page.getByRole('button', { name: 'Create' }).click();
  await page.getByRole('region', { name: 'Ladder diagram Latch' }).waitFor();
  await page.waitForFunction(() => Object.keys(localStorage).some((k) => {
    const text = k.includes('/project/') ? localStorage.getItem(k) : '';
    return text.includes('"ladder"') && text.includes('Latch');
  }));
}

test('the editor comes before the engine; Run pressed while it loads runs once it is here', async () => {
  // No service worker: every file comes through the network, where the engine's chunk is
  // held back until the test lets it go.
  const context = await browser.newContext({ serviceWorkers: 'block', viewport: { width: 1280, height: 900 } });
  const { release, asked } = await holdBack(context, '**/pack_engine.wasm');
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(server.url);

  const editor = page.getByRole('textbox', { name: 'ST source' });
  await editor.waitFor();
  assert.match(await editor.inputValue(), /PROGRAM Main/, 'the starting project is in the editor');
  await page.getByText('Loading the checker and the simulator…').first().waitFor();
  await page.getByRole('status', { name: 'PLC state: Loading…' }).waitFor();
  assert.equal(await page.getByText('No problems found.').count(), 0, 'no verdict before the check');
  assert.equal(asked(), 1, 'the engine was asked for once, as the page started');

  // Typing works meanwhile; Run is offered and says it waits.
  await editor.press('Control+End');
  await page.keyboard.type('\n(* typed while the engine loads *)');
  assert.match(await editor.inputValue(), /typed while the engine loads/);
  const run = page.getByRole('button', { name: 'Run', exact: true });
  assert.equal(await run.isEnabled(), true);
  await run.click();
  await page.getByRole('alert').filter({ hasText: 'The simulator is loading; it starts as soon as it is ready.' }).waitFor();

  release();
  await page.getByRole('status', { name: 'PLC state: Running' }).waitFor();
  await page.getByText('No problems found.').waitFor();
  assert.equal(await page.getByRole('alert').filter({ hasText: 'The simulator is loading' }).count(), 0, 'the banner went with the wait');
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor();
  assert.equal(asked(), 1, 'fetched once');
  assert.deepEqual(errors, []);
  await context.close();
});

/** Kills the page's renderer, as a crash or a hang the user ends would. */
async function crash(page) {
  const cdp = await page.context().newCDPSession(page);
  cdp.send('Page.crash').catch(() => {});
  await page.waitForEvent('crash');
}

test('a project that stops the page when the engine, come late, checks it is not opened again', async () => {
  const context = await browser.newContext({ serviceWorkers: 'block' });
  let page = await context.newPage();
  await page.goto(server.url);
  await page.getByText('No problems found.').waitFor();
  await page.close();

  // The stored project opens; the engine comes only after the page has run for a while
  // (longer than an opening takes to settle), and the check it then makes stops the page.
  const { release } = await holdBack(context, '**/pack_engine.wasm');
  page = await context.newPage();
  await page.goto(server.url);
  await page.getByText('Loading the checker and the simulator…').first().waitFor();
  await page.waitForTimeout(4000);
  release();
  await page.getByText('No problems found.').waitFor();
  await crash(page);

  page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(server.url);
  await page.getByRole('alert').filter({ hasText: '“My first project” stopped the page the last time it was opened' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('a trap of the app while a project opens counts as the page stopping: the project is not opened again', async () => {
  const context = await browser.newContext({ serviceWorkers: 'block' });
  let page = await context.newPage();
  await page.goto(server.url);
  await page.getByText('No problems found.').waitFor();
  await page.close();

  // The stored project is still opening (the engine held back, so the opening cannot
  // settle) when the app's wasm traps, as a panic does in the release build (it traps at
  // once, with no panic hook); the page is then left as a user leaves it, by reloading.
  const { release } = await holdBack(context, '**/pack_engine.wasm');
  page = await context.newPage();
  await page.goto(server.url);
  await page.getByText('Loading the checker and the simulator…').first().waitFor();
  const trapped = page.waitForEvent('pageerror');
  await page.evaluate(() => setTimeout(() => { throw new WebAssembly.RuntimeError('unreachable'); }));
  await trapped;
  release();
  const errors = [];
  await page.reload();
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.getByRole('alert').filter({ hasText: '“My first project” stopped the page the last time it was opened' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('a view picked while the engine loads stays when the engine comes', async () => {
  const context = await browser.newContext({ serviceWorkers: 'block', viewport: { width: 1280, height: 900 } });
  let page = await context.newPage();
  await page.goto(server.url);
  await page.getByText('No problems found.').waitFor();
  // The project's main view is its ST PROGRAM; it also has a ladder PROGRAM.
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Latch');
  await page.getByRole('combobox', { name: 'POU kind' }).selectOption('PROGRAM');
  await page.getByRole('button', { name: 'Create' }).click();
  await page.getByRole('region', { name: 'Ladder diagram Latch' }).waitFor();
  await page.getByRole('button', { name: 'ST source' }).click();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.waitForFunction(() => (localStorage.getItem('plc-trainer/v1/index') ?? '').length > 0);
  await page.close();

  const { release } = await holdBack(context, '**/pack_engine.wasm');
  page = await context.newPage();
  await page.goto(server.url);
  await page.getByText('Loading the checker and the simulator…').first().waitFor();
  await page.getByRole('button', { name: 'Ladder diagram Latch' }).click();
  // The ladder editor's chunks share code with the engine, which comes in one file: the
  // editor shows once that file is here.
  await page.getByText('Loading the ladder editor…').waitFor();
  release();
  const ladder = page.getByRole('region', { name: 'Ladder diagram Latch' });
  await ladder.waitFor();
  await page.getByText('No problems found.').waitFor();
  await page.getByRole('status', { name: /^PLC state: (Stopped|Paused)$/ }).waitFor();
  assert.equal(await ladder.isVisible(), true, 'the ladder diagram picked stays shown');
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).isVisible(), false);
  await context.close();
});

test('a share link shows that it opens, never another project, until its reader comes', async () => {
  const PROGRAM = 'PROGRAM Shared\nVAR_INPUT Go : BOOL; END_VAR\nVAR_OUTPUT Lamp : BOOL; END_VAR\nLamp := Go;\nEND_PROGRAM\n';
  const sharing = await browser.newContext({ serviceWorkers: 'block' });
  const first = await sharing.newPage();
  await first.goto(server.url);
  await first.getByRole('button', { name: 'New project' }).click();
  await first.getByRole('textbox', { name: 'ST source' }).fill(PROGRAM);
  await first.waitForTimeout(500);
  await first.getByRole('button', { name: 'Share' }).click();
  const link = await first.getByRole('textbox', { name: 'Share link' }).inputValue();
  await sharing.close();

  // A fresh browser opens the link; the link's reader (a chunk) is held back.
  const context = await browser.newContext({ serviceWorkers: 'block' });
  const { release } = await holdBack(context, '**/split_share_reader.wasm');
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(link);
  await page.getByRole('status').filter({ hasText: 'Opening the shared project…' }).waitFor();
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).isVisible(), false, 'no other project to type into meanwhile');
  release();
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await editor.waitFor();
  assert.equal(await editor.inputValue(), PROGRAM);
  assert.deepEqual(errors, []);
  await context.close();
});

test('Run pressed while a share link opens runs the shared project once it is open', async () => {
  const PROGRAM = 'PROGRAM Shared\nVAR n : INT; END_VAR\nn := n + 1;\nEND_PROGRAM\n';
  const sharing = await browser.newContext({ serviceWorkers: 'block' });
  const first = await sharing.newPage();
  await first.goto(server.url);
  await first.getByRole('button', { name: 'New project' }).click();
  await first.getByRole('textbox', { name: 'ST source' }).fill(PROGRAM);
  await first.waitForTimeout(500);
  await first.getByRole('button', { name: 'Share' }).click();
  const link = await first.getByRole('textbox', { name: 'Share link' }).inputValue();
  await sharing.close();

  // A fresh browser opens the link with its reader held back, and Run is pressed meanwhile.
  const context = await browser.newContext({ serviceWorkers: 'block' });
  const { release } = await holdBack(context, '**/split_share_reader.wasm');
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(link);
  await page.getByRole('status').filter({ hasText: 'Opening the shared project…' }).waitFor();
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await page.getByRole('alert').filter({ hasText: 'Opening the project…' }).waitFor();
  assert.equal(await page.getByRole('status', { name: 'PLC state: Running' }).count(), 0, 'nothing runs before the project is open');
  release();
  await page.getByRole('status', { name: 'PLC state: Running' }).waitFor();
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).inputValue(), PROGRAM);
  const vars = page.getByRole('region', { name: 'Variables' });
  await vars.getByRole('rowheader', { name: 'n', exact: true }).waitFor();
  // The shared project keeps running.
  const scans = page.getByLabel('Scan count');
  const before = Number(await scans.textContent());
  await page.waitForFunction((n) => Number(document.querySelector('[aria-label="Scan count"]')?.textContent) > n + 5, before);
  assert.equal(await page.getByRole('alert').filter({ hasText: 'Opening the project…' }).count(), 0, 'the banner went with the wait');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a stored ladder project says it opens until its diagrams\' readers come, then opens whole', async () => {
  const context = await browser.newContext({ serviceWorkers: 'block', viewport: { width: 1280, height: 900 } });
  let page = await context.newPage();
  await page.goto(server.url);
  await page.getByText('No problems found.').waitFor();
  await addStoredLadderPou(page);
  await page.close();

  // The project's ladder POU is read by a chunk the first screen does not hold.
  const { release, asked } = await holdBack(context, '**/split_project_reader.wasm');
  page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(server.url);
  await page.getByRole('status').filter({ hasText: 'Opening the project…' }).waitFor();
  assert.equal(asked(), 1);
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).isVisible(), false, 'no other project to type into meanwhile');
  release();
  // The project opens whole: its ST PROGRAM in the editor, its ladder POU a view away.
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.getByRole('button', { name: 'Ladder diagram Latch' }).click();
  await page.getByRole('region', { name: 'Ladder diagram Latch' }).waitFor();
  await page.getByText('No problems found.').waitFor();
  assert.equal(await page.getByRole('status').filter({ hasText: 'Opening the project…' }).count(), 0);
  // A project with only ST never fetches the readers.
  await page.getByRole('button', { name: 'New project' }).click();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.waitForTimeout(500);
  await page.close();
  assert.deepEqual(errors, []);
  await context.close();

  const fresh = await browser.newContext({ serviceWorkers: 'block' });
  let fetched = 0;
  await fresh.route('**/split_project_reader.wasm', (route) => { fetched++; return route.continue(); });
  page = await fresh.newPage();
  await page.goto(server.url);
  await page.getByText('No problems found.').waitFor();
  await page.reload();
  await page.getByText('No problems found.').waitFor();
  assert.equal(fetched, 0, 'an ST project opens without the diagrams\' readers');
  await fresh.close();
});

test('a project picked while a stored ladder project opens stays open when the readers come', async () => {
  const context = await browser.newContext({ serviceWorkers: 'block', viewport: { width: 1280, height: 900 } });
  let page = await context.newPage();
  await page.goto(server.url);
  await page.getByText('No problems found.').waitFor();
  // Two stored projects: "My first project" (ST only), then a newer one with a ladder POU.
  await page.getByRole('button', { name: 'New project' }).click();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await addStoredLadderPou(page);
  await page.close();

  const { release } = await holdBack(context, '**/split_project_reader.wasm');
  page = await context.newPage();
  await page.goto(server.url);
  await page.getByRole('status').filter({ hasText: 'Opening the project…' }).waitFor();
  // The student picks the ST project meanwhile.
  await page.getByRole('combobox', { name: 'Open project' }).selectOption({ label: 'My first project' });
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  release();
  await page.waitForTimeout(1500);
  assert.equal(await page.locator('.project-name').textContent(), 'My first project');
  assert.equal(await page.getByRole('textbox', { name: 'ST source' }).isVisible(), true);
  assert.equal(await page.getByRole('button', { name: 'Ladder diagram Latch' }).count(), 0, 'the ladder project did not open over it');
  await context.close();
});

const BLINKER = JSON.stringify({
  schema: 1,
  name: 'Blinker',
  source: `PROGRAM Main
VAR_INPUT Start : BOOL; END_VAR
VAR_OUTPUT Motor : BOOL; Lamp : BOOL; END_VAR
VAR Count : INT; END_VAR
Count := Count + 1;
Lamp := NOT Lamp;
Motor := Start;
END_PROGRAM
`,
  settings: { cycle_ms: 10, traced: [], breakpoints: [] },
});

test('Run pressed while an imported file or an example opens runs that project once it is open', async () => {
  // The CI run of 2026-12-07 failed why.test.mjs this way: the starting project has a
  // Motor too, so its variable table was there before the imported file had opened; Run
  // ran the starting project, and the import, done a moment later, stopped it.
  const context = await browser.newContext({ serviceWorkers: 'block', viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(server.url);
  await page.getByText('No problems found.').waitFor();
  const vars = page.getByRole('region', { name: 'Variables' });
  const run = page.getByRole('button', { name: 'Run', exact: true });
  const waiting = page.getByRole('alert').filter({ hasText: 'Opening the project…' });

  const importing = await holdBack(context, '**/split_import_ui.wasm');
  await page.getByLabel('Import project file').setInputFiles({
    name: 'blinker.plcproj.json', mimeType: 'application/json', buffer: Buffer.from(BLINKER),
  });
  await page.getByRole('status').filter({ hasText: 'Opening the project…' }).waitFor();
  await vars.getByRole('rowheader', { name: 'Motor', exact: true }).waitFor();
  await run.click();
  await waiting.waitFor();
  assert.equal(await page.getByRole('status', { name: 'PLC state: Running' }).count(), 0, 'the project about to go does not run');
  importing.release();
  await page.getByRole('status', { name: 'PLC state: Running' }).waitFor();
  await vars.getByRole('rowheader', { name: 'Lamp', exact: true }).waitFor();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  assert.match(await page.getByRole('textbox', { name: 'ST source' }).inputValue(), /Lamp := NOT Lamp/);
  assert.equal(await waiting.count(), 0, 'the banner went with the wait');
  // It keeps running: the import does not stop it.
  const scans = page.getByLabel('Scan count');
  const before = Number(await scans.textContent());
  await page.waitForFunction((n) => Number(document.querySelector('[aria-label="Scan count"]')?.textContent) > n + 5, before);
  await page.getByRole('button', { name: 'Pause', exact: true }).click();

  // An example picked, and Step pressed before it is here: one scan of the example.
  const opening = await holdBack(context, '**/split_examples.wasm');
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: 'Tank with level switches (ST plant)' });
  await page.getByRole('status').filter({ hasText: 'Opening the project…' }).waitFor();
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await waiting.waitFor();
  opening.release();
  await page.getByRole('status', { name: 'PLC state: Paused' }).waitFor();
  await page.getByText('Opened the example').first().waitFor();
  assert.equal(await scans.textContent(), '1');
  assert.doesNotMatch(await page.getByRole('textbox', { name: 'ST source' }).inputValue(), /Lamp := NOT Lamp/);
  assert.deepEqual(errors, []);
  await context.close();
});
