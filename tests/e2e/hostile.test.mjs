// Hostile content stays inert (issue 11): markup and script in project names, comments,
// variable descriptions, ladder and Petri net comments, share links and imported files is
// shown as text; nothing runs, nothing is even attempted (no Content-Security-Policy
// violation), and the page's own code runs under the strict policy in dist/index.html.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { readFile } from 'node:fs/promises';
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

/** Each payload sets `window.__pwned` (or opens a dialog) if it ever runs. */
const PAYLOADS = [
  `<img src=x onerror="window.__pwned='img'">`,
  `<script>window.__pwned='script'</script>`,
  `"><svg onload="window.__pwned='svg'">`,
  `'><iframe src="javascript:parent.__pwned='iframe'"></iframe>`,
  `<a href="javascript:window.__pwned='href'" id=hostile-link>click</a>`,
  `</textarea></code><img src=x onerror=alert(1)>`,
  `<style>body{display:none}</style>`,
  `&lt;b&gt;entity&lt;/b&gt; <b>bold</b>`,
];
const ALL = PAYLOADS.join(' ');

/** A page that records every attempt to run something. */
async function openWatched(context, url = server.url) {
  const page = await context.newPage();
  const trouble = [];
  page.on('pageerror', (e) => trouble.push(`page error: ${e.message}`));
  page.on('dialog', async (d) => { trouble.push(`dialog: ${d.message()}`); await d.dismiss(); });
  page.on('console', (m) => {
    if (/Content.Security.Policy/i.test(m.text())) trouble.push(`CSP: ${m.text()}`);
  });
  await page.addInitScript(() => {
    document.addEventListener('securitypolicyviolation', (e) => {
      window.__violations = (window.__violations ?? 0) + 1;
      console.log(`Content-Security-Policy violation: ${e.violatedDirective} ${e.blockedURI}`);
    });
  });
  await page.goto(url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { page, trouble };
}

async function assertInert(page, trouble) {
  await page.waitForTimeout(500);
  const state = await page.evaluate(() => ({
    pwned: window.__pwned ?? null,
    violations: window.__violations ?? 0,
    injected: document.querySelectorAll('#hostile-link, iframe, body img[src="x"], svg[onload]').length,
    visible: getComputedStyle(document.body).display,
  }));
  assert.deepEqual(state, { pwned: null, violations: 0, injected: 0, visible: 'block' });
  assert.deepEqual(trouble, []);
}

const SOURCE = `PROGRAM Main (* ${ALL} *)
VAR_INPUT
    Start : BOOL; (* ${PAYLOADS[0]} *)
END_VAR
VAR_OUTPUT
    Lamp : BOOL; (* ${PAYLOADS[1]} *)
END_VAR
VAR
    Note : STRING[200] := '${PAYLOADS[2].replaceAll("'", '$27')}';
END_VAR
Lamp := Start;
Lamp := '${PAYLOADS[0]}'; (* a problem whose message quotes markup *)
END_PROGRAM
`;

/** Types into the editor and waits for the debounced check. */
async function typeProgram(page, text) {
  await page.getByRole('textbox', { name: 'ST source' }).fill(text);
  await page.waitForTimeout(700);
}

test('the policy is in the built page and the app runs under it', async () => {
  const html = await readFile(path.join(root, 'dist/index.html'), 'utf8');
  assert.match(html, /<meta http-equiv="Content-Security-Policy" content="default-src 'none'; script-src 'self' 'wasm-unsafe-eval' 'sha256-/);
  const context = await browser.newContext();
  const { page, trouble } = await openWatched(context);
  await page.getByRole('button', { name: 'Run', exact: true }).click();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('img', { name: 'Motor: ON' }).waitFor({ timeout: 5000 });
  await assertInert(page, trouble);
  await context.close();
});

test('markup in names, comments, descriptions, strings and problem messages is shown as text', async () => {
  const context = await browser.newContext();
  const { page, trouble } = await openWatched(context);
  await typeProgram(page, SOURCE);
  // A rename to markup.
  await page.getByRole('button', { name: 'Rename' }).click();
  const nameBox = page.getByRole('textbox', { name: 'Project name' });
  await nameBox.fill(PAYLOADS[0]);
  await nameBox.press('Enter');
  assert.equal(await page.locator('.project-name').innerText(), PAYLOADS[0]);
  // The problem list quotes the source; fix it so the variables panel shows descriptions.
  await typeProgram(page, SOURCE.replace(/^Lamp := '.*$/m, ''));
  await page.getByRole('cell', { name: PAYLOADS[0] }).waitFor();
  await page.getByRole('cell', { name: PAYLOADS[1] }).waitFor();
  await assertInert(page, trouble);

  // The same project through a share link.
  await page.getByRole('button', { name: 'Share' }).click();
  const link = await page.getByRole('textbox', { name: 'Share link' }).inputValue();
  const other = await browser.newContext();
  const shared = await openWatched(other, link);
  assert.equal(await shared.page.locator('.project-name').innerText(), PAYLOADS[0]);
  await shared.page.getByRole('cell', { name: PAYLOADS[1] }).waitFor();
  await assertInert(shared.page, shared.trouble);
  await other.close();
  await context.close();
});

/** Imports `text` as the file `name` through the Import button's file input. */
async function importFile(page, name, text) {
  const dismiss = page.getByRole('button', { name: 'Dismiss' });
  if (await dismiss.count()) await dismiss.click();
  await page.getByLabel('Import project file').setInputFiles({
    name, mimeType: 'application/octet-stream', buffer: Buffer.from(text),
  });
  await page.waitForTimeout(700);
}

test('imported project files, PLCopen XML and PNML carrying markup stay inert', async () => {
  const context = await browser.newContext();
  const { page, trouble } = await openWatched(context);

  // A project file with a ladder POU and a Petri net POU, every comment hostile.
  const ladder = JSON.parse(await readFile(path.join(root, 'examples/latch-ladder.plcproj.json'), 'utf8'));
  ladder.name = PAYLOADS[2];
  for (const rung of ladder.ladder[0].rungs) rung.comment = ALL;
  ladder.ladder[0].declarations = ladder.ladder[0].declarations.replace('(* start button *)', `(* ${PAYLOADS[3]} *)`);
  await importFile(page, `${PAYLOADS[4]}.plcproj.json`, JSON.stringify(ladder));
  // Rung comments are editable text boxes: the markup is their value, as typed.
  const comment = page.getByRole('textbox', { name: 'Comment of rung 1' });
  await comment.waitFor();
  assert.equal(await comment.inputValue(), ALL);
  await assertInert(page, trouble);

  const petri = JSON.parse(await readFile(path.join(root, 'examples/weighing-sequential.plcproj.json'), 'utf8'));
  petri.name = PAYLOADS[5];
  for (const p of petri.petri[0].net.places) p.comment = ALL;
  for (const t of petri.petri[0].net.transitions) t.comment = PAYLOADS[6];
  await importFile(page, 'net.plcproj.json', JSON.stringify(petri));
  assert.match(await page.getByRole('alert').innerText(), /Imported/);
  assert.equal(await page.locator('.project-name').innerText(), PAYLOADS[5]);
  await assertInert(page, trouble);

  // PLCopen XML: markup (escaped, as XML requires) in names and documentation.
  const esc = (s) => s.replaceAll('&', '&amp;').replaceAll('<', '&lt;').replaceAll('>', '&gt;').replaceAll('"', '&quot;');
  const xml = `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="${esc(PAYLOADS[0])}" productName="x" productVersion="1" creationDateTime="2024-01-01T00:00:00"/>
  <contentHeader name="${esc(PAYLOADS[1])}"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program">
      <interface><localVars><variable name="Lamp"><type><BOOL/></type>
        <documentation><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml">${esc(ALL)}</xhtml:p></documentation>
      </variable></localVars></interface>
      <body><ST><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml">(* ${esc(ALL)} *) Lamp := NOT Lamp;</xhtml:p></ST></body>
      <documentation><xhtml:p xmlns:xhtml="http://www.w3.org/1999/xhtml">${esc(ALL)}</xhtml:p></documentation>
    </pou>
  </pous></types>
  <instances><configurations/></instances>
</project>`;
  await importFile(page, 'hostile.xml', xml);
  await page.getByRole('alert').filter({ hasText: '(PLCopen XML)' }).waitFor();
  await assertInert(page, trouble);

  // PNML: markup in the net's, places' and transitions' names.
  const pnml = `<?xml version="1.0" encoding="UTF-8"?>
<pnml xmlns="http://www.pnml.org/version-2009/grammar/pnml">
  <net id="n1" type="http://www.pnml.org/version-2009/grammar/ptnet">
    <name><text>${esc(PAYLOADS[2])}</text></name>
    <page id="pg">
      <place id="a"><name><text>${esc(PAYLOADS[0])}</text></name><initialMarking><text>1</text></initialMarking></place>
      <place id="b"><name><text>${esc(PAYLOADS[1])}</text></name></place>
      <transition id="t"><name><text>${esc(PAYLOADS[3])}</text></name></transition>
      <arc id="a1" source="a" target="t"/><arc id="a2" source="t" target="b"/>
    </page>
  </net>
</pnml>`;
  await importFile(page, `${PAYLOADS[5]}.pnml`, pnml);
  await page.getByRole('alert').filter({ hasText: '(PNML)' }).waitFor();
  await assertInert(page, trouble);
  await context.close();
});
