// The page by keyboard alone (issue 34): the ST editor is no trap (Tab moves on unless the
// student turns Tab indenting on with Ctrl+M), a skip link leads to the simulation, and
// Run and an input are reached and operated with keys to run the start/stop latch.
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

/** What has the focus: its tag, type, accessible label (aria-label or text) and value. */
function focused(page) {
  return page.evaluate(() => {
    const e = document.activeElement;
    if (!e) return { tag: '', label: '' };
    const label = (e.getAttribute('aria-label') || e.textContent || '').trim();
    return { tag: e.tagName.toLowerCase(), type: e.getAttribute('type') || '', label, value: e.value ?? null };
  });
}

/** Presses Tab until `wanted` (a test of `focused`, or a locator) has the focus; returns
 * how many presses it took. */
async function tabUntil(page, wanted, limit = 80) {
  const holds = typeof wanted === 'function'
    ? async () => wanted(await focused(page))
    : () => wanted.evaluate((e) => e === document.activeElement);
  for (let n = 1; n <= limit; n++) {
    await page.keyboard.press('Tab');
    if (await holds()) return n;
  }
  throw new Error(`not reached within ${limit} Tabs; focus is on ${JSON.stringify(await focused(page))}`);
}

const isEditor = (f) => f.tag === 'textarea' && f.label === 'ST source';

test('by keyboard alone: Tab enters the ST editor and leaves it with the code unchanged, then reaches Run and an input and runs the latch', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await editor.waitFor();
  const before = await editor.inputValue();
  assert.match(before, /Motor := \(Start OR Motor\) AND NOT Stop;/, 'a new project is the latch');

  await tabUntil(page, isEditor);
  await page.getByText('Tab moves focus (Ctrl+M: Tab indents)').waitFor();
  await page.keyboard.press('Tab');
  assert.ok(!isEditor(await focused(page)), 'Tab leaves the editor');
  assert.equal(await editor.inputValue(), before, 'the code is unchanged');

  await tabUntil(page, page.getByRole('button', { name: 'Run', exact: true }));
  await page.keyboard.press('Enter');
  await tabUntil(page, page.getByRole('checkbox', { name: 'Start', exact: true }));
  await page.keyboard.press('Space');
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor();
  await page.keyboard.press('Space');
  // Released, the motor holds itself.
  await page.waitForTimeout(200);
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor();
  await tabUntil(page, page.getByRole('checkbox', { name: 'Stop', exact: true }));
  await page.keyboard.press('Space');
  await page.getByRole('img', { name: 'Motor: OFF' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('the first Tab offers Skip to simulation, which leads straight to Run', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.keyboard.press('Tab');
  assert.deepEqual(
    [(await focused(page)).label, await page.getByRole('link', { name: 'Skip to simulation' }).isVisible()],
    ['Skip to simulation', true],
  );
  await page.keyboard.press('Enter');
  assert.equal(await page.evaluate(() => document.activeElement?.id), 'simulation');
  assert.equal(new URL(page.url()).hash, '', 'the address keeps no fragment (a share link lives there)');
  const presses = await tabUntil(page, page.getByRole('button', { name: 'Run', exact: true }), 5);
  assert.ok(presses <= 5);
  await context.close();
});

test('Ctrl+M turns Tab indenting on and off, and the choice is kept', async () => {
  const context = await browser.newContext();
  const page = await context.newPage();
  await page.goto(server.url);
  const editor = page.getByRole('textbox', { name: 'ST source' });
  await editor.waitFor();
  const before = await editor.inputValue();
  await editor.focus();
  await page.keyboard.press('Control+Home');
  await page.keyboard.press('Control+m');
  await page.getByText('Tab indents (Ctrl+M: Tab moves focus; Escape, then Tab leaves)').waitFor();
  await page.keyboard.press('Tab');
  assert.ok(isEditor(await focused(page)), 'Tab indents: the focus stays');
  assert.equal(await editor.inputValue(), `    ${before}`);
  await page.keyboard.press('Shift+Tab');
  assert.equal(await editor.inputValue(), before);
  // Escape, then Tab still leaves while Tab indents.
  await page.keyboard.press('Escape');
  await page.keyboard.press('Tab');
  assert.ok(!isEditor(await focused(page)));
  // Kept in this browser.
  await page.reload();
  await editor.waitFor();
  await page.getByText('Tab indents (Ctrl+M: Tab moves focus; Escape, then Tab leaves)').waitFor();
  await editor.focus();
  await page.keyboard.press('Control+m');
  await page.getByText('Tab moves focus (Ctrl+M: Tab indents)').waitFor();
  await page.keyboard.press('Tab');
  assert.ok(!isEditor(await focused(page)));
  assert.equal(await editor.inputValue(), before);
  await context.close();
});
