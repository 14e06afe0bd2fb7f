// What every flow file of the cross-engine suite shares: the site served from dist/, the
// engine ENGINE names, a fresh profile per test, and the screenshots' place.
import { before, after } from 'node:test';
import assert from 'node:assert/strict';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { startServer } from './server.mjs';
import { launchEngine } from './driver.mjs';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/** Starts the server and the engine around the file's tests; returns live references. */
export function suite() {
  const env = { server: null, engine: null };
  before(async () => {
    env.server = await startServer(path.join(root, 'dist'));
    env.engine = await launchEngine();
  });
  after(async () => {
    // (WebKit tells its version once a session is open.)
    if (env.engine) console.log(`# engine: ${env.engine.label}`);
    await env.engine?.close();
    await env.server?.close();
  });
  return env;
}

/** A fresh profile showing the app at `url` (the server's by default), ready to use. */
export async function openApp(env, { url = env.server.url, width = 1400, height = 1000 } = {}) {
  const s = await env.engine.newSession({ width, height });
  try {
    await s.goto(url);
    await s.role('textbox', 'ST source').waitFor();
  } catch (e) {
    await s.close().catch(() => {});
    throw e;
  }
  return s;
}

/** Where this engine's screenshot `name` goes: docs/screenshots/engines/ENGINE-NAME.png. */
export const shot = (env, name) => path.join(root, 'docs/screenshots/engines', `${env.engine.name}-${name}.png`);

/** The page reported no uncaught error. */
export async function noErrors(s) {
  assert.deepEqual(await s.errors(), [], `${s.engine.name}: errors in the page`);
}

/** Runs `body(session)` and closes the session whatever happens. */
export async function withSession(sessionPromise, body) {
  const s = await sessionPromise;
  try {
    return await body(s);
  } finally {
    await s.close().catch(() => {});
  }
}

/** Fills the ST editor and waits until the check found the program (its I/O is shown). */
export async function writeProgram(s, text, firstInput) {
  await s.role('textbox', 'ST source').fill(text);
  if (firstInput) await s.role('checkbox', firstInput).waitFor();
}

/** The scan counter. */
export const scans = async (s) => Number(await s.role('status', 'Scan count').text());

/** One Step: one scan, waited for by the scan counter. */
export async function step(s) {
  const before = await scans(s);
  await s.role('button', 'Step').click();
  await s.waitUntil((n) => Number(document.querySelector('[aria-label="Scan count"]').textContent) === n + 1, before, { what: `scan ${before + 1}` });
}

/**
 * Waits until local storage holds a project whose stored text contains `text` (a string or
 * a RegExp). The app checks and then saves a moment after each edit, and a check powers a
 * fresh simulator on: once the last edit is saved, stepping is not undone by that check.
 */
export async function saved(s, text) {
  const want = text instanceof RegExp ? { re: text.source, flags: text.flags } : { text };
  await s.waitUntil((w) => Object.keys(localStorage).some((k) => {
    if (!k.includes('/project/')) return false;
    const stored = localStorage.getItem(k);
    return w.re !== undefined ? new RegExp(w.re, w.flags).test(stored) : stored.includes(w.text);
  }), want, { what: `a project holding ${String(text).slice(0, 80)} saved in local storage` });
}
