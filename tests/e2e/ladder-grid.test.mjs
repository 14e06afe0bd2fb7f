// The rung grid as a person uses it (issue 34): a drop lands on the cell it was dropped on,
// the cells and operand names are big enough to read and hit, zoom and Fit change them, and
// while dragging the target is outlined, the drag label stays clear of it and the Operand
// box opens beside the element just placed.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { root, useApp, openPage, newLadderProgram, cell, centre, operand } from './setup.mjs';

const app = useApp();
const openApp = (context) => openPage(context, app.server.url);

const steps = (from, to, n = 8) => Array.from({ length: n }, (_, i) => ({
  x: from.x + ((to.x - from.x) * (i + 1)) / n,
  y: from.y + ((to.y - from.y) * (i + 1)) / n,
}));

/** Drags with the mouse from the middle of one element to another's. */
async function mouseDrag(page, from, to) {
  const a = await centre(from);
  const b = await centre(to);
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  await page.mouse.move(b.x, b.y, { steps: 8 });
  await page.mouse.up();
}

/** Drags with one finger from the middle of one element to another's. */
async function touchDrag(cdp, from, to) {
  const a = await centre(from);
  const b = await centre(to);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [a] });
  for (const p of steps(a, b)) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [p] });
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

const LATCH_DECLS = `VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
`;

