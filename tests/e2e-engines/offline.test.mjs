// Offline after a first visit (issue 32), in Firefox or WebKit (ENGINE): once the service
// worker holds the build, the trainer opens with the server gone, an example runs and an
// exercise is checked (both workers and their code come from the cache).
//
// In an engine with service workers a missing or broken one fails here. An engine without
// them must still open and run the app online (its fallback): the test says so in its
// output and passes.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { suite, openApp, withSession, noErrors, shot, root } from './harness.mjs';
import { startServer } from './server.mjs';

const env = suite();

test('after one visit the trainer opens, runs an example and checks an exercise with the server gone', async () => {
  await withSession(openApp(env), async (s) => {
    const supported = await s.evaluate(() => 'serviceWorker' in navigator && window.isSecureContext);
    if (!supported) {
      // The engine's fallback: no offline copy, but the app works online as ever.
      await s.role('button', 'Run').waitFor();
      console.log(`# ${env.engine.label} has no service workers: the app runs online only`);
      await noErrors(s);
      return;
    }
    const sw = await s.evaluate(async () => {
      const registration = await navigator.serviceWorker.ready;
      const worker = registration.active;
      if (worker.state !== 'activated') {
        await new Promise((done) => worker.addEventListener('statechange', () => worker.state === 'activated' && done()));
      }
      return { state: worker.state, caches: await caches.keys() };
    });
    assert.equal(sw.state, 'activated');
    assert.ok(sw.caches.length >= 1, 'the build is cached');
    console.log(`# ${env.engine.label} has service workers: the offline copy is tested`);

    env.server.setOffline(true);
    try {
      await s.reload();
      await s.role('textbox', 'ST source').waitFor();
      // An example opens and runs.
      await s.role('combobox', 'Open example').select('latch-ladder.plcproj.json');
      // (Opening a project stops the PLC: Run is for the example once it is open.)
      await s.css('.banner', { hasText: 'Opened the example “Ladder latch”' }).waitFor();
      await s.role('button', 'Run').click();
      await s.role('checkbox', 'Start').check();
      await s.role('img', 'Motor: ON').waitFor();
      await s.role('button', 'Pause').click();
      // A shipped exercise opens and is checked (the exercise worker, from the cache).
      await s.role('button', 'Exercises').click();
      await s.role('list', 'Exercise list').role('button', 'Start/stop motor latch').click();
      await s.role('region', 'Exercise').role('heading', 'Start/stop motor latch').waitFor();
      await s.role('button', 'Check').click();
      await s.role('region', 'Report').css('.report-score', { hasText: 'of 3' }).waitFor();
      await s.screenshot(shot(env, 'offline'));
    } finally {
      env.server.setOffline(false);
    }
    await noErrors(s);
  });
});

// Caching the site (some 330 files) must not hold up what the student asks for meanwhile:
// on a first visit over a network with some latency, an exercise opens (its views, the
// exercise worker and its code, the exercise file) while the service worker is still
// installing. When it fetched every file at once, the page's and the worker's requests
// waited behind all of them (WebKit: over a minute on a loaded machine).
test('on a first visit an exercise opens while the service worker is still caching the site', async () => {
  const server = await startServer(path.join(root, 'dist'), '/trainer/', {}, { delayMs: 60 });
  try {
    await withSession(openApp(env, { url: server.url }), async (s) => {
      const supported = await s.evaluate(() => 'serviceWorker' in navigator && window.isSecureContext);
      if (!supported) {
        console.log(`# ${env.engine.label} has no service workers: nothing is cached meanwhile`);
        return;
      }
      const installing = () => navigator.serviceWorker.getRegistration().then((r) => Boolean(r?.installing));
      await s.waitUntil(installing, null, { what: 'the service worker installing' });
      await s.role('button', 'Exercises').click();
      await s.role('list', 'Exercise list').role('button', 'Start/stop motor latch').click();
      await s.role('region', 'Exercise').role('heading', 'Start/stop motor latch').waitFor();
      assert.ok(await s.evaluate(installing), 'the exercise opened only once the whole site was cached');
      await noErrors(s);
    });
  } finally {
    await server.close();
  }
});
