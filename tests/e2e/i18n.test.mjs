// The page in Polish and Czech (issue 33): a browser whose language is pl-PL or cs-CZ
// opens the page in that language; the ST editor with a located error, the ladder editor,
// the Petri net editor, an exercise with a failed Check and the problems page are walked
// with no English word of the catalogue left visible (program text excepted); the
// `Language` select switches back to English at once, with the unsaved edits intact.
//
// The test finds things by their names in the language shown, looked up in the catalogue
// (web/i18n/LANG/*.json) from their English names, so it follows the translations.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { readdirSync, readFileSync } from 'node:fs';
import { useApp, root } from './setup.mjs';

const app = useApp();

/** The catalogue of `lang`: key → text; the diagnostics' messages (core/i18n/) as `diag.KEY`. */
function catalogue(lang) {
  const dir = path.join(root, 'web/i18n', lang);
  const out = {};
  for (const f of readdirSync(dir).filter((f) => f.endsWith('.json'))) {
    Object.assign(out, JSON.parse(readFileSync(path.join(dir, f), 'utf8')));
  }
  const messages = JSON.parse(readFileSync(path.join(root, `core/i18n/messages.${lang}.json`), 'utf8'));
  for (const [key, text] of Object.entries(messages)) out[`diag.${key}`] = text;
  return out;
}
const EN = catalogue('en');
const TR = { pl: catalogue('pl'), cs: catalogue('cs') };

/** The text `english` (a whole catalogue text, under `key` when several keys have it) in `lang`. */
function L(lang, english, key = Object.keys(EN).find((k) => EN[k] === english)) {
  if (lang === 'en') return english;
  assert.equal(EN[key], english, `${key} is “${english}” in English`);
  assert.ok(key, `the catalogue has the English text “${english}”`);
  return TR[lang][key];
}

const escape = (s) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
/** A pattern of a catalogue text, its `{placeholders}` standing for anything. */
const pattern = (text) =>
  new RegExp(`^${text.split(/\{[a-z_]+\}/).map(escape).join('.+')}$`, 's');

/**
 * The English texts of the catalogue that the page shows in `lang` where a translation
 * differs: visible text and the accessible names and tooltips of visible elements, outside
 * program text (editors, code views) and outside `allowed` (the program's own names).
 */
async function englishLeft(page, lang, allowed, comments = []) {
  const shown = await page.evaluate(() => {
    const skip = 'textarea, pre, code, .code, .ed-code, .ld-operand, .ld-st, .ld-il, .petri-code, [translate="no"], option';
    const visible = (el) => {
      if (!el || el.closest(skip)) return false;
      const r = el.getBoundingClientRect();
      const style = getComputedStyle(el);
      return r.width > 0 && r.height > 0 && style.visibility !== 'hidden' && style.display !== 'none';
    };
    const out = new Set();
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      const text = n.textContent.trim();
      if (text && visible(n.parentElement)) out.add(text);
    }
    for (const el of document.body.querySelectorAll('[aria-label], [title], [placeholder]')) {
      if (!visible(el)) continue;
      for (const a of ['aria-label', 'title', 'placeholder']) {
        const v = el.getAttribute(a)?.trim();
        if (v) out.add(v);
      }
    }
    return [...out];
  });
  const left = [];
  for (const [key, english] of Object.entries(EN)) {
    if (TR[lang][key] === english || allowed.has(english)) continue;
    // A text that is mostly placeholders (`{pin} of {block}`) would match any sentence.
    if (english.replace(/\{[a-z_]+\}/g, '').replace(/[^\p{L}]/gu, '').length < 5) continue;
    const re = pattern(english);
    const hit = shown.find((s) => re.test(s) && !comments.includes(s));
    if (hit) left.push(`${key}: “${hit}”`);
  }
  return left;
}

