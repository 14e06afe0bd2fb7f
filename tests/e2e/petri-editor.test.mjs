// The Petri net editor (issue 14): a student draws a net in a new project with the canvas
// tools, sets its marking and guards in the properties panel, sees the generated CASE OF
// code, runs it scan by scan, moves a place and undoes the move.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { readFile } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { execFileSync } from 'node:child_process';
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

/** Client pixels of net point (x, y) on the canvas (through its viewBox and size). */
async function at(canvas, x, y) {
  const box = await canvas.boundingBox();
  const [vx, vy, vw, vh] = (await canvas.getAttribute('viewBox')).split(' ').map(Number);
  return { x: box.x + ((x - vx) * box.width) / vw, y: box.y + ((y - vy) * box.height) / vh };
}

/** The middle of a place's circle or a transition's bar (not of its label). */
async function centre(locator) {
  const shape = locator.locator('.pn-circle, .pn-hit');
  const b = await ((await shape.count()) > 0 ? shape.first() : locator).boundingBox();
  return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
}

test('a three-place cycle drawn in a new project generates CASE code, runs scan by scan, and a move undoes', async () => {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  await page.getByRole('button', { name: 'New Petri net POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Cycle');
  await page.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: 'Petri net Cycle' });
  await view.waitFor();
  const decls = view.getByRole('textbox', { name: 'Declarations' });
  await decls.fill('VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Busy : BOOL;\nEND_VAR\n');
  await decls.press('Tab');
  const canvas = view.getByRole('group', { name: 'Net canvas' });

  // Places and transitions where clicked (snapped to the grid), named in creation order.
  const tool = (name) => view.getByRole('button', { name, exact: true });
  await tool('Place').click();
  assert.equal(await tool('Place').getAttribute('aria-pressed'), 'true');
  for (const [x, y] of [[100, 100], [300, 100], [300, 260]]) {
    const p = await at(canvas, x, y);
    await page.mouse.click(p.x, p.y);
  }
  await tool('Transition').click();
  for (const [x, y] of [[200, 100], [300, 180], [200, 260]]) {
    const p = await at(canvas, x, y);
    await page.mouse.click(p.x, p.y);
  }
  const place = (id) => view.locator(`.pn-place[data-id="${id}"]`);
  const transition = (id) => view.locator(`.pn-transition[data-id="${id}"]`);
  for (const id of ['P1', 'P2', 'P3']) await place(id).waitFor();
  for (const id of ['T1', 'T2', 'T3']) await transition(id).waitFor();
  assert.equal(await place('P1').getAttribute('aria-label'), 'Place P1: 0 tokens');
  // Without arcs there is no code yet, and the code column says why, naming the elements.
  assert.match(await view.locator('.pn-no-code').textContent(), /^No code can be generated:.*Cycle, (place|transition) [PT]\d/);

  // Arcs: press on one element and release on the other, or click one and then the other.
  await tool('Arc').click();
  const join = async (a, b, clicks) => {
    const arcs = await view.locator('.pn-arc').count();
    const from = await centre(a);
    const to = await centre(b);
    if (clicks) {
      await page.mouse.click(from.x, from.y);
      await page.mouse.click(to.x, to.y);
    } else {
      await page.mouse.move(from.x, from.y);
      await page.mouse.down();
      await page.mouse.move(to.x, to.y, { steps: 6 });
      await page.mouse.up();
    }
    // The arc is drawn before the next one is started, as a person waits to see it.
    // (attached: a horizontal line has no height, which Playwright counts as invisible)
    await view.locator('.pn-arc').nth(arcs).waitFor({ state: 'attached' });
  };
  await join(place('P1'), transition('T1'), false);
  await join(transition('T1'), place('P2'), true);
  await join(place('P2'), transition('T2'), false);
  await join(transition('T2'), place('P3'), true);
  await join(place('P3'), transition('T3'), false);
  await join(transition('T3'), place('P1'), false);
  assert.equal(await view.locator('.pn-arc').count(), 6);
  await page.keyboard.press('Escape');
  assert.equal(await tool('Select').getAttribute('aria-pressed'), 'true', 'Escape returns to Select');

  // Properties: one token in P1, the guard Go on T1, an action in P2.
  await place('P1').click();
  const props = view.getByRole('group', { name: 'Properties' });
  await props.getByRole('textbox', { name: 'Initial tokens' }).fill('1');
  await props.getByRole('textbox', { name: 'Initial tokens' }).press('Tab');
  await place('P1').and(page.locator('[data-tokens="1"]')).waitFor();
  await transition('T1').click();
  await props.getByRole('textbox', { name: 'Guard' }).fill('Go');
  await props.getByRole('textbox', { name: 'Guard' }).press('Tab');
  await place('P2').click();
  await props.getByRole('textbox', { name: 'Actions' }).fill('Busy := TRUE;');
  await props.getByRole('textbox', { name: 'Actions' }).press('Tab');

  // The generated CASE OF code, and the net runs scan by scan.
  const code = view.locator('.pn-code');
  await code.filter({ hasText: 'CASE' }).waitFor();
  assert.equal(await view.locator('.pn-no-code').count(), 0);
  await code.filter({ hasText: 'Busy := TRUE;' }).waitFor();
  await page.getByText('No problems found.').waitFor();
  await page.getByRole('combobox', { name: 'Program to run' }).selectOption('Cycle');
  const scans = page.getByLabel('Scan count');
  const step = async () => {
    const before = Number(await scans.textContent());
    await page.getByRole('button', { name: 'Step', exact: true }).click();
    await page.waitForFunction((n) => Number(document.querySelector('[aria-label="Scan count"]').textContent) === n + 1, before);
  };
  const tokens = async () => Promise.all(['P1', 'P2', 'P3'].map((id) => place(id).getAttribute('data-tokens')));
  await step();
  assert.deepEqual(await tokens(), ['1', '0', '0'], 'T1 waits for Go');
  assert.equal(await transition('T1').getAttribute('aria-label'), 'Transition T1, enabled', 'marked, waiting for its guard');
  await page.getByRole('checkbox', { name: 'Go', exact: true }).check();
  // The firing sends tokens along T1's arcs (seen by an observer, as they fly for 260 ms).
  await page.evaluate(() => {
    window.__flew = [];
    new MutationObserver(() => {
      for (const c of document.querySelectorAll('.pn-flying')) window.__flew.push(c.getAttribute('cx') + ',' + c.getAttribute('cy'));
    }).observe(document.querySelector('.pn-net'), { subtree: true, childList: true });
  });
  await step();
  assert.deepEqual(await tokens(), ['0', '1', '0'], 'Go fires T1');
  await page.waitForFunction(() => window.__flew.length >= 2);
  assert.deepEqual([...new Set(await page.evaluate(() => window.__flew))].sort(), ['100,100', '200,100'], 'from P1 into T1, from T1 out to P2');
  assert.equal(await transition('T1').getAttribute('aria-label'), 'Transition T1, fired');
  assert.equal(await place('P2').getAttribute('aria-label'), 'Place P2: 1 token');
  await step();
  await page.waitForFunction(() => /^2:/.test(document.querySelector('.code-active')?.dataset.text ?? ''));
  assert.equal(await page.getByRole('img', { name: 'Busy: ON', exact: true }).count(), 1, 'the P2 branch ran');
  assert.deepEqual(await tokens(), ['0', '0', '1'], 'T2 has no guard: it fires on the next scan');
  await step();
  assert.deepEqual(await tokens(), ['1', '0', '0'], 'T3 closes the cycle');

  // Move P2 with the mouse: its arcs follow; undo puts it back.
  const arcEnds = () => view.locator('.pn-arc').evaluateAll((ls) => ls.map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(',')).sort().join(' '));
  const before = await arcEnds();
  const p2 = await centre(place('P2'));
  const target = await at(canvas, 440, 100);
  await page.mouse.move(p2.x, p2.y);
  await page.mouse.down();
  await page.mouse.move(target.x, target.y, { steps: 8 });
  await page.mouse.up();
  await page.waitForFunction((b) => b !== [...document.querySelectorAll('.pn-arc')].map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(',')).sort().join(' '), before);
  const moved = await centre(place('P2'));
  assert.ok(Math.abs(moved.x - target.x) < 12 && Math.abs(moved.y - target.y) < 12, 'P2 is where it was dropped');
  const ends = (await arcEnds()).split(' ').map((e) => e.split(',').map(Number));
  const near = (x, y) => ends.some(([x1, y1, x2, y2]) => Math.hypot(x1 - x, y1 - y) < 30 || Math.hypot(x2 - x, y2 - y) < 30);
  assert.ok(near(440, 100), 'arcs end at the moved place');
  await view.getByRole('button', { name: 'Undo' }).click();
  await page.waitForFunction((b) => b === [...document.querySelectorAll('.pn-arc')].map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(',')).sort().join(' '), before);

  // Keys: arrows move the focused place by a grid step; Delete deletes it with its arcs.
  await place('P3').focus();
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => document.activeElement?.dataset.id === 'P3');
  await page.keyboard.press('Delete');
  await place('P3').waitFor({ state: 'detached' });
  assert.equal(await view.locator('.pn-arc').count(), 4);
  await page.keyboard.press('Control+z');
  await place('P3').waitFor();
  assert.equal(await view.locator('.pn-arc').count(), 6);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/petri-editor.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});

