// Accessibility (issue 34): axe-core finds no violation of any impact in every view a
// student or an instructor sees — the ST editor, the ladder editor, the Petri editor, an
// imported network, an SFC chart, a plant scene, the exercise catalogue, an exercise with
// its report after a failed Check, and the problems page — on a laptop (1280 × 800) and a
// phone (390 × 844), in the light and the dark theme. The dark runs follow the system's
// colour scheme (the Theme switch's `System`); one more run picks `Dark` in the switch.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { readFileSync } from 'node:fs';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';
import { NO_SEAL } from './setup.mjs';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const AXE = readFileSync(path.join(root, 'node_modules/axe-core/axe.min.js'), 'utf8');
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

const SIZES = { laptop: { width: 1280, height: 800 }, phone: { width: 390, height: 844 } };

/** Runs axe-core in the page as it is now; returns the violations, one line each. */
async function violations(page) {
  if (!(await page.evaluate(() => 'axe' in window))) await page.addScriptTag({ content: AXE });
  // Transitions and the debounced checks settle before colours are measured.
  await page.waitForTimeout(400);
  const found = await page.evaluate(async () => {
    const result = await window.axe.run(document);
    return result.violations.map((v) => ({
      id: v.id, impact: v.impact, help: v.help,
      nodes: v.nodes.map((n) => ({ target: n.target.join(' '), summary: n.failureSummary })),
    }));
  });
  return found.flatMap((v) => v.nodes.map((n) =>
    `${v.id} (${v.impact}): ${v.help}\n    at ${n.target}\n    ${(n.summary ?? '').replace(/\n/g, '\n    ')}`));
}

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

// An LD network with no left rail (stays a network view) from a PLCopen file.
const NETWORK = `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="lab" productName="OpenPLC" productVersion="1" creationDateTime="2024-03-01T10:00:00"/>
  <contentHeader name="Railless"><coordinateInfo><fbd><scaling x="10" y="10"/></fbd><ld><scaling x="10" y="10"/></ld><sfc><scaling x="10" y="10"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Mixer" pouType="program">
      <interface><inputVars><variable name="A"><type><BOOL/></type></variable><variable name="C"><type><BOOL/></type></variable></inputVars><outputVars><variable name="Y"><type><BOOL/></type></variable></outputVars></interface>
      <body><LD>
        <inVariable localId="1" height="30" width="40"><position x="20" y="135"/><connectionPointOut><relPosition x="40" y="15"/></connectionPointOut><expression>C</expression></inVariable>
        <contact localId="2" height="20" width="21" negated="false"><position x="90" y="140"/><connectionPointIn><relPosition x="0" y="10"/><connection refLocalId="1"><position x="90" y="150"/><position x="60" y="150"/></connection></connectionPointIn><connectionPointOut><relPosition x="21" y="10"/></connectionPointOut><variable>A</variable></contact>
        <coil localId="3" height="20" width="21" negated="false"><position x="200" y="140"/><connectionPointIn><relPosition x="0" y="10"/><connection refLocalId="2"><position x="200" y="150"/><position x="111" y="150"/></connection></connectionPointIn><connectionPointOut><relPosition x="21" y="10"/></connectionPointOut><variable>Y</variable></coil>
      </LD></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="Config0"><resource name="Res0">
    <task name="task0" priority="0" interval="T#20ms"><pouInstance name="inst0" typeName="Mixer"/></task>
  </resource></configuration></configurations></instances>
</project>`;

