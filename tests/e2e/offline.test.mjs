// Offline and installable (issue 32): after one visit the service worker has the whole
// build, so with the network off the page opens, an example runs, a shipped exercise opens
// and its Check scores, a PLCopen XML file imports, and the ladder and Petri net editors
// (chunks of the app) open; a new deploy is offered with `New version available` and
// `Reload`, and the page then runs the new build only.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { cp, mkdtemp, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let browser;
// Servers to stop at the end, whatever happened (an open server keeps the test file alive).
const servers = [];

before(async () => { browser = await launch(); });
after(async () => {
  await browser?.close();
  for (const s of servers) await s.close();
});

async function serve(dir) {
  const server = await startServer(dir);
  servers.push(server);
  return server;
}

/** Waits until the service worker of the page is active (its install cached the build). */
async function cached(page) {
  return page.evaluate(async () => {
    const registration = await navigator.serviceWorker.ready;
    const worker = registration.active;
    if (worker.state !== 'activated') {
      await new Promise((done) => worker.addEventListener('statechange', () => {
        if (worker.state === 'activated') done();
      }));
    }
    return { state: worker.state, caches: await caches.keys() };
  });
}

const PLCOPEN = `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="x" productName="x" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="Offline import"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Blink" pouType="program"><interface><localVars><variable name="X"><type><BOOL/></type></variable></localVars></interface>
      <body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">X := NOT X;</xhtml></ST></body></pou>
  </pous></types>
  <instances><configurations/></instances>
</project>`;

test('after one visit the trainer opens and works with the network off', async () => {
  const server = await serve(path.join(root, 'dist'));
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  const sw = await cached(page);
  assert.equal(sw.state, 'activated');
  assert.equal(sw.caches.length, 1, `one build is cached: ${sw.caches}`);

  await context.setOffline(true);
  await page.reload();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();

  // An example opens and runs.
  await page.getByRole('combobox', { name: 'Open example' }).selectOption('latch-ladder.plcproj.json');
  await page.getByText('Opened the example').waitFor();
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON' }).first().waitFor({ timeout: 10000 });
  await page.getByRole('button', { name: 'Pause', exact: true }).click();

  // A shipped exercise opens and its Check scores (the exercise worker and its chunk).
  await page.getByRole('button', { name: 'Exercises', exact: true }).click();
  await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: 'Start/stop motor latch' }).click();
  const panel = page.getByRole('region', { name: 'Exercise' });
  await panel.getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
  await page.getByRole('button', { name: 'Check', exact: true }).click();
  await page.getByRole('region', { name: 'Report' }).locator('.report-score').waitFor();
  assert.match(await page.getByRole('region', { name: 'Report' }).locator('.report-score').textContent(), /^Score \d+ of 3/);

  // The ladder and Petri net editors (chunks) open.
  await page.getByRole('button', { name: 'New project' }).click();
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Rungs');
  await page.getByRole('button', { name: 'Create' }).click();
  await page.getByRole('region', { name: 'Ladder diagram Rungs' }).getByRole('grid').first().waitFor();
  await page.getByRole('button', { name: 'New Petri net POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Net');
  await page.getByRole('button', { name: 'Create' }).click();
  await page.getByRole('region', { name: 'Petri net Net' }).getByRole('group', { name: 'Net canvas' }).waitFor();

  // A PLCopen XML file imports (the import worker and its chunk).
  await page.getByLabel('Import project file').setInputFiles({
    name: 'offline.xml', mimeType: 'application/xml', buffer: Buffer.from(PLCOPEN),
  });
  await page.getByText('Imported “Offline import”').waitFor();

  assert.deepEqual(errors, []);
  await context.close();
});