async function openApp(context) {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(server.url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { page, errors };
}

test('the concurrent weighing net runs with two places marked at once and both branches lit', async () => {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const { page, errors } = await openApp(context);
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: 'Weighing (concurrent Petri net)' });
  const view = page.getByRole('region', { name: 'Petri net WeighingConcurrent' });
  await view.waitFor();
  const place = (id) => view.locator(`.pn-place[data-id="${id}"]`);
  const step = page.getByRole('button', { name: 'Step', exact: true });
  await step.click();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await step.click();
  await place('A31').and(page.locator('[data-tokens="1"]')).waitFor();
  assert.equal(await place('B41').getAttribute('data-tokens'), '1', 'the fork marks both branches');
  assert.equal(await place('P1').getAttribute('aria-label'), 'Place P1: 0 tokens');
  await step.click();
  await page.waitForFunction(() => {
    const lit = [...document.querySelectorAll('.code-active')].map((b) => b.dataset.text);
    return lit.some((t) => /^31:/.test(t)) && lit.some((t) => /^41:/.test(t));
  });
  // Selecting a place marks its branch in the code; a click on a code line selects back.
  await place('A31').click();
  const marked = view.locator('.code-selected');
  await marked.first().waitFor();
  const first = Number(await marked.first().getAttribute('data-first'));
  const line = view.locator('.code-lines');
  const box = await line.boundingBox();
  await page.mouse.click(box.x + 40, box.y + 6 + (first - 1) * 18 + 9);
  assert.equal(await place('A31').getAttribute('class').then((c) => /\bselected\b/.test(c)), true);
  assert.deepEqual(errors, []);
  await context.close();
});

