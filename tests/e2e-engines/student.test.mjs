// What a student does first, in Firefox or WebKit (ENGINE): types the start/stop latch and
// runs it, steps a timer scan by scan, and finds a project again after a reload and in a
// fresh browser that opens its share link.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { suite, openApp, withSession, writeProgram, noErrors, shot, scans, step, saved } from './harness.mjs';

const env = suite();

const LATCH = `PROGRAM Latch
VAR_INPUT
    Start : BOOL; (* start button *)
    Stop : BOOL;  (* stop button *)
END_VAR
VAR_OUTPUT
    Motor : BOOL; (* motor contactor *)
END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
`;

const DELAYED_LAMP = `PROGRAM Delay
VAR_INPUT Switch : BOOL; END_VAR
VAR_OUTPUT Lamp : BOOL; END_VAR
VAR Timer : TON; END_VAR
Timer(IN := Switch, PT := T#100ms);
Lamp := Timer.Q;
END_PROGRAM
`;

/** Waits until the simulator ran `n` more scans than now. */
async function scansPass(s, n) {
  const from = await scans(s);
  await s.waitUntil(([f, k]) => Number(document.querySelector('[aria-label="Scan count"]').textContent) >= f + k, [from, n], { what: `${n} more scans` });
}

test('the start/stop latch typed in a new project runs: Start, release, Stop', async () => {
  await withSession(openApp(env, { width: 1280, height: 800 }), async (s) => {
    await s.role('button', 'New project').click();
    await writeProgram(s, LATCH, 'Start');
    for (const name of ['Start', 'Stop', 'Motor']) await s.role('checkbox', `Chart ${name}`).check();
    await s.role('button', 'Run').click();
    await s.role('checkbox', 'Start').check();
    await s.role('img', 'Motor: ON').waitFor();
    await s.role('checkbox', 'Start').uncheck();
    await scansPass(s, 20);
    await s.role('img', 'Motor: ON').waitFor({ timeout: 1 });
    await s.role('checkbox', 'Stop').check();
    await s.role('img', 'Motor: OFF').waitFor();
    await scansPass(s, 20);
    await s.role('img', 'Motor: OFF').waitFor({ timeout: 1 });
    await s.role('checkbox', 'Stop').uncheck();
    await s.role('checkbox', 'Start').check();
    await s.role('img', 'Motor: ON').waitFor();
    await scansPass(s, 40);
    // The timeline drew the three lanes while it ran.
    const chart = s.role('img', 'Timeline chart');
    await chart.waitFor();
    assert.ok((await chart.css('polyline, path', { state: 'attached' }).count()) >= 3, 'the timeline draws the lanes');
    await s.screenshot(shot(env, 'latch'));
    await s.role('button', 'Pause').click();
    await noErrors(s);
  });
});

test('stepping a TON: the lamp comes on after the preset, scan by scan', async () => {
  await withSession(openApp(env), async (s) => {
    await s.role('button', 'New project').click();
    await writeProgram(s, DELAYED_LAMP, 'Switch');
    await s.role('checkbox', 'Chart Switch').check();
    await s.role('checkbox', 'Chart Lamp').check();
    await s.role('checkbox', 'Switch').check();
    for (let i = 0; i < 10; i++) await step(s);
    assert.equal(await scans(s), 10);
    await s.role('img', 'Lamp: OFF').waitFor({ timeout: 1 });
    await step(s);
    await s.role('img', 'Lamp: ON').waitFor();
    assert.equal(await s.role('status', 'Virtual time').text(), 'T#110ms');
    await s.role('img', 'Timeline chart').waitFor();
    // The active CASE-free program has no lit branch; the variable table shows the timer.
    await noErrors(s);
  });
});

test('a project is saved as it is typed, kept by a reload, and opened from its share link in a fresh browser', async () => {
  let link;
  await withSession(openApp(env), async (s) => {
    await s.role('button', 'New project').click();
    await writeProgram(s, DELAYED_LAMP, 'Switch');
    // Saved: local storage holds the text (every edit is saved, debounced).
    await saved(s, 'Timer(IN := Switch, PT := T#100ms);');
    const projects = await s.role('combobox', 'Open project').options();
    assert.equal(projects.length, 2, `the new project beside the first one: ${projects}`);
    await s.reload();
    await s.role('textbox', 'ST source').waitFor();
    assert.equal(await s.role('textbox', 'ST source').value(), DELAYED_LAMP, 'the reload keeps the project');
    assert.deepEqual(await s.role('combobox', 'Open project').options(), projects);
    await s.role('button', 'Share').click();
    link = await s.role('textbox', 'Share link').value();
    assert.match(link, /#p=/);
    await noErrors(s);
  });
  await withSession(openApp(env, { url: link }), async (s) => {
    await s.waitUntil((want) => document.querySelector('textarea[aria-label="ST source"]')?.value === want, DELAYED_LAMP,
      { what: 'the shared project in the editor' });
    await s.role('checkbox', 'Switch').waitFor();
    // It runs as it did where it was written.
    await s.role('checkbox', 'Switch').check();
    for (let i = 0; i < 11; i++) await step(s);
    await s.role('img', 'Lamp: ON').waitFor();
    // Reloaded, the shared project stays (stored, and the link is not opened again).
    const projects = await s.role('combobox', 'Open project').options();
    await s.reload();
    await s.role('textbox', 'ST source').waitFor();
    assert.equal(await s.role('textbox', 'ST source').value(), DELAYED_LAMP);
    assert.deepEqual(await s.role('combobox', 'Open project').options(), projects, 'the shared project once, not twice');
    await noErrors(s);
  });
});

test('two tabs of one browser: an edit in one is announced in the other, which loads it', async () => {
  await withSession(openApp(env), async (a) => {
    await writeProgram(a, DELAYED_LAMP, 'Switch');
    await saved(a, 'PT := T#100ms');
    const b = await a.newTab();
    try {
      await b.goto(env.server.url);
      await b.role('textbox', 'ST source').waitFor();
      assert.equal(await b.role('textbox', 'ST source').value(), DELAYED_LAMP, 'both tabs show the same project');
      const changed = DELAYED_LAMP.replace('T#100ms', 'T#250ms');
      await a.role('textbox', 'ST source').fill(changed);
      await saved(a, 'PT := T#250ms');
      // The other tab hears of it through the storage event.
      await b.role('alert', undefined, { hasText: 'was changed in another tab' }).waitFor();
      await b.role('button', "Load the other tab's version").click();
      await b.waitUntil((want) => document.querySelector('textarea[aria-label="ST source"]')?.value === want, changed, { what: "the other tab's version loaded" });
      await noErrors(b);
    } finally {
      await b.close();
    }
    await noErrors(a);
  });
});