test('a second visit is answered from the cache by the browser itself, the page with a query by the worker', async () => {
  // Chromium's static routing (web/sw.js, `route`): the page at its plain address and the
  // build's files come out of the build's cache without the worker's fetch handler, so a
  // second visit waits neither for the worker to start nor for a round trip through it.
  const server = await serve(path.join(root, 'dist'));
  const context = await browser.newContext();
  const first = await context.newPage();
  await first.goto(server.url);
  await first.getByRole('textbox', { name: 'ST source' }).waitFor();
  await cached(first);
  await first.close();

  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  const looked = await page.evaluate(() => {
    const name = (e) => e.name.split('/').pop() || 'the page';
    const entries = [
      ...performance.getEntriesByType('navigation'),
      ...performance.getEntriesByType('resource').filter((e) => /\.(css|js|wasm)$/.test(e.name)),
    ];
    return entries.map((e) => [name(e), e.workerCacheLookupStart > 0]);
  });
  const names = looked.map(([n]) => n);
  for (const file of ['the page', 'boot.js', 'plc-web.js', 'plc-web_bg.wasm']) {
    assert.ok(names.includes(file), `${file} was asked for: ${names}`);
  }
  const missed = looked.filter(([, router]) => !router).map(([n]) => n);
  assert.deepEqual(missed, [], 'every one answered by the router from the cache');

  // Offline, the page with a query (which the router leaves to the worker) opens too.
  await context.setOffline(true);
  await page.goto(`${server.url}?from=bookmark`);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  const query = await page.evaluate(() => performance.getEntriesByType('navigation')[0].workerCacheLookupStart);
  assert.equal(query, 0, 'the page with a query comes through the fetch handler');
  assert.deepEqual(errors, []);
  await context.close();
});

test('a new deploy is offered with New version available and Reload, then runs alone', async () => {
  // A copy of the site, so that "deploying" a new build does not touch dist/.
  const site = await mkdtemp(path.join(tmpdir(), 'plc-site-'));
  await cp(path.join(root, 'dist'), site, { recursive: true });
  const server = await serve(site);
  const context = await browser.newContext();
  const page = await context.newPage();
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  const before = await cached(page);
  // The page that the worker now controls shows no banner.
  await page.reload();
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  assert.equal(await page.getByText('New version available').count(), 0);

  // A new build: another build id in sw.js (build-web.sh writes it from the files' hash).
  const swFile = path.join(site, 'sw.js');
  const sw = await readFile(swFile, 'utf8');
  const next = sw.replace(/const BUILD = "([0-9a-f]+)"/, 'const BUILD = "$1ff"');
  assert.notEqual(next, sw, 'sw.js names its build');
  await writeFile(swFile, next);

  await page.reload();
  const banner = page.getByRole('status').filter({ hasText: 'New version available' });
  await banner.waitFor();
  // Until Reload, the old build serves the page.
  assert.deepEqual((await cached(page)).caches.length >= 1, true);
  await Promise.all([
    page.waitForEvent('framenavigated'),
    banner.getByRole('button', { name: 'Reload' }).click(),
  ]);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  const after = await page.evaluate(async () => {
    await navigator.serviceWorker.ready;
    return caches.keys();
  });
  assert.equal(after.length, 1, `only the new build is cached: ${after}`);
  assert.notDeepEqual(after, before.caches);
  assert.equal(await page.getByText('New version available').count(), 0);
  await context.close();
  await rm(site, { recursive: true, force: true });
});

test('the app is installable: a manifest with icons, a theme colour and standalone display', async () => {
  const manifest = JSON.parse(await readFile(path.join(root, 'dist', 'manifest.json'), 'utf8'));
  assert.equal(manifest.display, 'standalone');
  assert.match(manifest.theme_color, /^#[0-9a-f]{6}$/i);
  assert.equal(manifest.start_url, './');
  assert.ok(manifest.icons.some((i) => i.sizes === '512x512' && i.type === 'image/png'));
  for (const icon of manifest.icons) await readFile(path.join(root, 'dist', icon.src));
  const html = await readFile(path.join(root, 'dist', 'index.html'), 'utf8');
  assert.match(html, /<link href="?manifest\.json"? rel="?manifest"?>/);
});