/** Each view: how a person reaches it from a fresh page. */
const VIEWS = {
  'ST editor': async (context) => {
    const { page, errors } = await openApp(context);
    await showPane(page, 'Simulation');
    await page.getByRole('button', { name: 'Run', exact: true }).click();
    await showPane(page, 'Program');
    return { page, errors };
  },
  'ladder editor': async (context) => {
    const { page, errors } = await openApp(context);
    await openExample(page, 'Ladder latch');
    await page.getByRole('region', { name: 'Ladder diagram Latch' }).waitFor();
    await page.getByRole('img', { name: 'Coil Motor: OFF' }).waitFor();
    return { page, errors };
  },
  'Petri editor': async (context) => {
    const { page, errors } = await openApp(context);
    await openExample(page, 'Weighing (concurrent Petri net)');
    await page.getByRole('region', { name: 'Petri net WeighingConcurrent' }).waitFor();
    await page.getByRole('region', { name: 'Petri net WeighingConcurrent' }).locator('.pn-place').first().waitFor();
    return { page, errors };
  },
  'network view': async (context) => {
    const { page, errors } = await openApp(context);
    await page.getByLabel('Import project file').setInputFiles({
      name: 'railless.xml', mimeType: 'application/xml', buffer: Buffer.from(NETWORK),
    });
    const view = page.getByRole('region', { name: 'LD network Mixer' });
    await view.waitFor();
    await view.getByRole('img', { name: 'Coil Y, off' }).waitFor();
    return { page, errors };
  },
  'SFC chart': async (context) => {
    const { page, errors } = await openApp(context);
    await openMenu(page);
    await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: 'SFC weighing (ST)' });
    await page.getByRole('button', { name: 'SFC chart SfcWeighing' }).click();
    await page.getByRole('region', { name: 'SFC chart SfcWeighing' }).locator('.sfc-step').first().waitFor();
    return { page, errors };
  },
  'plant scene': async (context) => {
    const { page, errors } = await openApp(context);
    await openExample(page, 'Weighing with its plant (Petri net and ST plant)');
    await showPane(page, 'Simulation');
    const scene = page.getByRole('region', { name: 'Plant' });
    await scene.getByRole('img', { name: 'Scale: 0 g' }).waitFor();
    return { page, errors };
  },
  'exercise catalogue': async (context) => {
    const { page, errors } = await openApp(context);
    await openMenu(page);
    await page.getByRole('button', { name: 'Exercises', exact: true }).click();
    await page.getByRole('list', { name: 'Exercise list' }).getByRole('listitem').first().waitFor();
    return { page, errors };
  },
  'exercise page with a report': async (context) => {
    const { page, errors } = await openApp(context);
    await openMenu(page);
    await page.getByRole('button', { name: 'Exercises', exact: true }).click();
    await page.getByRole('list', { name: 'Exercise list' }).getByRole('button', { name: 'Start/stop motor latch' }).click();
    await page.getByRole('region', { name: 'Exercise' }).getByRole('heading', { name: 'Start/stop motor latch' }).waitFor();
    await page.waitForFunction(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'));
    await showPane(page, 'Program');
    await page.getByRole('textbox', { name: 'ST source' }).fill(NO_SEAL);
    await page.waitForTimeout(400);
    await showPane(page, 'Exercise');
    await page.getByRole('button', { name: 'Check', exact: true }).click();
    const report = page.getByRole('region', { name: 'Report' });
    await report.locator('.report-scenario.failed').first().waitFor();
    await page.waitForFunction(() => !document.querySelector('.exercise-actions button.primary')?.disabled);
    return { page, errors };
  },
  'problems page': (context) => problemsPage(context, 'problems.html#E0403'),
  'problems page in Polish': (context) => problemsPage(context, 'problems.pl.html#E0403'),
  'problems page in Czech': (context) => problemsPage(context, 'problems.cs.html#E0403'),
};

async function problemsPage(context, address) {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(new URL(address, server.url).href);
  await page.getByRole('heading').first().waitFor();
  return { page, errors };
}

for (const [size, viewport] of Object.entries(SIZES)) {
  for (const colorScheme of ['light', 'dark']) {
    for (const [view, open] of Object.entries(VIEWS)) {
      test(`axe: ${view} at ${viewport.width} × ${viewport.height} (${size}), ${colorScheme}`, async () => {
        // bypassCSP: the page's policy allows no inline script, and axe-core comes as one.
        const context = await browser.newContext({ viewport, colorScheme, hasTouch: size === 'phone', isMobile: size === 'phone', bypassCSP: true });
        try {
          const { page, errors } = await open(context);
          const found = await violations(page);
          assert.equal(found.length, 0, `${found.length} axe violation(s) in the ${view}:\n  ${found.join('\n  ')}`);
          assert.deepEqual(errors, []);
        } finally {
          await context.close();
        }
      });
    }
  }
}

test('axe: the Theme switch set to Dark on a light system makes the page dark, with no violation', async () => {
  const context = await browser.newContext({ viewport: SIZES.laptop, colorScheme: 'light', bypassCSP: true });
  try {
    const { page, errors } = await openApp(context);
    await openExample(page, 'Ladder latch');
    await page.getByRole('img', { name: 'Coil Motor: OFF' }).waitFor();
    const theme = page.getByRole('combobox', { name: 'Theme' });
    await theme.selectOption({ label: 'Dark' });
    await page.waitForFunction(() => document.documentElement.dataset.theme === 'dark');
    const found = await violations(page);
    assert.equal(found.length, 0, `${found.length} axe violation(s) with Theme Dark:\n  ${found.join('\n  ')}`);
    assert.deepEqual(errors, []);
  } finally {
    await context.close();
  }
});
