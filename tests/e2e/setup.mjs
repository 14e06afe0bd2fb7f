// What most browser test files share: the release build in dist/ served and one Chromium
// for the file, and the page opened as a person opens it.
import { before, after } from 'node:test';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { startServer } from './server.mjs';
import { launch } from './browser.mjs';

/** The repository's root. */
export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/**
 * Serves dist/ and launches Chromium before the file's tests and stops both after them;
 * `app.server` and `app.browser` are set once the tests run.
 */
export function useApp() {
  const app = { server: undefined, browser: undefined };
  before(async () => {
    app.server = await startServer(path.join(root, 'dist'));
    app.browser = await launch();
  });
  after(async () => {
    await app.browser?.close();
    await app.server?.close();
  });
  return app;
}

/** Opens the page at `url` in `context` once its ST editor is there; collects page errors. */
export async function openPage(context, url) {
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(url);
  await page.getByRole('textbox', { name: 'ST source' }).waitFor();
  return { page, errors };
}

/** Adds a ladder PROGRAM named `name` with `declarations` and shows it. */
export async function newLadderProgram(page, name, declarations) {
  await page.getByRole('button', { name: 'New ladder POU' }).click();
  await page.getByRole('textbox', { name: 'POU name' }).fill(name);
  await page.getByRole('combobox', { name: 'POU kind' }).selectOption('PROGRAM');
  await page.getByRole('button', { name: 'Create' }).click();
  const view = page.getByRole('region', { name: `Ladder diagram ${name}` });
  await view.waitFor();
  const decls = view.getByRole('textbox', { name: 'Declarations' });
  await decls.fill(declarations);
  await decls.press('Tab');
  return view;
}

/** The rung grid's cell at rung, row and column (1-based), by its accessible name. */
export const cell = (view, rung, row, col) =>
  view.getByRole('gridcell', { name: new RegExp(`^Rung ${rung}, row ${row}, column ${col}: `) });

/** The middle of what `loc` shows, in client pixels (it must be shown). */
export async function centre(loc) {
  const b = await loc.boundingBox();
  if (!b) throw new Error(`${loc} is not shown`);
  return { x: b.x + b.width / 2, y: b.y + b.height / 2 };
}

/** Types `text` into the ladder editor's Operand box and closes it with Enter. */
export async function operand(view, text) {
  const box = view.getByRole('textbox', { name: 'Operand' });
  await box.fill(text);
  await box.press('Enter');
  await box.waitFor({ state: 'detached' });
}

/** Whether the page scrolls sideways. */
export const scrollsSideways = (page) =>
  page.evaluate(() => document.scrollingElement.scrollWidth > window.innerWidth);

/** The latch exercise's program without its hold contact: Check fails. */
export const NO_SEAL = `PROGRAM Main
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