const PHILOSOPHERS = `<?xml version="1.0" encoding="UTF-8"?>
<pnml xmlns="http://www.pnml.org/version-2009/grammar/pnml">
<net id="n" type="http://www.pnml.org/version-2009/grammar/ptnet"><name><text>Philosophers</text></name><page id="g">
${[['think0', 1, 60, 60], ['left0', 0, 60, 180], ['eat0', 0, 60, 300], ['think1', 1, 420, 60], ['left1', 0, 420, 180], ['eat1', 0, 420, 300], ['f0', 1, 240, 120], ['f1', 1, 240, 260]]
    .map(([id, m, x, y]) => `<place id="${id}"><name><text>${id}</text></name><graphics><position x="${x}" y="${y}"/></graphics>${m ? '<initialMarking><text>1</text></initialMarking>' : ''}</place>`).join('\n')}
${[['takeL0', 60, 120], ['takeR0', 60, 240], ['rel0', 150, 360], ['takeL1', 420, 120], ['takeR1', 420, 240], ['rel1', 330, 360]]
    .map(([id, x, y]) => `<transition id="${id}"><name><text>${id}</text></name><graphics><position x="${x}" y="${y}"/></graphics></transition>`).join('\n')}
${[['think0', 'takeL0'], ['f0', 'takeL0'], ['takeL0', 'left0'], ['left0', 'takeR0'], ['f1', 'takeR0'], ['takeR0', 'eat0'], ['eat0', 'rel0'], ['rel0', 'think0'], ['rel0', 'f0'], ['rel0', 'f1'],
    ['think1', 'takeL1'], ['f1', 'takeL1'], ['takeL1', 'left1'], ['left1', 'takeR1'], ['f0', 'takeR1'], ['takeR1', 'eat1'], ['eat1', 'rel1'], ['rel1', 'think1'], ['rel1', 'f1'], ['rel1', 'f0']]
    .map(([a, b], i) => `<arc id="a${i}" source="${a}" target="${b}"/>`).join('\n')}
</page></net></pnml>`;

