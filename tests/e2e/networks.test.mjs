// Network POUs (issue 16): an LD network with no left rail and an FBD network, imported
// from PLCopen XML as OpenPLC Editor writes them, are drawn at the file's own positions and
// run with their values on the drawing.
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

const v = (name, type) => `<variable name="${name}"><type><${type}/></type></variable>`;

/** A PLCopen project of one PROGRAM with the interface and the body given. */
function project(name, program, iface, body) {
  return `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="lab" productName="OpenPLC" productVersion="1" creationDateTime="2024-03-01T10:00:00"/>
  <contentHeader name="${name}"><coordinateInfo><fbd><scaling x="10" y="10"/></fbd><ld><scaling x="10" y="10"/></ld><sfc><scaling x="10" y="10"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="${program}" pouType="program">
      <interface>${iface}</interface>
      <body>${body}</body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="Config0"><resource name="Res0">
    <task name="task0" priority="0" interval="T#20ms"><pouInstance name="inst0" typeName="${program}"/></task>
  </resource></configuration></configurations></instances>
</project>`;
}

// No left rail at all, as OpenPLC lets students draw: the variable box A feeds an AND block
// FBD-style, the variable box C powers the contact B, and the AND drives the coil Y.
const RAILLESS = project('Railless', 'Mixer',
  `<inputVars>${v('A', 'BOOL')}${v('B', 'BOOL')}${v('C', 'BOOL')}</inputVars><outputVars>${v('Y', 'BOOL')}</outputVars>`,
  `<LD>
    <inVariable localId="1" height="30" width="40"><position x="60" y="60"/><connectionPointOut><relPosition x="40" y="15"/></connectionPointOut><expression>A</expression></inVariable>
    <inVariable localId="2" height="30" width="40"><position x="20" y="135"/><connectionPointOut><relPosition x="40" y="15"/></connectionPointOut><expression>C</expression></inVariable>
    <contact localId="3" height="20" width="21" negated="false"><position x="90" y="140"/><connectionPointIn><relPosition x="0" y="10"/><connection refLocalId="2"><position x="90" y="150"/><position x="60" y="150"/></connection></connectionPointIn><connectionPointOut><relPosition x="21" y="10"/></connectionPointOut><variable>B</variable></contact>
    <block localId="4" typeName="AND" height="60" width="70"><position x="240" y="50"/>
      <inputVariables>
        <variable formalParameter="IN1"><connectionPointIn><relPosition x="0" y="25"/><connection refLocalId="1"><position x="240" y="75"/><position x="100" y="75"/></connection></connectionPointIn></variable>
        <variable formalParameter="IN2"><connectionPointIn><relPosition x="0" y="45"/><connection refLocalId="3"><position x="240" y="95"/><position x="170" y="95"/><position x="170" y="150"/><position x="111" y="150"/></connection></connectionPointIn></variable>
      </inputVariables><inOutVariables/>
      <outputVariables><variable formalParameter="OUT"><connectionPointOut><relPosition x="70" y="25"/></connectionPointOut></variable></outputVariables>
    </block>
    <coil localId="5" height="20" width="21" negated="false"><position x="400" y="65"/><connectionPointIn><relPosition x="0" y="10"/><connection refLocalId="4" formalParameter="OUT"><position x="400" y="75"/><position x="310" y="75"/></connection></connectionPointIn><connectionPointOut><relPosition x="21" y="10"/></connectionPointOut><variable>Y</variable></coil>
  </LD>`);

