// Exercises in Firefox or WebKit (ENGINE): the catalogue, an exercise opened, a wrong
// solution checked (the graded report with the failing scenario, its first wrong output and
// the timeline at that scan), a right one passing and ticked in the catalogue, and the
// exercise opened again from its share link in a fresh browser.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { suite, openApp, withSession, noErrors, shot, saved } from './harness.mjs';

const env = suite();

const NO_SEAL = `PROGRAM Main
VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
Motor := Start AND NOT Stop;
END_PROGRAM
`;
const RIGHT = NO_SEAL.replace('Motor := Start AND NOT Stop;', 'Motor := (Start OR Motor) AND NOT Stop;');

/** Checks the attempt and waits for the report whose score matches `score`. */
async function check(s, score) {
  await s.role('button', 'Check').click();
  const report = s.role('region', 'Report');
  await report.css('.report-score', { hasText: score }).waitFor();
  await s.role('button', 'Check').waitFor();
  return report;
}

test('an exercise opened from the catalogue, checked wrong then right, its report shown and its tick kept', async () => {
  let link;
  await withSession(openApp(env), async (s) => {
    await s.role('button', 'Exercises').click();
    const list = s.role('list', 'Exercise list');
    await list.waitFor();
    await s.role('textbox', 'ST source').waitFor({ state: 'hidden' });
    await s.role('combobox', 'Level').select('1');
    await list.role('button', 'Start/stop motor latch').click();
    const panel = s.role('region', 'Exercise');
    await panel.role('heading', 'Start/stop motor latch').waitFor();
    assert.match(await panel.role('table', 'Interface').text(), /Motor.*BOOL.*VAR_OUTPUT/);
    await s.waitUntil(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'), null, { what: 'the starter in the editor' });

    await s.role('textbox', 'ST source').fill(NO_SEAL);
    await saved(s, 'Motor := Start AND NOT Stop;');
    let report = await check(s, 'Score 1 of 3');
    const failed = report.css('.report-scenario.failed').first;
    assert.match(await failed.css('.report-name').text(), /^Start, release, stop$/);
    assert.match(await failed.css('.report-actual').text(), /Motor was FALSE at 0\.21 s \(scan 21\)/);
    assert.match(await failed.text(), /Hint: Does the motor hold itself/);
    const timeline = failed.role('img', /^Timeline of “Start, release, stop”/);
    assert.equal(await timeline.attr('data-cursor-scan'), '21');
    await failed.css('.tl-cursor').waitFor({ state: 'attached' });
    assert.ok((await failed.css('.tl-wrong').count()) > 0, 'the wrong scans are marked');
    await s.screenshot(shot(env, 'exercise-report'));

    await s.role('textbox', 'ST source').fill(RIGHT);
    await saved(s, 'Motor := (Start OR Motor) AND NOT Stop;');
    report = await check(s, 'Score 3 of 3');
    await report.css('.report-score', { hasText: 'every scenario passes' }).waitFor();
    assert.equal(await report.css('.report-scenario.failed').count(), 0);
    await panel.role('button', 'All exercises').click();
    await s.css('.catalogue-item[data-exercise="latch"]').role('img', 'Passed').waitFor();

    // A reload keeps the attempt and the tick.
    await s.reload();
    await s.role('region', 'Exercise').role('heading', 'Start/stop motor latch').waitFor();
    assert.equal(await s.role('textbox', 'ST source').value(), RIGHT);
    await s.role('button', 'Share exercise').click();
    link = await s.role('textbox', 'Exercise link').value();
    assert.match(link, /#x=/);
    await noErrors(s);
  });

  // The exercise from its link in a fresh browser: the statement and the starter, checkable.
  await withSession(openApp(env, { url: link }), async (s) => {
    const panel = s.role('region', 'Exercise');
    await panel.role('heading', 'Start/stop motor latch').waitFor();
    await s.waitUntil(() => document.querySelector('textarea[aria-label="ST source"]')?.value.includes('Motor := FALSE;'), null, { what: 'the starter in the editor' });
    await check(s, 'Score');
    assert.match(await s.role('region', 'Report').css('.report-score').text(), /^Score \d of 3/);
    await noErrors(s);
  });
});
