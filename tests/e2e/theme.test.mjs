// The colour theme (issue 34): `System` follows the browser's colour scheme, the header's
// `Theme` switch picks Light or Dark at once (no reload) and keeps the choice in local
// storage; the diagrams use the theme's colours. Screenshots of the ST, ladder and Petri
// views and of an exercise with a failed Check, in both themes, on a laptop (1280 px), a
// tablet (768 px) and a phone (390 px): docs/screenshots/theme-*.png.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { mkdirSync } from 'node:fs';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';
import { NO_SEAL } from './setup.mjs';

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
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  return { page, errors };
}

/** A phone (issue 34) folds the header's actions into `Menu`: opened first there. */
async function openMenu(page) {
  const menu = page.getByRole('button', { name: 'Menu', exact: true });
  if (await menu.isVisible() && (await menu.getAttribute('aria-expanded')) !== 'true') await menu.click();
}

/** A phone shows one pane at a time: its tab (`Program`, `Simulation`, `Exercise`) first. */
async function showPane(page, name) {
  const tab = page.getByRole('tab', { name, exact: true });
  if (await tab.isVisible()) await tab.click();
}

async function openExample(page, title) {
  await openMenu(page);
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: title });
  await page.getByRole('alert').filter({ hasText: `Opened the example “${title}”` }).waitFor();
}

/** The computed colour of `selector`'s `property`, as `rgb(…)`. */
const colour = (page, selector, property) =>
  page.locator(selector).first().evaluate((el, p) => getComputedStyle(el)[p], property);

/** Relative luminance of an `rgb(r, g, b)` colour (0 black … 1 white). */
function luminance(rgb) {
  const [r, g, b] = rgb.match(/\d+(\.\d+)?/g).slice(0, 3).map(Number).map((c) => {
    const s = c / 255;
    return s <= 0.03928 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
  });
  return 0.2126 * r + 0.7152 * g + 0.0722 * b;
}

test('System follows the colour scheme; Dark and Light apply at once and are kept after a reload', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, colorScheme: 'dark' });
  const { page, errors } = await openApp(context);
  const theme = page.getByRole('combobox', { name: 'Theme' });
  assert.deepEqual(await theme.locator('option').allTextContents(), ['System', 'Light', 'Dark']);
  assert.equal(await theme.inputValue(), 'system', 'System is the default');
  assert.ok(luminance(await colour(page, 'html', 'backgroundColor')) < 0.1, 'a dark system gets the dark page');

  await openExample(page, 'Ladder latch');
  const wire = 'svg[aria-label="Rung 1"] .ld-wire:not(.powered)';
  await page.locator(wire).first().waitFor({ state: 'attached' });
  assert.ok(luminance(await colour(page, wire, 'stroke')) > 0.2, 'the rung wires are light on the dark canvas');

  // Light on a dark system: at once, with no reload (the page keeps its state).
  let reloaded = false;
  page.on('framenavigated', () => { reloaded = true; });
  await theme.selectOption({ label: 'Light' });
  await page.waitForFunction(() => document.documentElement.dataset.theme === 'light');
  assert.ok(luminance(await colour(page, 'html', 'backgroundColor')) > 0.8, 'Light wins over the dark system');
  assert.ok(luminance(await colour(page, wire, 'stroke')) < 0.2, 'the wires are dark on the light canvas');
  assert.equal(reloaded, false, 'no reload');
  assert.equal(await page.evaluate(() => localStorage.getItem('plc-trainer/v1/theme')), 'light');

  await page.reload();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  assert.equal(await page.getByRole('combobox', { name: 'Theme' }).inputValue(), 'light', 'kept after a reload');
  assert.equal(await page.evaluate(() => document.documentElement.dataset.theme), 'light');

  // Back to System: the choice is forgotten and the system's scheme applies again.
  await page.getByRole('combobox', { name: 'Theme' }).selectOption({ label: 'System' });
  await page.waitForFunction(() => !document.documentElement.hasAttribute('data-theme'));
  assert.equal(await page.evaluate(() => localStorage.getItem('plc-trainer/v1/theme')), null);
  assert.ok(luminance(await colour(page, 'html', 'backgroundColor')) < 0.1);
  assert.deepEqual(errors, []);
  await context.close();
});