// FBD: M := ADD(N, 5), and a TON T1 on Go whose Q is Done.
const FBD = project('Counter', 'Calc',
  `<inputVars>${v('N', 'INT')}${v('Go', 'BOOL')}</inputVars><outputVars>${v('M', 'INT')}${v('Done', 'BOOL')}</outputVars><localVars><variable name="T1"><type><derived name="TON"/></type></variable></localVars>`,
  `<FBD>
    <inVariable localId="1" height="30" width="40"><position x="50" y="40"/><connectionPointOut><relPosition x="40" y="15"/></connectionPointOut><expression>N</expression></inVariable>
    <inVariable localId="2" height="30" width="40"><position x="50" y="90"/><connectionPointOut><relPosition x="40" y="15"/></connectionPointOut><expression>5</expression></inVariable>
    <block localId="3" typeName="ADD" height="70" width="70" executionOrderId="1"><position x="170" y="30"/>
      <inputVariables>
        <variable formalParameter="IN1"><connectionPointIn><relPosition x="0" y="25"/><connection refLocalId="1"/></connectionPointIn></variable>
        <variable formalParameter="IN2"><connectionPointIn><relPosition x="0" y="75"/><connection refLocalId="2"/></connectionPointIn></variable>
      </inputVariables><inOutVariables/>
      <outputVariables><variable formalParameter="OUT"><connectionPointOut><relPosition x="70" y="25"/></connectionPointOut></variable></outputVariables>
    </block>
    <outVariable localId="4" height="30" width="40" executionOrderId="2"><position x="320" y="40"/><connectionPointIn><relPosition x="0" y="15"/><connection refLocalId="3" formalParameter="OUT"/></connectionPointIn><expression>M</expression></outVariable>
    <inVariable localId="5" height="30" width="40"><position x="50" y="190"/><connectionPointOut><relPosition x="40" y="15"/></connectionPointOut><expression>Go</expression></inVariable>
    <inVariable localId="6" height="30" width="60"><position x="30" y="240"/><connectionPointOut><relPosition x="60" y="15"/></connectionPointOut><expression>T#60ms</expression></inVariable>
    <block localId="7" typeName="TON" instanceName="T1" height="70" width="70" executionOrderId="3"><position x="170" y="180"/>
      <inputVariables>
        <variable formalParameter="IN"><connectionPointIn><relPosition x="0" y="25"/><connection refLocalId="5"/></connectionPointIn></variable>
        <variable formalParameter="PT"><connectionPointIn><relPosition x="0" y="75"/><connection refLocalId="6"/></connectionPointIn></variable>
      </inputVariables><inOutVariables/>
      <outputVariables>
        <variable formalParameter="Q"><connectionPointOut><relPosition x="70" y="25"/></connectionPointOut></variable>
        <variable formalParameter="ET"><connectionPointOut><relPosition x="70" y="45"/></connectionPointOut></variable>
      </outputVariables>
    </block>
    <outVariable localId="8" height="30" width="50" executionOrderId="4"><position x="320" y="190"/><connectionPointIn><relPosition x="0" y="15"/><connection refLocalId="7" formalParameter="Q"/></connectionPointIn><expression>Done</expression></outVariable>
  </FBD>`);

async function openApp() {
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor({ state: 'attached' });
  return { context, page, errors };
}

async function importXml(page, name, text) {
  await page.getByLabel('Import project file').setInputFiles({
    name, mimeType: 'application/xml', buffer: Buffer.from(text),
  });
}

/** The x and y the element `id` is drawn at (its first shape's corner). */
async function drawnAt(view, id) {
  const shape = view.locator(`[data-local-id="${id}"]`).locator('rect').first();
  return [Number(await shape.getAttribute('x')), Number(await shape.getAttribute('y'))];
}

