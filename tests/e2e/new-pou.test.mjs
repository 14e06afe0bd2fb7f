// POUs made simply (issue 31): `New ladder POU` and `New Petri net POU` open a dialog with a
// free name filled in, checked as it is typed; inside an exercise the new POU declares the
// exercise's interface and becomes the program that runs and is graded.
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

test('the new POU dialog suggests a free name and checks the name as it is typed', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const { page, errors } = await openApp(context);
  const tabsBefore = await page.getByRole('navigation', { name: 'POUs' }).boundingBox();
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  const dialog = page.getByRole('dialog', { name: 'New ladder POU' });
  await dialog.waitFor();
  const name = dialog.getByRole('textbox', { name: 'POU name' });
  const create = dialog.getByRole('button', { name: 'Create' });
  assert.equal(await name.inputValue(), 'Ladder1');
  assert.equal(await page.evaluate(() => document.activeElement?.getAttribute('aria-label')), 'POU name');
  const tabsAfter = await page.getByRole('navigation', { name: 'POUs' }).boundingBox();
  assert.equal(tabsAfter.height, tabsBefore.height, 'the dialog does not push the tabs around');

  const says = async (typed, message) => {
    await name.fill(typed);
    await dialog.getByText(message, { exact: true }).waitFor();
    assert.equal(await create.isDisabled(), true, `Create is disabled for “${typed}”`);
    assert.equal(await name.getAttribute('aria-invalid'), 'true');
  };
  await says('', 'Type a name for the POU.');
  await says('main', 'The project already has a POU named main.');
  await says('IF', 'IF is a keyword of ST: choose another name.');
  await says('TON', 'TON is the name of a standard function block: choose another name.');
  await says('2nd', '“2nd” is not a name: use letters, digits and single underscores, starting with a letter.');
  await page.screenshot({ path: path.join(shots, 'new-pou-dialog.png') });
  await name.fill('Seal');
  assert.equal(await create.isEnabled(), true);
  assert.equal(await name.getAttribute('aria-invalid'), 'false');
  // Escape closes it without adding anything.
  await name.press('Escape');
  await dialog.waitFor({ state: 'hidden' });
  assert.equal(await page.getByRole('button', { name: 'Ladder diagram Seal' }).count(), 0);

  // Enter creates; the next suggestion skips the name taken.
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await name.fill('Seal');
  await name.press('Enter');
  await page.getByRole('region', { name: 'Ladder diagram Seal' }).waitFor();
  await page.getByRole('button', { name: 'New Petri net POU' }).click();
  const net = page.getByRole('dialog', { name: 'New Petri net POU' });
  assert.equal(await net.getByRole('textbox', { name: 'POU name' }).inputValue(), 'Net1');
  await net.getByRole('button', { name: 'Cancel' }).click();
  await net.waitFor({ state: 'hidden' });
  assert.deepEqual(errors, []);
  await context.close();
});

test('in an exercise a new ladder PROGRAM declares the interface and becomes the program that runs', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const { page, errors } = await openApp(context);
  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: 'Start/stop motor latch' }).click();
  await page.getByRole('region', { name: 'Exercise' }).getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  await page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'));

  await page.getByRole('button', { name: 'New ladder POU' }).click();
  const dialog = page.getByRole('dialog', { name: 'New ladder POU' });
  assert.equal(await dialog.getByRole('textbox', { name: 'POU name' }).inputValue(), 'Latch1', 'named after the exercise');
  await dialog.getByText("declares the exercise's interface").waitFor();
  await dialog.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: 'Ladder diagram Latch1' });
  await view.waitFor();
  const decls = await view.getByRole('textbox', { name: 'Declarations' }).inputValue();
  assert.match(decls, /^VAR_INPUT\n    Start : BOOL; \(\* [^*]+ \*\)\n    Stop : BOOL; \(\* [^*]+ \*\)\nEND_VAR\nVAR_OUTPUT\n    Motor : BOOL; \(\* [^*]+ \*\)\nEND_VAR\nVAR\nEND_VAR\n$/);
  // It is the program that runs (and that Check grades), without touching Simulation.
  const chooser = page.getByRole('combobox', { name: 'Program to run' });
  await chooser.waitFor();
  assert.equal(await chooser.inputValue(), 'Latch1');
  await page.getByRole('checkbox', { name: 'Start', exact: true }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});
