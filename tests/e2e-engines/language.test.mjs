// The Language switch (issue 33), in Firefox or WebKit (ENGINE): English, Polski and
// Čeština; the page's words and its `lang` follow the choice, which a reload keeps, and the
// simulator works whatever the language.
//
// In scripts/test.sh's run list: a missing or broken switch fails here.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { suite, openApp, withSession, writeProgram, noErrors, shot } from './harness.mjs';

const env = suite();

const LATCH = `PROGRAM Latch
VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
Motor := (Start OR Motor) AND NOT Stop;
END_PROGRAM
`;

const lang = () => document.documentElement.lang;

test('the Language switch shows the trainer in Polski and Čeština, keeps the choice, and comes back to English', async () => {
  await withSession(openApp(env), async (s) => {
    const language = s.role('combobox', 'Language');
    const options = await language.options();
    for (const name of ['English', 'Polski', 'Čeština']) assert.ok(options.includes(name), `${name} is offered: ${options}`);
    assert.equal(await s.evaluate(lang), 'en');
    await writeProgram(s, LATCH, 'Start');

    await language.select('Polski');
    await s.waitUntil(() => document.documentElement.lang === 'pl', null, { what: 'lang="pl"' });
    // The English words are gone; the program and its variables are the student's own.
    await s.role('button', 'Run').waitFor({ state: 'hidden' });
    assert.equal(await s.css('textarea').first.value(), LATCH);
    await s.role('checkbox', 'Start').waitFor();
    // The simulator runs in Polish: the controls' primary button is Run, and the motor's
    // lamp changes its (translated) state when Start is pressed.
    const motor = () => document.querySelector('.io-panel [role=img][aria-label^="Motor"]')?.getAttribute('aria-label');
    const off = await s.waitUntil(motor, null, { what: 'the Motor lamp' });
    await s.css('.controls button.primary').click();
    await s.role('checkbox', 'Start').check();
    await s.waitUntil((was) => {
      const now = document.querySelector('.io-panel [role=img][aria-label^="Motor"]')?.getAttribute('aria-label');
      return now && now !== was;
    }, off, { what: 'the Motor lamp on' });
    await s.screenshot(shot(env, 'language-pl'));

    // A reload keeps Polski.
    await s.reload();
    await s.css('textarea').first.waitFor();
    await s.waitUntil(() => document.documentElement.lang === 'pl', null, { what: 'lang="pl" after a reload' });

    const switchAgain = s.css('select', { hasText: 'Čeština' });
    await switchAgain.select('Čeština');
    await s.waitUntil(() => document.documentElement.lang === 'cs', null, { what: 'lang="cs"' });
    await s.role('button', 'Run').waitFor({ state: 'hidden' });
    await switchAgain.select('English');
    await s.waitUntil(() => document.documentElement.lang === 'en', null, { what: 'lang="en"' });
    await s.role('button', 'Run').waitFor();
    await s.role('combobox', 'Language').waitFor();
    await noErrors(s);
  });
});
