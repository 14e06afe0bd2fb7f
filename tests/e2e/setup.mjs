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