test('Dark on a light system colours the editors, the diagrams and the timeline', async () => {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, colorScheme: 'light' });
  const { page, errors } = await openApp(context);
  await page.getByRole('combobox', { name: 'Theme' }).selectOption({ label: 'Dark' });
  await page.waitForFunction(() => document.documentElement.dataset.theme === 'dark');
  assert.ok(luminance(await colour(page, 'html', 'backgroundColor')) < 0.1);
  assert.ok(luminance(await colour(page, '.ed-frame', 'backgroundColor')) < 0.1, 'the ST editor is dark');
  assert.ok(luminance(await colour(page, 'body', 'color')) > 0.6, 'the text is light');
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await page.locator('svg.timeline-chart .tl-bg').waitFor();
  assert.ok(luminance(await colour(page, 'svg.timeline-chart .tl-bg', 'fill')) < 0.1, 'the timeline is dark');
  await openExample(page, 'Weighing (concurrent Petri net)');
  await page.locator('.pn-circle').first().waitFor();
  assert.ok(luminance(await colour(page, '.pn-circle', 'stroke')) > 0.3, 'the places are outlined in light');
  assert.ok(luminance(await colour(page, '.pn-circle', 'fill')) < 0.1, 'and filled dark');
  assert.deepEqual(errors, []);
  await context.close();
});

// A laptop, a tablet in portrait and a phone (the last two with touch).
const SIZES = { 1280: { width: 1280, height: 800 }, 768: { width: 768, height: 1024 }, 390: { width: 390, height: 844 } };
// Each view: how to reach it, and what the screenshot shows (scrolled to, as a person would).
const SHOWN = { st: '.app-header', ladder: '.ld-rung', petri: '.pn-net', exercise: '.report-scenario.failed' };
const VIEWS = {
  st: async () => {},
  ladder: async (page) => {
    await openExample(page, 'Ladder latch');
    await page.getByRole('img', { name: 'Coil Motor: OFF' }).waitFor();
    await showPane(page, 'Simulation');
    await page.getByRole('button', { name: 'Run', exact: true }).click();
    await showPane(page, 'Program');
    await page.getByRole('region', { name: 'Ladder diagram Latch' }).getByRole('button', { name: 'Contact Start' }).click();
    await page.getByRole('img', { name: 'Coil Motor: ON' }).waitFor();
  },
  petri: async (page) => {
    await openExample(page, 'Weighing (concurrent Petri net)');
    await page.locator('.pn-place').first().waitFor();
    await showPane(page, 'Simulation');
    await page.getByRole('button', { name: 'Step', exact: true }).click();
    await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
    await page.getByRole('button', { name: 'Step', exact: true }).click();
    await showPane(page, 'Program');
    await page.locator('.pn-place[data-tokens="1"]').first().waitFor();
  },
  exercise: async (page) => {
    await openMenu(page);
    await page.getByRole('button', { name: 'Exercises', exact: true }).click();
    await page.locator('.catalogue-item[data-exercise="latch"] button').first().click();
    await page.getByRole('region', { name: 'Exercise' }).waitFor({ state: 'attached' });
    await showPane(page, 'Program');
    await page.getByRole('textbox', { name: 'ST source' }).fill(NO_SEAL);
    await page.waitForTimeout(400);
    await showPane(page, 'Exercise');
    await page.getByRole('button', { name: 'Check', exact: true }).click();
    await page.locator('.report-scenario.failed').first().waitFor();
  },
};

for (const [width, viewport] of Object.entries(SIZES)) {
  for (const scheme of ['light', 'dark']) {
    test(`screenshots: the ST, ladder and Petri views and an exercise at ${width} px, ${scheme}`, async () => {
      for (const [name, open] of Object.entries(VIEWS)) {
        const context = await browser.newContext({ viewport, colorScheme: scheme, hasTouch: width !== '1280', isMobile: width === '390' });
        const { page, errors } = await openApp(context);
        await open(page);
        await page.locator(SHOWN[name]).first().evaluate((el) => el.scrollIntoView({ block: 'start' }));
        await page.waitForTimeout(500);
        await page.screenshot({ path: path.join(shots, `theme-${name}-${width}-${scheme}.png`) });
        assert.deepEqual(errors, []);
        await context.close();
      }
    });
  }
}
