// What a student does, end to end, against the release build in dist/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { mkdirSync } from 'node:fs';
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

const LATCH = `PROGRAM Latch
VAR_INPUT
    Start : BOOL; (* start button *)
    Stop : BOOL;  (* stop button *)
END_VAR
VAR_OUTPUT
    Motor : BOOL; (* motor contactor *)
END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
`;

const DELAYED_LAMP = `PROGRAM Delay
VAR_INPUT Switch : BOOL; END_VAR
VAR_OUTPUT Lamp : BOOL; END_VAR
VAR Timer : TON; END_VAR
Timer(IN := Switch, PT := T#100ms);
Lamp := Timer.Q;
END_PROGRAM
`;

async function openApp(context, url = server.url) {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { page, errors };
}

async function typeProgram(page, text) {
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await editor.fill(text);
  // The check is debounced; the I/O panel appears once the program compiles.
  await page.waitForTimeout(600);
}

test('a start/stop latch runs: Start turns the motor on, Stop turns it off', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const { page, errors } = await openApp(context);
  await page.getByRole('button', { name: 'New project' }).click();
  await typeProgram(page, LATCH);
  for (const name of ['Start', 'Stop', 'Motor']) {
    await page.getByRole('checkbox', { name: `Chart ${name}` }).check();
  }
  // Pressing Run starts the recording; its row's room is kept, so the inputs stay where
  // the pointer is (a click right after Run must not land beside Start).
  const inputsTop = () => page.getByRole('region', { name: 'Inputs and outputs' }).evaluate((e) => e.getBoundingClientRect().top);
  // A person sees Run before pressing it (a click scrolls it into view first).
  const run = page.getByRole('button', { name: 'Run', exact: true });
  await run.scrollIntoViewIfNeeded();
  const before = await inputsTop();
  await run.click();
  await page.getByRole('slider', { name: 'Recorded scan' }).waitFor();
  assert.equal(await inputsTop(), before, 'the inputs do not move when Run is pressed');
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor({ timeout: 5000 });
  await page.getByRole('checkbox', { name: 'Start', exact: true }).uncheck();
  await page.waitForTimeout(200);
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor({ timeout: 5000 });
  await page.getByRole('checkbox', { name: 'Stop', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: OFF' }).waitFor({ timeout: 5000 });
  // The README's screenshot is this page, taken from the real app.
  await page.getByRole('checkbox', { name: 'Stop', exact: true }).uncheck();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor({ timeout: 5000 });
  await page.waitForTimeout(800);
  mkdirSync(path.join(root, 'docs'), { recursive: true });
  await page.screenshot({ path: path.join(root, 'docs/screenshot.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});

test('stepping a TON shows the lamp come on after the preset and draws the timeline', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  await page.getByRole('button', { name: 'New project' }).click();
  await typeProgram(page, DELAYED_LAMP);
  await page.getByRole('checkbox', { name: 'Chart Switch' }).check();
  await page.getByRole('checkbox', { name: 'Chart Lamp' }).check();
  await page.getByRole('checkbox', { name: 'Switch', exact: true }).check();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  for (let i = 0; i < 10; i++) await step.click();
  await page.getByRole('img', { name: 'Lamp: OFF' }).waitFor();
  await step.click();
  await page.getByRole('img', { name: 'Lamp: ON' }).waitFor();
  const chart = page.getByRole('img', { name: 'Timeline chart' });
  await chart.waitFor();
  assert.ok((await chart.locator('polyline, path').count()) >= 2, 'the timeline draws both lanes');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a share link opened in a fresh browser reproduces the project', async () => {
  const context = await browser.newContext();
  const { page } = await openApp(context);
  await page.getByRole('button', { name: 'New project' }).click();
  await typeProgram(page, DELAYED_LAMP);
  await page.getByRole('button', { name: 'Share' }).click();
  const link = await page.getByRole('textbox', { name: 'Share link' }).inputValue();
  assert.match(link, /#p=/);
  await context.close();

  const fresh = await browser.newContext();
  const { page: other, errors } = await openApp(fresh, link);
  const text = await other.getByRole('textbox', { name: 'ST source' }).inputValue();
  assert.equal(text, DELAYED_LAMP);
  assert.deepEqual(errors, []);
  await fresh.close();
});

test('a reload keeps the project', async () => {
  const context = await browser.newContext();
  const { page } = await openApp(context);
  await page.getByRole('button', { name: 'New project' }).click();
  await typeProgram(page, LATCH.replace('Latch', 'KeptAfterReload'));
  await page.waitForTimeout(500);
  await page.reload();
  const text = await page.getByRole('textbox', { name: 'ST source' }).inputValue();
  assert.match(text, /KeptAfterReload/);
  await context.close();
});

test('a corrupt share link shows a message and loses nothing', async () => {
  const context = await browser.newContext();
  const { page } = await openApp(context);
  await typeProgram(page, LATCH.replace('Latch', 'MyWork'));
  await page.waitForTimeout(500);
  await page.goto(`${server.url}#p=this-is-not-a-project`);
  await page.reload();
  await page.getByRole('alert').filter({ hasText: 'damaged' }).waitFor();
  const text = await page.getByRole('textbox', { name: 'ST source' }).inputValue();
  assert.match(text, /MyWork/);
  await context.close();
});

test('while stepping, the active CASE branch is lit in the editor', async () => {
  const context = await browser.newContext();
  const { page, errors } = await openApp(context);
  await page.getByRole('button', { name: 'New project' }).click();
  await typeProgram(page, `PROGRAM Steps
VAR p : INT := 1; END_VAR
CASE p OF
    1: p := 2;
    2: p := 1;
END_CASE;
END_PROGRAM
`);
  const band = page.locator('.ed-active');
  assert.equal(await band.count(), 0);
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await band.first().waitFor();
  const first = await band.first().getAttribute('style');
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await page.waitForFunction((prev) => document.querySelector('.ed-active')?.getAttribute('style') !== prev, first);
  assert.deepEqual(errors, []);
  await context.close();
});