test('the lost drop: Link down dragged onto the NC contact Stop after a touch drag lands, ten times in a row', async () => {
  for (let attempt = 1; attempt <= 10; attempt++) {
    const context = await app.browser.newContext({ viewport: { width: 1400, height: 900 }, hasTouch: true });
    const { page, errors } = await openApp(context);
    const cdp = await context.newCDPSession(page);
    const view = await newLadderProgram(page, 'Latch', LATCH_DECLS);
    const tool = (name) => view.getByRole('button', { name, exact: true });
    await mouseDrag(page, tool('NO contact'), cell(view, 1, 1, 1));
    await operand(view, 'Start');
    await mouseDrag(page, tool('NC contact'), cell(view, 1, 1, 2));
    await operand(view, 'Stop');
    await mouseDrag(page, tool('Coil'), cell(view, 1, 1, 3));
    await operand(view, 'Motor');
    await touchDrag(cdp, tool('NO contact'), cell(view, 1, 2, 1));
    await operand(view, 'Motor');
    await view.getByRole('gridcell', { name: 'Rung 1, row 2, column 1: NO contact Motor' }).waitFor();
    await mouseDrag(page, tool('Link down'), view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop' }));
    const linked = view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop, linked down' });
    await linked.waitFor({ timeout: 3000 }).catch(() => {});
    const names = await view.getByRole('gridcell').evaluateAll((cells) => cells.slice(0, 12).map((c) => c.getAttribute('aria-label')));
    assert.equal(await linked.count(), 1, `attempt ${attempt}: the link was not placed; cells: ${names.join(' | ')}`);
    assert.deepEqual(errors, []);
    await context.close();
  }
});

/** The size of rung 1's first cell and the rendered size of its first operand's text. */
const measure = (view) => view.evaluate((v) => {
  const cell = v.querySelector('.ld-cell').getBoundingClientRect();
  const text = v.querySelector('text.ld-operand').getBoundingClientRect();
  const svg = v.querySelector('.ld-rung-svg');
  const ctm = svg.getScreenCTM();
  const size = parseFloat(getComputedStyle(v.querySelector('text.ld-operand')).fontSize) * ctm.a;
  return { w: cell.width, h: cell.height, font: size, textH: text.height };
});

test('the rung grid is readable at 1280 × 800: cells at least 44 × 32 px, operands at least 12 px; zoom and Fit change them and are kept', async () => {
  const context = await app.browser.newContext({ viewport: { width: 1280, height: 800 } });
  const { page, errors } = await openApp(context);
  const view = await newLadderProgram(page, 'Latch', LATCH_DECLS);
  await cell(view, 1, 1, 1).click();
  await page.keyboard.press('c');
  await page.keyboard.type('Start');
  await page.keyboard.press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 1: NO contact Start' }).waitFor();
  let m = await measure(view);
  assert.ok(m.w >= 44 && m.h >= 32, `a cell is ${m.w} × ${m.h} px`);
  assert.ok(m.font >= 12, `operand text is ${m.font} px`);
  // No page-wide horizontal scroll: the rung scrolls in its own box.
  assert.equal(await page.evaluate(() => document.documentElement.scrollWidth <= innerWidth), true, 'the page scrolls sideways');
  await page.screenshot({ path: path.join(root, 'docs/screenshots/ladder-1280.png') });
  // The ST and IL views beside the rungs show one line per line, no blank line after each
  // (a rung with its coil, so that it has code to show).
  await cell(view, 1, 1, 2).click();
  await page.keyboard.press('o');
  await page.keyboard.type('Motor');
  await page.keyboard.press('Enter');
  await view.getByRole('gridcell', { name: /^Rung 1, row 1, column \d+: coil Motor/ }).waitFor();
  await view.locator('.ld-st-line').first().waitFor();
  const lines = await view.locator('.ld-st-line').evaluateAll((ls) => ls.map((l) => [l.textContent, l.getBoundingClientRect().height, parseFloat(getComputedStyle(l).lineHeight)]));
  assert.ok(lines.length > 0, 'the ST and IL views show lines');
  for (const [text, height, lineHeight] of lines) {
    assert.ok(height <= lineHeight + 1, `the line ${JSON.stringify(text)} is ${height} px tall, a line is ${lineHeight} px`);
  }

  // Zoom in twice: 150 %, cells and text grow by half.
  const zoomIn = view.getByRole('button', { name: 'Zoom in', exact: true });
  const zoomOut = view.getByRole('button', { name: 'Zoom out', exact: true });
  assert.equal(await zoomOut.isDisabled(), true, 'zoom out stops at 100 % (the readable minimum)');
  await zoomIn.click();
  await zoomIn.click();
  const z = await measure(view);
  assert.ok(Math.abs(z.w / m.w - 1.5) < 0.02, `zoomed cell ${z.w} vs ${m.w}`);
  assert.ok(Math.abs(z.font / m.font - 1.5) < 0.02, `zoomed text ${z.font} vs ${m.font}`);
  assert.equal(await page.evaluate(() => document.documentElement.scrollWidth <= innerWidth), true, 'zoomed, the page scrolls sideways');
  await page.screenshot({ path: path.join(root, 'docs/screenshots/ladder-1280-zoomed.png') });

  // The side views collapse, remembered; with their room, Fit draws the widest rung as
  // large as fits: a rung of six columns fills the box without scrolling.
  const side = view.getByRole('button', { name: 'ST and IL views' });
  assert.equal(await side.getAttribute('aria-pressed'), 'true');
  await side.click();
  await view.getByRole('complementary').waitFor({ state: 'detached' });
  assert.equal(await side.getAttribute('aria-pressed'), 'false');
  await cell(view, 1, 1, 7).click();
  for (let i = 0; i < 4; i++) await view.getByRole('button', { name: 'Delete column' }).click();
  await cell(view, 1, 1, 7).waitFor({ state: 'detached' });
  await view.getByRole('button', { name: 'Fit', exact: true }).click();
  const fit = await view.evaluate((v) => {
    const scroll = v.querySelector('.ld-scroll');
    const svg = v.querySelector('.ld-rung-svg').getBoundingClientRect();
    return { overflow: scroll.scrollWidth - scroll.clientWidth, svg: svg.width, room: scroll.clientWidth };
  });
  assert.ok(fit.overflow <= 1, `after Fit the rung still scrolls: ${JSON.stringify(fit)}`);
  assert.ok(fit.svg >= fit.room * 0.9, `Fit left the rung small: ${JSON.stringify(fit)}`);
  const fitted = await measure(view);
  assert.ok(fitted.w > m.w, 'Fit drew the cells larger than 100 %');

  // A reload keeps the zoom and the collapsed side views.
  const zoomText = await view.locator('.ld-zoom-value').textContent();
  await page.reload();
  await page.getByRole('button', { name: 'Ladder diagram Latch' }).click();
  const again = page.getByRole('region', { name: 'Ladder diagram Latch' });
  await again.getByRole('gridcell', { name: 'Rung 1, row 1, column 1: NO contact Start' }).waitFor();
  assert.equal(await again.locator('.ld-zoom-value').textContent(), zoomText);
  assert.equal(await again.getByRole('button', { name: 'ST and IL views' }).getAttribute('aria-pressed'), 'false');
  assert.equal(await again.getByRole('complementary').count(), 0);
  assert.deepEqual(errors, []);
  await context.close();
});

test('while dragging the target is outlined and the label clear of it; the Operand box opens beside the element placed', async () => {
  const context = await app.browser.newContext({ viewport: { width: 1280, height: 800 } });
  const { page, errors } = await openApp(context);
  const view = await newLadderProgram(page, 'Latch', LATCH_DECLS);
  const from = await centre(view.getByRole('button', { name: 'NC contact', exact: true }));
  const target = cell(view, 1, 1, 2);
  const to = await centre(target);
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  await page.mouse.move(to.x, to.y, { steps: 8 });
  const during = await page.evaluate(() => {
    const cell = document.querySelector('.ld-cell.ld-drop-ok');
    const ghost = document.querySelector('.ld-ghost');
    const style = getComputedStyle(cell);
    return {
      cell: cell?.getAttribute('aria-label'),
      outline: `${style.outlineStyle} ${parseFloat(style.outlineWidth)}`,
      rect: cell.getBoundingClientRect().toJSON(),
      ghost: ghost.getBoundingClientRect().toJSON(),
    };
  });
  assert.equal(during.cell, 'Rung 1, row 1, column 2: empty');
  assert.match(during.outline, /^solid [3-9]/, 'the target has a clear outline');
  const overlap = (a, b) => a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
  assert.equal(overlap(during.ghost, during.rect), false, `the drag label covers the target: ${JSON.stringify(during)}`);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/ladder-dragging.png') });
  await page.mouse.up();
  const box = view.getByRole('textbox', { name: 'Operand' });
  await box.waitFor();
  await box.pressSequentially('St');
  const boxRect = await view.locator('div.ld-operand').boundingBox();
  const cellRect = await target.boundingBox();
  const asRect = (b) => ({ left: b.x, top: b.y, right: b.x + b.width, bottom: b.y + b.height });
  assert.equal(overlap(asRect(boxRect), asRect(cellRect)), false, `the Operand box covers the placed element: ${JSON.stringify({ boxRect, cellRect })}`);
  await page.screenshot({ path: path.join(root, 'docs/screenshots/ladder-operand.png') });
  await box.fill('Stop');
  await box.press('Enter');
  await view.getByRole('gridcell', { name: 'Rung 1, row 1, column 2: NC contact Stop' }).waitFor();
  // In the last column the box opens on the left of the cell.
  const last = cell(view, 1, 1, 10);
  await last.click();
  await page.keyboard.press('o');
  await box.waitFor();
  const lastBox = await view.locator('div.ld-operand').boundingBox();
  const lastCell = await last.boundingBox();
  assert.equal(overlap(asRect(lastBox), asRect(lastCell)), false, 'the Operand box covers the coil in the last column');
  await page.keyboard.press('Escape');
  assert.deepEqual(errors, []);
  await context.close();
});