test('the two-philosopher net shows its deadlock, plays its path, and exports PNML that plc reads back', async () => {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const { page, errors } = await openApp(context);
  await page.getByLabel('Import project file').setInputFiles({ name: 'philosophers.pnml', mimeType: 'application/xml', buffer: Buffer.from(PHILOSOPHERS) });
  const view = page.getByRole('region', { name: 'Petri net Philosophers' });
  await view.waitFor();
  const tokens = (id) => view.locator(`.pn-place[data-id="${id}"]`).getAttribute('data-tokens');
  await view.locator('.pn-analysis summary').click();
  // Two philosophers reach for one fork: the code depends on priorities there.
  const conflicts = view.getByRole('list', { name: 'Conflicts' });
  await conflicts.getByText('takeL0 and takeR1 both take the token of f0: takeL0 is tested first (priority 0 against 0)').waitFor();
  const deadlock = view.getByRole('button', { name: '{left0, left1} after takeL0 → takeL1' });
  await deadlock.click();
  const play = view.getByRole('group', { name: 'Play the net' });
  await play.getByText('Deadlock path: step 0 of 2.').waitFor();
  assert.equal(await play.getByRole('button', { name: 'Previous' }).isDisabled(), true);
  await play.getByRole('button', { name: 'Next' }).click();
  await play.getByText('Deadlock path: step 1 of 2. Fired: takeL0.').waitFor();
  assert.deepEqual([await tokens('think0'), await tokens('left0'), await tokens('f0')], ['0', '1', '0']);
  await view.locator('.pn-transition[data-id="takeL0"].fired').waitFor();
  await play.getByRole('button', { name: 'Next' }).click();
  await play.getByText('Deadlock path: step 2 of 2. Fired: takeL0 → takeL1.').waitFor();
  assert.deepEqual([await tokens('left0'), await tokens('left1'), await tokens('f0'), await tokens('f1')], ['1', '1', '0', '0']);
  assert.equal(await play.getByRole('button', { name: 'Next' }).isDisabled(), true, 'nothing is enabled: the deadlock');
  assert.equal(await view.locator('.pn-transition.enabled').count(), 0);
  await play.getByRole('button', { name: 'Previous' }).click();
  await play.getByText('Deadlock path: step 1 of 2. Fired: takeL0.').waitFor();
  await play.getByRole('button', { name: 'Stop playing' }).click();
  assert.equal(await tokens('think0'), '1', 'back to the initial marking');

  // The token game: clicks fire enabled transitions, guards ignored; Reset marking.
  await play.getByRole('button', { name: 'Token game' }).click();
  await view.locator('.pn-transition[data-id="takeL1"] .pn-hit').click();
  assert.equal(await tokens('left1'), '1');
  await view.locator('.pn-transition[data-id="takeR1"] .pn-hit').click();
  assert.deepEqual([await tokens('eat1'), await tokens('f0'), await tokens('f1')], ['1', '0', '0']);
  await view.locator('.pn-transition[data-id="takeL0"] .pn-hit').click();
  assert.equal(await tokens('think0'), '1', 'takeL0 is not enabled: its fork is in use');
  await play.getByRole('button', { name: 'Reset marking' }).click();
  assert.deepEqual([await tokens('think1'), await tokens('eat1')], ['1', '0']);
  await play.getByRole('button', { name: 'Token game' }).click();

  // Export PNML from the page; plc petri import reads the same net back.
  const download = page.waitForEvent('download');
  await view.getByRole('button', { name: 'Export PNML' }).click();
  const file = await (await download).path();
  const plc = path.join(root, 'target/debug/plc');
  assert.ok(existsSync(plc), 'the plc binary is built by cargo test before the browser tests');
  const project = JSON.parse(execFileSync(plc, ['petri', 'import', file]).toString());
  const net = project.petri[0].net;
  assert.deepEqual(net.places.map((p) => [p.id, p.tokens ?? 0, p.position.x, p.position.y]),
    [['think0', 1, 60, 60], ['left0', 0, 60, 180], ['eat0', 0, 60, 300], ['think1', 1, 420, 60], ['left1', 0, 420, 180], ['eat1', 0, 420, 300], ['f0', 1, 240, 120], ['f1', 1, 240, 260]]);
  assert.equal(net.transitions.length, 6);
  assert.equal(net.arcs.length, 20);
  const svgDownload = page.waitForEvent('download');
  await view.getByRole('button', { name: 'Export SVG' }).click();
  const svg = await readFile(await (await svgDownload).path(), 'utf8');
  assert.match(svg, /^<\?xml/);
  assert.match(svg, /<svg[^>]*xmlns="http:\/\/www.w3.org\/2000\/svg"/);
  assert.match(svg, /\.pn-circle/);
  assert.deepEqual(errors, []);
  await context.close();
});

