// The Petri net editor in Firefox or WebKit (ENGINE): a three-place cycle drawn with the
// pointer (places and transitions clicked onto the canvas, arcs dragged and clicked), its
// marking and guard set in the properties, run scan by scan; a place dragged and undone.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { suite, openApp, withSession, noErrors, shot, step, saved } from './harness.mjs';

const env = suite();

/** Viewport pixels of net point (x, y) on the canvas (through its viewBox and size). */
async function at(canvas, x, y) {
  const box = await canvas.box();
  const [vx, vy, vw, vh] = (await canvas.attr('viewBox')).split(' ').map(Number);
  return { x: box.x + ((x - vx) * box.width) / vw, y: box.y + ((y - vy) * box.height) / vh };
}

const arcEnds = () => [...document.querySelectorAll('.pn-arc')]
  .map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(','))
  .sort().join(' ');

test('a three-place cycle drawn with the pointer generates CASE code and runs scan by scan', async () => {
  await withSession(openApp(env), async (s) => {
    await s.role('button', 'New Petri net POU').click();
    await s.role('textbox', 'POU name').fill('Cycle');
    await s.role('button', 'Create').click();
    const view = s.role('region', 'Petri net Cycle');
    await view.waitFor();
    const decls = view.role('textbox', 'Declarations');
    await decls.fill('VAR_INPUT\n    Go : BOOL;\nEND_VAR\nVAR_OUTPUT\n    Busy : BOOL;\nEND_VAR\n');
    await decls.press('Tab');
    const canvas = view.role('group', 'Net canvas');
    const tool = (name) => view.role('button', name);
    const place = (id) => view.css(`.pn-place[data-id="${id}"]`);
    const transition = (id) => view.css(`.pn-transition[data-id="${id}"]`);
    // The middle of a place's circle or a transition's bar (not of its label; the bar is
    // drawn over the transition's wider hit area).
    const centre = async (el) => {
      const b = await el.css('.pn-circle, .pn-hit').first.box();
      return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
    };

    // Selects an element with a click at its middle. On a loaded machine the page can
    // move between reading where the element is and the click (the check that follows the
    // last edit redraws the generated code below), so the click may miss it, as a quick
    // person's might: like Playwright's click, it is made again until it selects.
    const select = async (el, what) => {
      for (let attempt = 1; ; attempt++) {
        await s.clickAt(await centre(el));
        try {
          await el.waitForAttr('class', /\bselected\b/, 5000);
          return;
        } catch (e) {
          if (attempt === 3) throw e;
          console.log(`# ${env.engine.name}: the click missed ${what} (it moved); clicking again`);
        }
      }
    };

    await tool('Place').click();
    await tool('Place').waitForAttr('aria-pressed', 'true');
    for (const [i, [x, y]] of [[100, 100], [300, 100], [300, 260]].entries()) {
      await s.clickAt(await at(canvas, x, y));
      await place(`P${i + 1}`).waitFor();
    }
    await tool('Transition').click();
    for (const [i, [x, y]] of [[200, 100], [300, 180], [200, 260]].entries()) {
      await s.clickAt(await at(canvas, x, y));
      await transition(`T${i + 1}`).waitFor();
    }
    assert.equal(await place('P1').attr('aria-label'), 'Place P1: 0 tokens');

    // Arcs: press on one element and release on the other, or click one then the other.
    await tool('Arc').click();
    const join = async (a, b, clicks) => {
      const arcs = await view.css('.pn-arc').count();
      const from = await centre(a);
      const to = await centre(b);
      if (clicks) {
        await s.clickAt(from);
        await s.clickAt(to);
      } else {
        await s.drag(from, to, 6);
      }
      await view.css('.pn-arc', { nth: arcs, state: 'attached' }).waitFor({ state: 'attached' });
    };
    await join(place('P1'), transition('T1'), false);
    await join(transition('T1'), place('P2'), true);
    await join(place('P2'), transition('T2'), false);
    await join(transition('T2'), place('P3'), true);
    await join(place('P3'), transition('T3'), false);
    await join(transition('T3'), place('P1'), false);
    assert.equal(await view.css('.pn-arc').count(), 6);
    await s.press('Escape');
    await tool('Select').waitForAttr('aria-pressed', 'true');

    // Properties: a token in P1, the guard Go on T1, an action in P2.
    await select(place('P1'), 'P1');
    const props = view.role('group', 'Properties');
    await props.role('textbox', 'Initial tokens').fill('1');
    await props.role('textbox', 'Initial tokens').press('Tab');
    await place('P1').waitForAttr('data-tokens', '1');
    await select(transition('T1'), 'T1');
    await props.role('textbox', 'Guard').fill('Go');
    await props.role('textbox', 'Guard').press('Tab');
    await select(place('P2'), 'P2');
    await props.role('textbox', 'Actions').fill('Busy := TRUE;');
    await props.role('textbox', 'Actions').press('Tab');

    const code = view.css('.pn-code', { hasText: 'Busy := TRUE;' });
    await code.waitFor();
    assert.match(await code.text(), /CASE/);
    await saved(s, 'Busy := TRUE;');
    await s.role('combobox', 'Program to run').select('Cycle');
    const tokens = () => Promise.all(['P1', 'P2', 'P3'].map((id) => place(id).attr('data-tokens')));
    await step(s);
    assert.deepEqual(await tokens(), ['1', '0', '0'], 'T1 waits for Go');
    assert.equal(await transition('T1').attr('aria-label'), 'Transition T1, enabled');
    await s.role('checkbox', 'Go').check();
    await step(s);
    assert.deepEqual(await tokens(), ['0', '1', '0'], 'Go fires T1');
    assert.equal(await transition('T1').attr('aria-label'), 'Transition T1, fired');
    await step(s);
    await s.role('img', 'Busy: ON').waitFor();
    assert.deepEqual(await tokens(), ['0', '0', '1'], 'T2 has no guard: it fires on the next scan');
    await step(s);
    assert.deepEqual(await tokens(), ['1', '0', '0'], 'T3 closes the cycle');

    // P2 dragged with the pointer: its arcs follow; Undo puts it back.
    const before = await s.evaluate(arcEnds);
    const target = await at(canvas, 440, 100);
    await s.drag(await centre(place('P2')), target, 8);
    await s.waitUntil((b) => b !== [...document.querySelectorAll('.pn-arc')]
      .map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(','))
      .sort().join(' '), before, { what: 'the arcs following the moved place' });
    const moved = await centre(place('P2'));
    assert.ok(Math.abs(moved.x - target.x) < 12 && Math.abs(moved.y - target.y) < 12, `P2 is where it was dropped (${JSON.stringify(moved)} vs ${JSON.stringify(target)})`);
    await view.role('button', 'Undo').click();
    await s.waitUntil((b) => b === [...document.querySelectorAll('.pn-arc')]
      .map((l) => [l.x1.baseVal.value, l.y1.baseVal.value, l.x2.baseVal.value, l.y2.baseVal.value].map(Math.round).join(','))
      .sort().join(' '), before, { what: 'the arcs back after Undo' });

    // Keys: Delete removes the focused place with its arcs; Ctrl+Z brings them back.
    await place('P3').focus();
    await s.press('Delete');
    await place('P3').waitFor({ state: 'detached' });
    assert.equal(await view.css('.pn-arc').count(), 4);
    await s.press('Control+z');
    await place('P3').waitFor();
    assert.equal(await view.css('.pn-arc').count(), 6);
    await s.screenshot(shot(env, 'petri'));
    await noErrors(s);
  });
});