test('a rail-less LD network and an FBD network run with live values at the file positions', async () => {
  const { context, page, errors } = await openApp();

  // The LD network has no rail, so it does not fit the rung grid: it stays a network, drawn
  // as the file has it.
  await importXml(page, 'railless.xml', RAILLESS);
  const ld = page.getByRole('region', { name: 'LD network Mixer' });
  await ld.waitFor();
  await page.getByRole('button', { name: 'LD network Mixer' }).waitFor();
  assert.deepEqual(await drawnAt(ld, '4'), [240, 50], 'the AND block at the file position');
  assert.deepEqual(await drawnAt(ld, '1'), [60, 60], 'the variable box A');
  const step = page.getByRole('button', { name: 'Step', exact: true });
  await step.click();
  await ld.getByRole('img', { name: 'Coil Y, off' }).waitFor();
  for (const input of ['A', 'B', 'C']) await page.getByRole('checkbox', { name: input, exact: true }).check();
  await step.click();
  await ld.getByRole('img', { name: 'Coil Y, on' }).waitFor();
  await ld.getByRole('img', { name: 'Contact B, passes power' }).waitFor();
  await ld.getByRole('img', { name: 'Variable A = TRUE' }).waitFor();
  // The wires carry power along the file's own paths.
  assert.equal(await ld.locator('.nw-wire.powered').count(), 4);
  assert.equal(await ld.locator('.nw-wire.powered[d="M240 95 L170 95 L170 150 L111 150"]').count(), 1);
  await page.screenshot({ path: path.join(shots, 'network-ld.png'), fullPage: true });
  await page.getByRole('checkbox', { name: 'B', exact: true }).uncheck();
  await step.click();
  await ld.getByRole('img', { name: 'Coil Y, off' }).waitFor();

  // The FBD network: values beside the pins, the timer's outputs on its block.
  await importXml(page, 'counter.xml', FBD);
  const fbd = page.getByRole('region', { name: 'FBD network Calc' });
  await fbd.waitFor();
  assert.deepEqual(await drawnAt(fbd, '3'), [170, 30]);
  assert.deepEqual(await drawnAt(fbd, '7'), [170, 180]);
  await step.click();
  await fbd.getByRole('img', { name: 'Variable M = 5' }).waitFor();
  // A function's output has no variable: the simulator watches its expression.
  await fbd.getByRole('img', { name: 'Block ADD: OUT = 5' }).waitFor();
  await fbd.getByRole('img', { name: /^Block TON T1: Q = FALSE, ET = T#0s$/ }).waitFor();
  await page.getByRole('checkbox', { name: 'Go', exact: true }).check();
  for (let k = 0; k < 5; k += 1) await step.click();
  await fbd.getByRole('img', { name: /^Block TON T1: Q = TRUE, ET = T#60ms$/ }).waitFor();
  await fbd.getByRole('img', { name: 'Variable Done = TRUE' }).waitFor();
  await page.screenshot({ path: path.join(shots, 'network-fbd.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});

// SFC as OpenPLC Editor draws it: Idle (initial) → [Start] → Run (action N Motor) →
// [NOT Start] → jump to Idle.
const SFC = project('Chart', 'Machine',
  `<inputVars>${v('Start', 'BOOL')}</inputVars><outputVars>${v('Motor', 'BOOL')}</outputVars>`,
  `<SFC>
    <step localId="1" name="Idle" initialStep="true" height="30" width="60"><position x="100" y="40"/><connectionPointOut formalParameter=""><relPosition x="30" y="30"/></connectionPointOut></step>
    <transition localId="2" height="10" width="20"><position x="120" y="100"/><connectionPointIn><relPosition x="10" y="0"/><connection refLocalId="1"><position x="130" y="100"/><position x="130" y="70"/></connection></connectionPointIn><connectionPointOut><relPosition x="10" y="10"/></connectionPointOut><condition><inline name=""><ST><xhtml:p><![CDATA[Start]]></xhtml:p></ST></inline></condition></transition>
    <step localId="3" name="Run" initialStep="false" height="30" width="60"><position x="100" y="140"/><connectionPointIn><relPosition x="30" y="0"/><connection refLocalId="2"><position x="130" y="140"/><position x="130" y="110"/></connection></connectionPointIn><connectionPointOut formalParameter=""><relPosition x="30" y="30"/></connectionPointOut><connectionPointOutAction formalParameter=""><relPosition x="60" y="15"/></connectionPointOutAction></step>
    <actionBlock localId="4" height="30" width="100"><position x="200" y="140"/><connectionPointIn><relPosition x="0" y="15"/><connection refLocalId="3"><position x="200" y="155"/><position x="160" y="155"/></connection></connectionPointIn><action localId="0" qualifier="N"><relPosition x="0" y="0"/><reference name="Motor"/></action></actionBlock>
    <transition localId="5" height="10" width="20"><position x="120" y="200"/><connectionPointIn><relPosition x="10" y="0"/><connection refLocalId="3"><position x="130" y="200"/><position x="130" y="170"/></connection></connectionPointIn><connectionPointOut><relPosition x="10" y="10"/></connectionPointOut><condition><inline name=""><ST><xhtml:p><![CDATA[NOT Start]]></xhtml:p></ST></inline></condition></transition>
    <jumpStep localId="6" targetName="Idle" height="20" width="20"><position x="120" y="240"/><connectionPointIn><relPosition x="10" y="0"/><connection refLocalId="5"><position x="130" y="240"/><position x="130" y="210"/></connection></connectionPointIn></jumpStep>
  </SFC>`);

test('an SFC chart is drawn at the file positions with its active step lit', async () => {
  const { context, page, errors } = await openApp();
  await importXml(page, 'chart.xml', SFC);
  const chart = page.getByRole('region', { name: 'SFC network Machine' });
  await chart.waitFor();
  await page.getByRole('button', { name: 'SFC network Machine' }).waitFor();
  assert.deepEqual(await drawnAt(chart, '1'), [100, 40], 'step Idle at the file position');
  assert.deepEqual(await drawnAt(chart, '3'), [100, 140], 'step Run');
  assert.deepEqual(await drawnAt(chart, '4'), [200, 140], 'its action block');
  await chart.getByRole('img', { name: 'Transition Start' }).waitFor();
  await chart.getByRole('img', { name: 'Actions N Motor' }).waitFor();
  await chart.getByRole('img', { name: 'Jump to step Idle' }).waitFor();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  await step.click();
  await chart.getByRole('img', { name: 'Initial step Idle, active' }).waitFor();
  await chart.getByRole('img', { name: 'Step Run', exact: true }).waitFor();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await step.click();
  await chart.getByRole('img', { name: 'Step Run, active' }).waitFor();
  await chart.getByRole('img', { name: 'Initial step Idle', exact: true }).waitFor();
  assert.equal(await chart.locator('.nw-step.active').count(), 1);
  // The wire out of the active step shows its activity.
  assert.equal(await chart.locator('.nw-wire.powered[d="M130 200 L130 170"]').count(), 1);
  await page.screenshot({ path: path.join(shots, 'network-sfc.png'), fullPage: true });
  await page.getByRole('checkbox', { name: 'Start', exact: true }).uncheck();
  await step.click();
  await step.click();
  await chart.getByRole('img', { name: 'Initial step Idle, active' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});

test('a problem in a network is marked on its element, its entry reveals it, and the POU is renamed and deleted', async () => {
  const { context, page, errors } = await openApp();
  // The output variable writes Lamp9, which the program does not declare.
  // Nothing runs, so the app opens on the ST source; the problem names the element.
  await importXml(page, 'broken.xml', FBD.replace('<expression>Done</expression>', '<expression>Lamp9</expression>'));
  const problem = page.getByRole('button', { name: /^Calc, element localId 8 +E0100 +`Lamp9` is not declared/ });
  await problem.waitFor();
  await page.getByRole('button', { name: /FBD network Calc/ }).getByText('1').waitFor();
  await problem.click();
  const fbd = page.getByRole('region', { name: 'FBD network Calc' });
  await fbd.waitFor();
  await fbd.getByRole('status').filter({ hasText: 'Element localId 8 is marked in red.' }).waitFor();
  assert.equal(await fbd.locator('.nw-el.faulty[data-local-id="8"]').count(), 1);
  assert.equal(await fbd.locator('.nw-el.faulty').count(), 1);
  await fbd.getByRole('img', { name: 'Variable Lamp9' }).waitFor();
  // The POU is renamed and deleted like a ladder POU.
  await fbd.getByRole('button', { name: 'Rename POU' }).click();
  const box = page.getByRole('textbox', { name: 'New POU name' });
  await box.fill('Calc2');
  await box.press('Enter');
  const renamed = page.getByRole('region', { name: 'FBD network Calc2' });
  await renamed.waitFor();
  page.once('dialog', (d) => d.accept());
  await renamed.getByRole('button', { name: 'Delete POU' }).click();
  await page.getByText('Deleted the network POU “Calc2”.').waitFor();
  assert.equal(await page.getByRole('button', { name: /FBD network/ }).count(), 0);
  assert.deepEqual(errors, []);
  await context.close();
});

// A function block drawn in FBD (a TON between Go and Done) with two instances in an ST
// PROGRAM: its view shows the chosen instance's values.
const FB_DOC = `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201" xmlns:xhtml="http://www.w3.org/1999/xhtml">
  <fileHeader companyName="lab" productName="OpenPLC" productVersion="1" creationDateTime="2024-03-01T10:00:00"/>
  <contentHeader name="Delays"><coordinateInfo><fbd><scaling x="10" y="10"/></fbd><ld><scaling x="10" y="10"/></ld><sfc><scaling x="10" y="10"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Delay" pouType="functionBlock">
      <interface><inputVars>${v('Go', 'BOOL')}</inputVars><outputVars>${v('Done', 'BOOL')}</outputVars><localVars><variable name="T"><type><derived name="TON"/></type></variable></localVars></interface>
      <body><FBD>
        <inVariable localId="1" height="30" width="40"><position x="40" y="40"/><connectionPointOut><relPosition x="40" y="15"/></connectionPointOut><expression>Go</expression></inVariable>
        <inVariable localId="2" height="30" width="60"><position x="20" y="90"/><connectionPointOut><relPosition x="60" y="15"/></connectionPointOut><expression>T#40ms</expression></inVariable>
        <block localId="3" typeName="TON" instanceName="T" height="70" width="70"><position x="160" y="30"/>
          <inputVariables>
            <variable formalParameter="IN"><connectionPointIn><relPosition x="0" y="25"/><connection refLocalId="1"/></connectionPointIn></variable>
            <variable formalParameter="PT"><connectionPointIn><relPosition x="0" y="75"/><connection refLocalId="2"/></connectionPointIn></variable>
          </inputVariables><inOutVariables/>
          <outputVariables>
            <variable formalParameter="Q"><connectionPointOut><relPosition x="70" y="25"/></connectionPointOut></variable>
            <variable formalParameter="ET"><connectionPointOut><relPosition x="70" y="45"/></connectionPointOut></variable>
          </outputVariables>
        </block>
        <outVariable localId="4" height="30" width="50"><position x="300" y="40"/><connectionPointIn><relPosition x="0" y="15"/><connection refLocalId="3" formalParameter="Q"/></connectionPointIn><expression>Done</expression></outVariable>
      </FBD></body>
    </pou>
    <pou name="Main" pouType="program">
      <interface><inputVars>${v('Start', 'BOOL')}</inputVars><outputVars>${v('Lamp', 'BOOL')}</outputVars><localVars><variable name="D1"><type><derived name="Delay"/></type></variable><variable name="D2"><type><derived name="Delay"/></type></variable></localVars></interface>
      <body><ST><xhtml:p><![CDATA[D1(Go := Start);
D2(Go := FALSE);
Lamp := D1.Done;]]></xhtml:p></ST></body>
    </pou>
  </pous></types>
  <instances><configurations><configuration name="Config0"><resource name="Res0">
    <task name="task0" priority="0" interval="T#20ms"><pouInstance name="inst0" typeName="Main"/></task>
  </resource></configuration></configurations></instances>
</project>`;

test('a function block network shows the values of the chosen instance', async () => {
  const { context, page, errors } = await openApp();
  await importXml(page, 'delays.xml', FB_DOC);
  await page.getByRole('button', { name: 'FBD network Delay' }).click();
  const fb = page.getByRole('region', { name: 'FBD network Delay' });
  await fb.waitFor();
  const picker = fb.getByRole('combobox', { name: 'Instance' });
  assert.deepEqual(await picker.locator('option').allTextContents(), ['D1', 'D2']);
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  const step = page.getByRole('button', { name: 'Step', exact: true });
  for (let k = 0; k < 3; k += 1) await step.click();
  await fb.getByRole('img', { name: 'Block TON T: Q = TRUE, ET = T#40ms' }).waitFor();
  await fb.getByRole('img', { name: 'Variable Go = TRUE' }).waitFor();
  await picker.selectOption('D2');
  await fb.getByRole('img', { name: 'Block TON T: Q = FALSE, ET = T#0s' }).waitFor();
  await fb.getByRole('img', { name: 'Variable Go = FALSE' }).waitFor();
  assert.deepEqual(errors, []);
  await context.close();
});