test('a textual SFC program gets a chart with its steps and conditions, and its active step is lit while it runs', async () => {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 } });
  const { page, errors } = await openApp(context);
  await page.getByRole('combobox', { name: 'Open example' }).selectOption({ label: 'SFC weighing (ST)' });
  await page.getByRole('button', { name: 'SFC chart SfcWeighing' }).click();
  const view = page.getByRole('region', { name: 'SFC chart SfcWeighing' });
  const chart = view.getByRole('group', { name: 'SFC chart SfcWeighing' });
  await chart.waitFor();
  const steps = await chart.locator('.sfc-step').evaluateAll((gs) => gs.map((g) => g.dataset.step));
  assert.deepEqual(steps, ['Ready', 'Alarm', 'Filling', 'Settling', 'Discharging']);
  await chart.getByRole('img', { name: 'Transition Start AND NOT Fault' }).waitFor();
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await chart.getByRole('img', { name: 'Initial step Ready, active' }).waitFor();
  await page.getByRole('checkbox', { name: 'Start', exact: true }).check();
  await page.getByRole('button', { name: 'Step', exact: true }).click();
  await chart.getByRole('img', { name: 'Step Filling, active' }).waitFor();
  assert.equal(await chart.getByRole('img', { name: 'Initial step Ready' }).count(), 1, 'Ready is no longer active');
  await page.screenshot({ path: path.join(root, 'docs/screenshots/sfc-chart.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await context.close();
});

test('touch and pen draw and move on the net canvas as the mouse does', async () => {
  const context = await browser.newContext({ viewport: { width: 1400, height: 1000 }, hasTouch: true });
  const { page, errors } = await openApp(context);
  await page.getByRole('button', { name: 'New Petri net POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill('Touch');
  await page.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: 'Petri net Touch' });
  await view.waitFor();
  const canvas = view.getByRole('group', { name: 'Net canvas' });
  const cdp = await context.newCDPSession(page);
  const touch = async (points) => {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [points[0]] });
    for (const p of points.slice(1)) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [p] });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  };
  const pen = async (points) => {
    const send = (type, p) => cdp.send('Input.dispatchMouseEvent', { type, x: p.x, y: p.y, button: 'left', buttons: type === 'mouseReleased' ? 0 : 1, clickCount: 1, pointerType: 'pen' });
    await send('mousePressed', points[0]);
    for (const p of points.slice(1)) await send('mouseMoved', p);
    await send('mouseReleased', points[points.length - 1]);
  };
  // A finger taps a place in, a pen a transition.
  await view.getByRole('button', { name: 'Place', exact: true }).click();
  await touch([await at(canvas, 100, 100)]);
  await view.locator('.pn-place[data-id="P1"]').waitFor();
  await view.getByRole('button', { name: 'Transition', exact: true }).click();
  await pen([await at(canvas, 200, 100)]);
  await view.locator('.pn-transition[data-id="T1"]').waitFor();
  // The pen joins them with an arc; the finger drags the place down.
  await view.getByRole('button', { name: 'Arc', exact: true }).click();
  await pen([await centre(view.locator('.pn-place[data-id="P1"]')), await at(canvas, 150, 100), await centre(view.locator('.pn-transition[data-id="T1"]'))]);
  await view.locator('.pn-arc').first().waitFor({ state: 'attached' });
  await view.getByRole('button', { name: 'Select', exact: true }).click();
  const from = await centre(view.locator('.pn-place[data-id="P1"]'));
  const to = await at(canvas, 100, 240);
  await touch(Array.from({ length: 8 }, (_, i) => ({ x: from.x + ((to.x - from.x) * i) / 7, y: from.y + ((to.y - from.y) * i) / 7 })));
  await page.waitForFunction(() => document.querySelector('.pn-place[data-id="P1"] .pn-circle')?.getAttribute('cy') === '240');
  assert.equal(await view.locator('.pn-place[data-id="P1"] .pn-circle').getAttribute('cx'), '100');
  assert.deepEqual(errors, []);
  await context.close();
});
