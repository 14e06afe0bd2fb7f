// The driver itself (ENGINE): a press lands on the element asked for even when the page
// moves between finding the point and pressing. In Firefox a scroll the page makes on its
// own (the caret of a text area just typed into brought back into view) could take the
// page away after the driver had scrolled a button into view, and the press then landed
// on whatever was under the point instead (exercise.test.mjs's second Check, once in
// several runs). This page makes that move every time: on the first pointer move after
// the driver has scrolled `Check` into view, it scrolls down, so that `Decoy` is under the
// point.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { suite, withSession } from './harness.mjs';

const env = suite();

const PAGE = `<!doctype html><meta charset="utf-8"><title>press</title>
<style>body { margin: 0 } button { display: block; margin: 0; width: 200px; height: 40px }</style>
<button id="check">Check</button>
<div style="height: 400px"></div>
<button id="decoy">Decoy</button>
<div style="height: 3000px"></div>
<script>
  const pressed = { check: 0, decoy: 0 };
  window.pressed = pressed;
  for (const id of Object.keys(pressed)) document.getElementById(id).addEventListener('click', () => pressed[id]++);
  let moved = false;
  const moveAway = () => {
    if (moved || scrollY !== 0) return;
    moved = true;
    window.scrollTo(0, 440);
  };
  addEventListener('pointermove', moveAway, true);
  addEventListener('mousemove', moveAway, true);
  window.scrollTo(0, 1000);
</script>`;

test('a press the page moves away from is made again where the element is', async () => {
  await withSession(env.engine.newSession({ width: 800, height: 600 }), async (s) => {
    await s.goto(`data:text/html,${encodeURIComponent(PAGE)}`);
    await s.waitUntil(() => window.pressed && scrollY === 1000, null, { what: 'the page scrolled down' });

    await s.role('button', 'Check').click();
    const pressed = await s.evaluate(() => ({ ...window.pressed }));
    assert.deepEqual(pressed, { check: 1, decoy: 0 }, 'Check pressed once, Decoy never');
  });
});
