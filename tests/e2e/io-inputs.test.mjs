// The inputs panel's number boxes while the program runs: what a student types is held on
// the input, an INT rounded to a whole number, a REAL as typed (the page reads the boxes
// with the browser's own number parser: web/src/dom.rs). The boxes used to be written
// again on every scan of a run, which wiped out what was being typed.
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

const PROGRAM = `PROGRAM Main
VAR_INPUT
    Count : INT;
    Level : REAL;
END_VAR
VAR_OUTPUT
    Twice : REAL;
END_VAR
Twice := Level * 2.0;
END_PROGRAM
`;

/** The table's value of a variable. */
function valueOf(page, name) {
  const vars = page.getByRole('region', { name: 'Variables' });
  return vars.getByRole('row').filter({ has: page.getByRole('rowheader', { name, exact: true }) }).getByRole('cell').nth(3);
}

/** Types `text` into a number box and leaves it, as a student does. */
async function type(page, box, text) {
  const input = page.getByRole('spinbutton', { name: box });
  await input.fill(text);
  await input.press('Tab');
}

test('numbers typed into the inputs are held: an INT rounded, a REAL as typed, a slider limit set', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.getByRole('button', { name: 'New project' }).click();
  await page.getByRole('textbox', { name: 'ST source' }).fill(PROGRAM);
  await page.getByText('No problems found.').waitFor();
  await page.getByRole('button', { name: 'Run', exact: true }).click();

  await type(page, 'Count value', '41.6');
  await valueOf(page, 'Count').filter({ hasText: /^42$/ }).waitFor();
  await type(page, 'Level value', '0.1');
  await valueOf(page, 'Level').filter({ hasText: /^0\.1$/ }).waitFor();
  await valueOf(page, 'Twice').filter({ hasText: /^0\.2$/ }).waitFor();
  await type(page, 'Level value', '-2.5e1');
  await valueOf(page, 'Level').filter({ hasText: /^-25(\.0)?$/ }).waitFor();

  // A slider's limits take numbers too.
  await type(page, 'Level maximum', '250');
  assert.equal(await page.getByRole('slider', { name: 'Level' }).evaluate((s) => s.max), '250');
  assert.deepEqual(errors, []);
  await context.close();
});