const LATCH_ERROR = `PROGRAM Main
VAR_INPUT
    Start : BOOL;
    Stop : BOOL;
END_VAR
VAR_OUTPUT
    Motor : BOOL;
END_VAR
Motor := (Start OR Motor) AND NOT Stopp;
END_PROGRAM
`;
/** A fresh browser in `locale` on the page, its editor shown; page errors collected. */
async function openIn(locale, lang) {
  const context = await app.browser.newContext({ locale, viewport: { width: 1400, height: 1000 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(app.server.url);
  await page.getByRole('textbox', { name: L(lang, 'ST source', 'editor.st_source') }).waitFor();
  return { context, page, errors };
}

/** A PLCopen project whose program has an interface section the importer skips (line 8). */
const NOTED = `<?xml version="1.0" encoding="utf-8"?>
<project xmlns="http://www.plcopen.org/xml/tc6_0201">
  <fileHeader companyName="" productName="" productVersion="" creationDateTime="2026-01-01T00:00:00"/>
  <contentHeader name="Noted"><coordinateInfo><fbd><scaling x="1" y="1"/></fbd><ld><scaling x="1" y="1"/></ld><sfc><scaling x="1" y="1"/></sfc></coordinateInfo></contentHeader>
  <types><dataTypes/><pous>
    <pou name="Main" pouType="program"><interface>
      <localVars><variable name="Go"><type><BOOL/></type></variable></localVars>
      <accessVars><variable name="Far"><type><BOOL/></type></variable></accessVars>
    </interface><body><ST><xhtml xmlns="http://www.w3.org/1999/xhtml">Go := NOT Go;</xhtml></ST></body></pou>
  </pous></types>
  <instances><configurations/></instances>
</project>`;

/** A PNML net whose initial marking is not a number. */
const BAD_PNML = `<?xml version="1.0"?><pnml xmlns="http://www.pnml.org/version-2009/grammar/pnml">
<net id="n" type="http://www.pnml.org/version-2009/grammar/ptnet"><name><text>Net</text></name>
<page id="g"><place id="a"><initialMarking><text>many</text></initialMarking></place></page></net></pnml>`;

/** The program's own names: never translated. */
const PROGRAM_NAMES = new Set(['Main', 'Start', 'Stop', 'Motor', 'Stopp', 'Latch', 'Cycle', 'Busy', 'Go']);

for (const [locale, lang] of [['pl-PL', 'pl'], ['cs-CZ', 'cs']]) {
  test(`a ${locale} browser opens the page in ${lang}; every view walked shows no English; back to English keeps the edits`, async () => {
    const context = await app.browser.newContext({ locale, viewport: { width: 1400, height: 1000 } });
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(e.message));
    const shots = path.join(root, 'docs/screenshots');
    await page.goto(app.server.url);
    const editor = page.getByRole('textbox', { name: L(lang, 'ST source', 'editor.st_source') });
    await editor.waitFor();
    // The first project's comments: its own words, shown as descriptions and tooltips while
    // its build still runs.
    const comments = (await page.locator('.tok-com').allTextContents()).map((c) => c.replace(/^\(\*|\*\)$/g, '').trim());
    assert.equal(await page.evaluate(() => document.documentElement.lang), lang);
    // Its name in the language shown, with the English word beside it for the lost.
    const named = page.getByRole('combobox', { name: `${L(lang, 'Language', 'header.language')} (Language)` });
    assert.equal(await named.inputValue(), lang);
    const select = page.locator('select.language-select');

    // The ST editor with a located error.
    await editor.fill(LATCH_ERROR);
    await page.locator('.ed-problem').first().waitFor();
    // The error's message in the language shown (a diagnostic is data: its key, the
    // misspelt name and the name meant), program text as written.
    const said = (key, name) => L(lang, EN[key], key).replace('{name}', name);
    const undeclared = `${said('diag.not_declared', 'Stopp')}; ${said('diag.did_you_mean', 'Stop')}`;
    await page.getByText(undeclared).first().waitFor();
    assert.deepEqual(await englishLeft(page, lang, PROGRAM_NAMES, comments), [], 'the ST editor and the panels');
    await page.screenshot({ path: path.join(shots, `i18n-${lang}-st.png`) });
    // The same diagnostic in English as soon as the page is (it is data, not a sentence).
    await select.selectOption('en');
    await page.getByText('`Stopp` is not declared; did you mean Stop?').first().waitFor();
    await select.selectOption(lang);
    await page.getByText(undeclared).first().waitFor();

    // The ladder editor.
    await page.getByRole('button', { name: L(lang, 'New ladder POU') }).click();
    // A reserved name is refused, and the dialog says why in the language shown.
    await page.getByRole('textbox', { name: L(lang, 'POU name') }).fill('TON');
    await page.locator('.field-error', { hasText: 'TON' }).waitFor();
    assert.deepEqual(await englishLeft(page, lang, PROGRAM_NAMES, comments), [], 'the New POU dialog');
    await page.getByRole('textbox', { name: L(lang, 'POU name') }).fill('Latch');
    await page.getByRole('button', { name: L(lang, 'Create') }).click();
    const ladder = page.getByRole('region', { name: new RegExp(`Latch$`) }).first();
    await ladder.waitFor();
    await page.locator('.ld-palette, [role="toolbar"]').first().waitFor();
    assert.deepEqual(await englishLeft(page, lang, PROGRAM_NAMES, comments), [], 'the ladder editor');
    await page.screenshot({ path: path.join(shots, `i18n-${lang}-ladder.png`) });

    // The Petri net editor.
    await page.getByRole('button', { name: L(lang, 'New Petri net POU') }).click();
    await page.getByRole('textbox', { name: L(lang, 'POU name') }).fill('Cycle');
    await page.getByRole('button', { name: L(lang, 'Create') }).click();
    await page.getByRole('group', { name: L(lang, 'Net canvas') }).waitFor();
    assert.deepEqual(await englishLeft(page, lang, PROGRAM_NAMES, comments), [], 'the Petri net editor');
    await page.screenshot({ path: path.join(shots, `i18n-${lang}-petri.png`) });

    // Back to English: every view in English, the edits intact.
    await select.selectOption('en');
    await page.getByRole('button', { name: 'New ladder POU' }).waitFor();
    assert.equal(await page.evaluate(() => document.documentElement.lang), 'en');
    assert.ok(await page.getByRole('group', { name: 'Net canvas' }).isVisible(), 'the Petri net is still shown');
    const pous = await page.locator('.pou-tab, [role="tab"]').allTextContents();
    assert.ok(pous.join(' ').includes('Latch') && pous.join(' ').includes('Cycle'), `the new POUs are kept: ${pous}`);
    await page.locator('.pou-tab').first().click();
    assert.equal(await page.getByRole('textbox', { name: 'ST source' }).inputValue(), LATCH_ERROR, 'the unsaved ST edit is kept');

    // And back to the language, kept across a reload.
    await select.selectOption(lang);
    await page.getByRole('button', { name: L(lang, 'New ladder POU') }).waitFor();
    await page.reload();
    await page.getByRole('button', { name: L(lang, 'New ladder POU') }).waitFor();

    // The examples' menu in the language (titles and descriptions), and an example opened is named in it.
    const title = TR[lang]['examples.latch_ladder'];
    const examples = page.getByRole('combobox', { name: L(lang, 'Open example', 'header.open_example') });
    const option = examples.locator('option', { hasText: title });
    assert.equal(await option.getAttribute('title'), TR[lang]['examples.latch_ladder_about'], 'its description');
    await examples.selectOption({ label: title });
    await page.locator('.project-name', { hasText: title }).waitFor();
    assert.deepEqual(errors, []);
    await context.close();
  });

  test(`an exercise with a failed Check, in ${lang}`, async () => {
    const { context, page, errors } = await openIn(locale, lang);
    await page.getByRole('button', { name: L(lang, 'Exercises', 'header.exercises'), exact: true }).click();
    await page.locator('.catalogue-item[data-exercise="latch"] button').first().click();
    const panel = page.getByRole('region', { name: L(lang, 'Exercise', 'exercise.exercise') });
    await panel.waitFor();
    await page.getByRole('textbox', { name: L(lang, 'ST source', 'editor.st_source') }).fill(LATCH_ERROR.replace('Stopp', 'Stop').replace('(Start OR Motor)', 'Start'));
    await page.waitForTimeout(400);
    await page.getByRole('button', { name: L(lang, 'Check'), exact: true }).click();
    await page.locator('.report-scenario.failed').first().waitFor();
    assert.deepEqual(await englishLeft(page, lang, PROGRAM_NAMES), [], 'the exercise and its report');
    await page.screenshot({ path: path.join(root, `docs/screenshots/i18n-${lang}-exercise.png`) });
    assert.deepEqual(errors, []);
    await context.close();
  });

  test(`an imported file's notes and a broken file's error, in ${lang}`, async () => {
    const { context, page, errors } = await openIn(locale, lang);
    const input = page.getByLabel(L(lang, 'Import project file', 'header.import_file'));
    const prefix = (key) => L(lang, EN[key], key).split('{')[0];

    // A PLCopen project with an interface section the trainer does not read: imported,
    // with a note at the section's place in the file, all in the language shown.
    await input.setInputFiles({ name: 'notes.xml', mimeType: 'application/xml', buffer: Buffer.from(NOTED) });
    const imported = page.locator('.banner-info span', { hasText: prefix('header.imported') });
    await imported.waitFor();
    const text = await imported.innerText();
    const at = L(lang, EN['header.import_note_at'], 'header.import_note_at')
      .replace('{line}', '8').replace('{column}', '7').split('{note}')[0];
    assert.ok(text.includes(at), `the note's place in ${lang}: ${text}`);
    assert.ok(text.includes('<accessVars>') && text.includes('Main'), `program text kept: ${text}`);
    assert.deepEqual(await englishLeft(page, lang, PROGRAM_NAMES), [], 'the import notes');
    await page.screenshot({ path: path.join(root, `docs/screenshots/i18n-${lang}-import.png`) });

    // A PNML net whose marking is not a number, and a file that is not well-formed XML: the
    // errors in the language shown, nothing changed.
    for (const [name, body] of [['net.pnml', BAD_PNML], ['broken.xml', '<?xml version="1.0"?>\n<project><pou></project>']]) {
      await input.setInputFiles({ name, mimeType: 'application/xml', buffer: Buffer.from(body) });
      const failed = page.locator('.banner-error span', { hasText: name });
      await failed.waitFor();
      assert.match(await failed.innerText(), pattern(L(lang, EN['header.import_failed'], 'header.import_failed')));
      assert.deepEqual(await englishLeft(page, lang, PROGRAM_NAMES), [], `the error of ${name}`);
    }
    assert.deepEqual(errors, []);
    await context.close();
  });

  test(`the problems page in ${lang}`, async () => {
    const context = await app.browser.newContext({ locale });
    const page = await context.newPage();
    await page.goto(`${app.server.url}problems.${lang}.html`);
    assert.equal(await page.evaluate(() => document.documentElement.lang), lang);
    const text = await page.locator('main, body').first().innerText();
    assert.ok(!/\bthe parser expected something else here\b/.test(text), 'no English title left');
    await page.screenshot({ path: path.join(root, `docs/screenshots/i18n-${lang}-problems.png`) });
    await context.close();
  });
}
