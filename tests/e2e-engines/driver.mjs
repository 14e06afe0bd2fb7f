// One small driver for the cross-engine suite: the same flow file drives Firefox (Debian's
// firefox-esr, through puppeteer-core over WebDriver BiDi) and WebKit (Debian's
// WebKitWebDriver and MiniBrowser, through selenium-webdriver over classic WebDriver).
// No browser is ever downloaded: both are the system's.
//
// A flow sees a `Session` (a fresh browser profile: empty storage, no service worker) and
// finds elements by role and accessible name (`s.role('button', 'Run')`), clicks them
// with the real pointer at their middle once nothing covers it, types with the real
// keyboard, drags with real pointer events, and waits for conditions (never for a time).
// `ENGINE` chooses the engine: `firefox` or `webkit`.
import { mkdirSync, existsSync, readdirSync } from 'node:fs';
import { writeFile } from 'node:fs/promises';
import path from 'node:path';
import { PAGE_SRC } from './page.mjs';

/** How long a condition may take to hold (the test machine is shared and often loaded). */
export const TIMEOUT = Number(process.env.E2E_TIMEOUT_MS ?? 60000);
const POLL_MS = 50;
/** How long a browser may take to start. */
const LAUNCH_MS = 30000;

const delay = (ms) => new Promise((r) => setTimeout(r, ms));

/** Run in the page: the texts of its alerts, status lines and loading states. */
function PAGE_STATE() {
  const seen = [];
  for (const el of document.querySelectorAll('[role=alert], [role=status], .lazy-loading, .lazy-failed, .banner')) {
    const text = (el.textContent ?? '').replace(/\s+/g, ' ').trim();
    if (text && !el.closest('[hidden]') && !seen.includes(text)) seen.push(text);
  }
  return seen.map((t) => t.slice(0, 200));
}

const toQuery = (q) => {
  const out = { ...q };
  if (q.name instanceof RegExp) out.name = { re: q.name.source, flags: q.name.flags };
  if (q.within) out.within = toQuery(q.within.query ?? q.within);
  return out;
};

/** An element described by role and name (or CSS), resolved anew on every use. */
export class Locator {
  constructor(session, query) {
    this.session = session;
    this.query = toQuery(query);
  }

  /** An element inside this one. */
  role(role, name, opts = {}) {
    return new Locator(this.session, { role, name, ...opts, within: this.query });
  }

  css(css, opts = {}) {
    return new Locator(this.session, { css, ...opts, within: this.query });
  }

  nth(i) {
    return new Locator(this.session, { ...this.query, nth: i });
  }

  get first() {
    return this.nth(0);
  }

  /** Runs a page operation on the element once it resolves to exactly one. */
  async op(op, arg, what = op, timeout = TIMEOUT) {
    return this.session.until(`${what} ${describe(this.query)}`, () => this.session.backend.run(op, this.query, arg), timeout);
  }

  async waitFor({ state = 'visible', timeout = TIMEOUT } = {}) {
    const q = { ...this.query, state };
    await this.session.until(`wait for ${describe(q)} (${state})`, () => this.session.backend.run('wait', q), timeout);
  }

  async count() {
    return (await this.session.backend.run('count', { ...this.query, state: this.query.state ?? 'attached' })).value;
  }

  /** The accessible names of every match, in document order. */
  async names() {
    return (await this.session.backend.run('names', this.query)).value;
  }

  /**
   * Presses the element with the real pointer. A press the page moved away from (a scroll
   * or redraw between finding the point and pressing) is stopped before the page sees it
   * and made again where the element is now (`guardPress` in page.mjs).
   */
  async click(opts = {}) {
    const arg = { guard: !this.session.dialogExpected, ...(opts.offset ? { dx: opts.offset.x, dy: opts.offset.y } : {}) };
    await this.session.until(`click ${describe(this.query)}`, async () => {
      const p = await this.session.backend.run('point', this.query, arg);
      if (!p.ok) return p;
      await this.session.backend.pointer([{ type: 'move', ...p.value }, { type: 'down' }, { type: 'up' }]);
      if (!arg.guard) return { ok: true };
      // A click that navigated has nothing to report: it arrived.
      const r = await this.session.backend.run('pressed', this.query).catch(() => ({ value: { hit: null } }));
      return r.value?.hit === false ? { ok: false, why: `the press landed on ${r.value.on}` } : { ok: true };
    });
  }

  /** The middle of the element, in viewport pixels (scrolled into view, not covered). */
  async point() {
    return this.op('point');
  }

  async fill(text) {
    await this.op('fill', text);
  }

  async focus() {
    await this.op('focus');
  }

  /** Focuses the element and presses a key on it (e.g. 'Enter', 'Control+z'). */
  async press(key) {
    await this.focus();
    await this.session.press(key);
  }

  async select(valueOrLabel) {
    await this.op('select', valueOrLabel);
  }

  async setChecked(on) {
    if ((await this.op('checked')) !== on) await this.click();
    await this.session.until(`${describe(this.query)} ${on ? 'checked' : 'unchecked'}`, async () => {
      const r = await this.session.backend.run('checked', this.query);
      return r.ok && r.value === on ? { ok: true } : { ok: false, why: r.why ?? 'not yet' };
    });
  }

  check() { return this.setChecked(true); }

  uncheck() { return this.setChecked(false); }

  value() { return this.op('value'); }

  checked() { return this.op('checked'); }

  attr(name) { return this.op('attr', name, `read ${name} of`); }

  text() { return this.op('text'); }

  name() { return this.op('name'); }

  options() { return this.op('options'); }

  isFocused() { return this.op('focused'); }

  /** Viewport rectangle `{ x, y, width, height }` (scrolled into view first). */
  box() { return this.op('box'); }

  /** Waits until the text is `want` (or matches the RegExp). */
  async waitForText(want, timeout = TIMEOUT) {
    await this.session.until(`${describe(this.query)} text ${want}`, async () => {
      const r = await this.session.backend.run('text', this.query);
      if (!r.ok) return r;
      const good = want instanceof RegExp ? want.test(r.value ?? '') : r.value === want;
      return good ? { ok: true } : { ok: false, why: `the text is ${JSON.stringify(r.value)}` };
    }, timeout);
  }

  /** Waits until the attribute has the value (or matches the RegExp). */
  async waitForAttr(name, want, timeout = TIMEOUT) {
    await this.session.until(`${describe(this.query)} [${name}] ${want}`, async () => {
      const r = await this.session.backend.run('attr', this.query, name);
      if (!r.ok) return r;
      const good = want instanceof RegExp ? want.test(r.value ?? '') : r.value === want;
      return good ? { ok: true } : { ok: false, why: `${name} is ${JSON.stringify(r.value)}` };
    }, timeout);
  }
}

function describe(q) {
  const parts = [];
  if (q.role) parts.push(q.role);
  if (q.name !== undefined) parts.push(typeof q.name === 'object' ? `/${q.name.re}/` : `"${q.name}"`);
  if (q.css) parts.push(q.css);
  if (q.hasText !== undefined) parts.push(`with text "${q.hasText}"`);
  if (q.nth !== undefined) parts.push(`#${q.nth}`);
  return q.within ? `${describe(q.within)} > ${parts.join(' ')}` : parts.join(' ');
}

/** What a flow drives: one fresh browser profile with one page. */
export class Session {
  constructor(engine, backend) {
    this.engine = engine;
    this.backend = backend;
  }

  role(role, name, opts = {}) {
    return new Locator(this, { role, name, ...opts });
  }

  css(css, opts = {}) {
    return new Locator(this, { css, ...opts });
  }

  /** Polls `probe` (→ `{ ok, value, why }`) until it holds; fails with its last reason. */
  async until(what, probe, timeout = TIMEOUT) {
    const end = Date.now() + timeout;
    let last = 'never checked';
    for (;;) {
      let r;
      try {
        r = await probe();
      } catch (e) {
        // A page in the middle of a navigation answers nothing yet.
        if (!/navigat|context|detached|destroyed|stale|unload|Execution context/i.test(String(e?.message))) throw e;
        r = { ok: false, why: String(e.message).split('\n')[0] };
      }
      if (r.ok) return r.value;
      last = r.why;
      if (Date.now() > end) {
        throw new Error(`${this.engine.name}: ${what}: not done after ${timeout} ms: ${last}${await this.whatItShows()}`);
      }
      await delay(POLL_MS);
    }
  }

  /**
   * What the page shows that may say why a wait failed (its banners, alerts and loading
   * states, its uncaught errors), as a suffix for the failure's message; '' when it says
   * nothing or cannot be asked.
   */
  async whatItShows() {
    try {
      const said = await this.backend.evaluate(`(${PAGE_STATE.toString()})()`);
      const errors = await this.backend.errors();
      const parts = [...(said ?? []), ...errors.map((e) => `error: ${e}`)];
      return parts.length ? `; the page shows: ${parts.join(' | ').slice(0, 1500)}` : '';
    } catch {
      return '';
    }
  }

  /** Waits until `fn(arg)`, run in the page, returns something truthy; returns that. */
  async waitUntil(fn, arg, { timeout = TIMEOUT, what } = {}) {
    return this.until(what ?? `the page condition ${String(fn).slice(0, 120)}`, async () => {
      const value = await this.evaluate(fn, arg);
      return value ? { ok: true, value } : { ok: false, why: `it returned ${JSON.stringify(value)}` };
    }, timeout);
  }

  /** Runs `fn(arg)` in the page (it may be async) and returns its JSON value. */
  evaluate(fn, arg) {
    return this.backend.evaluate(`(${fn.toString()})(${JSON.stringify(arg ?? null)})`);
  }

  goto(url) { return this.backend.goto(url); }

  reload() { return this.backend.reload(); }

  url() { return this.backend.url(); }

  /** A key or a chord as Playwright spells them: 'Enter', 'ArrowRight', 'Control+Shift+Z', 'a'. */
  press(key) { return this.backend.press(key); }

  /** Types text with the keyboard into what has the focus. */
  type(text) { return this.backend.type(text); }

  async clickAt({ x, y }) {
    await this.backend.pointer([{ type: 'move', x, y }, { type: 'down' }, { type: 'up' }]);
  }

  /** Presses the mouse at `from`, moves it in `steps` to `to` and releases it there. */
  async drag(from, to, steps = 8) {
    const seq = [{ type: 'move', ...from }, { type: 'down' }];
    for (let i = 1; i <= steps; i++) {
      seq.push({ type: 'move', x: from.x + ((to.x - from.x) * i) / steps, y: from.y + ((to.y - from.y) * i) / steps });
    }
    seq.push({ type: 'up' });
    await this.backend.pointer(seq);
  }

  /** Drags from the middle of one element to the middle of another. */
  async dragTo(from, to, steps = 8) {
    const a = await from.point();
    const b = await to.box();
    await this.drag(a, { x: b.x + b.width / 2, y: b.y + b.height / 2 }, steps);
  }

  /** Saves a PNG of the page (the whole page where the engine can, else the viewport). */
  async screenshot(file) {
    mkdirSync(path.dirname(file), { recursive: true });
    await this.backend.screenshot(file);
  }

  /** Uncaught errors and unhandled rejections the page reported so far. */
  errors() { return this.backend.errors(); }

  /** Accepts (or dismisses) the confirm() that `action` opens. */
  async answerDialog(accept, action) {
    // A press that opens a dialog is not checked afterwards (the page is blocked by it).
    this.dialogExpected = true;
    try {
      return await this.backend.answerDialog(accept, action);
    } finally {
      this.dialogExpected = false;
    }
  }

  /** Another tab of the same profile (same storage), as a Session of its own. */
  async newTab() { return new Session(this.engine, await this.backend.newTab()); }

  close() { return this.backend.close(); }
}

/* ------------------------------------------------------------------ Firefox (BiDi) -- */

const PUPPETEER_KEYS = { Space: ' ' };

class FirefoxBackend {
  constructor(context, page, ownsContext = true) {
    this.context = context;
    this.page = page;
    this.ownsContext = ownsContext;
    this.pageErrors = [];
    page.on('pageerror', (e) => this.pageErrors.push(e?.message ?? String(e)));
  }

  async run(op, q, arg) {
    return this.page.evaluate(`(${PAGE_SRC})(${JSON.stringify(op)}, ${JSON.stringify(q)}, ${JSON.stringify(arg ?? null)})`);
  }

  evaluate(src) { return this.page.evaluate(src); }

  async goto(url) { await this.page.goto(url, { waitUntil: 'load', timeout: TIMEOUT }); }

  async reload() { await this.page.reload({ waitUntil: 'load', timeout: TIMEOUT }); }

  async url() { return this.page.url(); }

  async press(chord) {
    const keys = chord === '+' ? ['+'] : chord.split('+').map((k) => PUPPETEER_KEYS[k] ?? k);
    const last = keys.pop();
    for (const k of keys) await this.page.keyboard.down(k);
    await this.page.keyboard.press(last);
    for (const k of keys.reverse()) await this.page.keyboard.up(k);
  }

  async type(text) { await this.page.keyboard.type(text); }

  async pointer(seq) {
    for (const a of seq) {
      if (a.type === 'move') await this.page.mouse.move(a.x, a.y);
      else if (a.type === 'down') await this.page.mouse.down();
      else if (a.type === 'up') await this.page.mouse.up();
    }
  }

  async screenshot(file) { await this.page.screenshot({ path: file, fullPage: true }); }

  async errors() { return [...this.pageErrors]; }

  async answerDialog(accept, action) {
    const answered = new Promise((resolve) => {
      this.page.once('dialog', async (d) => {
        await (accept ? d.accept() : d.dismiss());
        resolve();
      });
    });
    await action();
    await answered;
  }

  async newTab() {
    const page = await this.context.newPage();
    page.setDefaultTimeout(TIMEOUT);
    await page.setViewport(this.page.viewport());
    return new FirefoxBackend(this.context, page, false);
  }

  async close() { await (this.ownsContext ? this.context.close() : this.page.close()); }
}

async function launchFirefox() {
  const { default: puppeteer } = await import('puppeteer-core');
  const executablePath = process.env.FIREFOX ?? '/usr/bin/firefox-esr';
  if (!existsSync(executablePath)) throw new Error(`no Firefox at ${executablePath}: run scripts/setup.sh (apt firefox-esr)`);
  const browser = await puppeteer.launch({
    browser: 'firefox',
    protocol: 'webDriverBiDi',
    executablePath,
    headless: true,
    protocolTimeout: 4 * TIMEOUT,
    timeout: 2 * TIMEOUT,
    extraPrefsFirefox: {
      // Nothing but the page under test talks to the network.
      'app.update.enabled': false,
      'browser.safebrowsing.downloads.remote.enabled': false,
      'network.captive-portal-service.enabled': false,
      'network.connectivity-service.enabled': false,
      'datareporting.policy.dataSubmissionEnabled': false,
      'toolkit.telemetry.enabled': false,
    },
  });
  const version = (await browser.version()).replace(/^firefox\//i, '');
  return {
    name: 'firefox',
    label: `Firefox ESR ${version}`,
    version,
    async newSession({ width = 1280, height = 800 } = {}) {
      const context = await browser.createBrowserContext();
      const page = await context.newPage();
      page.setDefaultTimeout(TIMEOUT);
      await page.setViewport({ width, height });
      return new Session(this, new FirefoxBackend(context, page));
    },
    async close() { await browser.close(); },
  };
}

/* ---------------------------------------------------------- WebKit (WebKitWebDriver) -- */

const COLLECT_ERRORS = `
  if (!window.__e2eErrors) {
    window.__e2eErrors = [];
    addEventListener('error', (e) => window.__e2eErrors.push(e.message || String(e.error)));
    addEventListener('unhandledrejection', (e) => window.__e2eErrors.push('unhandled rejection: ' + (e.reason?.message ?? e.reason)));
  }`;

class WebKitBackend {
  constructor(driver, service, webdriver, handle, shared = { current: handle }) {
    this.raw = driver;
    this.service = service;
    this.wd = webdriver;
    this.handle = handle;
    this.shared = shared;
    this.pageErrors = [];
  }

  /** The WebDriver session, switched to this backend's tab when another one was in use. */
  async use() {
    if (this.shared.current !== this.handle) {
      await this.raw.switchTo().window(this.handle);
      this.shared.current = this.handle;
    }
    return this.raw;
  }

  async run(op, q, arg) {
    return (await this.use()).executeScript(`return (${PAGE_SRC})(arguments[0], arguments[1], arguments[2]);`, op, q, arg ?? null);
  }

  async evaluate(src) {
    const r = await (await this.use()).executeAsyncScript(`
      const done = arguments[arguments.length - 1];
      Promise.resolve().then(() => ${src}).then((v) => done({ v: v === undefined ? null : v }), (e) => done({ e: String(e && e.stack || e) }));`);
    if (r && 'e' in r) throw new Error(`in the page: ${r.e}`);
    return r?.v;
  }

  /** Keeps the errors of the page about to be left, then watches the new one. */
  async harvest() {
    try {
      const list = await (await this.use()).executeScript('return window.__e2eErrors ? window.__e2eErrors.splice(0) : [];');
      this.pageErrors.push(...list);
    } catch {
      // No page yet.
    }
  }

  async watch() { await (await this.use()).executeScript(COLLECT_ERRORS); }

  async goto(url) {
    await this.harvest();
    const before = await (await this.use()).getCurrentUrl().catch(() => '');
    await (await this.use()).get(url);
    // A link that changes only the #fragment does not load the page again: a person
    // would press Enter in the address bar, which for such a link is a reload.
    const strip = (u) => u.split('#')[0];
    if (before && strip(before) === strip(url) && before !== url && url.includes('#')) await (await this.use()).navigate().refresh();
    await this.watch();
  }

  async reload() {
    await this.harvest();
    await (await this.use()).navigate().refresh();
    await this.watch();
  }

  async url() { return (await this.use()).getCurrentUrl(); }

  keyOf(k) {
    const { Key } = this.wd;
    const map = {
      Enter: Key.ENTER, Tab: Key.TAB, Escape: Key.ESCAPE, Backspace: Key.BACK_SPACE, Delete: Key.DELETE,
      ArrowLeft: Key.ARROW_LEFT, ArrowRight: Key.ARROW_RIGHT, ArrowUp: Key.ARROW_UP, ArrowDown: Key.ARROW_DOWN,
      Home: Key.HOME, End: Key.END, PageUp: Key.PAGE_UP, PageDown: Key.PAGE_DOWN, Space: Key.SPACE,
      Control: Key.CONTROL, Shift: Key.SHIFT, Alt: Key.ALT, Meta: Key.META,
    };
    if (map[k]) return map[k];
    if ([...k].length !== 1) throw new Error(`unknown key ${k}`);
    return k;
  }

  async press(chord) {
    const keys = chord === '+' ? ['+'] : chord.split('+');
    const last = this.keyOf(keys.pop());
    const mods = keys.map((k) => this.keyOf(k));
    let a = (await this.use()).actions({ async: true });
    for (const m of mods) a = a.keyDown(m);
    a = a.keyDown(last).keyUp(last);
    for (const m of mods.reverse()) a = a.keyUp(m);
    await a.perform();
  }

  async type(text) {
    let a = (await this.use()).actions({ async: true });
    for (const ch of text) a = a.keyDown(ch).keyUp(ch);
    await a.perform();
  }

  async pointer(seq) {
    const { Origin, Button } = this.wd;
    let a = (await this.use()).actions({ async: true });
    for (const step of seq) {
      if (step.type === 'move') a = a.move({ x: Math.round(step.x), y: Math.round(step.y), origin: Origin.VIEWPORT, duration: 0 });
      else if (step.type === 'down') a = a.press(Button.LEFT);
      else if (step.type === 'up') a = a.release(Button.LEFT);
    }
    await a.perform();
  }

  async screenshot(file) {
    await writeFile(file, Buffer.from(await (await this.use()).takeScreenshot(), 'base64'));
  }

  async errors() {
    await this.harvest();
    return [...this.pageErrors];
  }

  async answerDialog(accept, action) {
    await action();
    const alert = await (await this.use()).wait(this.wd.until.alertIsPresent(), TIMEOUT);
    await (accept ? alert.accept() : alert.dismiss());
  }

  async newTab() {
    await (await this.use()).getWindowHandle();
    // A window rather than a tab: MiniBrowser shows one tab at a time and switching to a
    // tab over WebDriver does not bring it forward, and a click on a hidden tab never
    // arrives (the session waits forever). Two windows of one session share the profile.
    await this.raw.switchTo().newWindow('window');
    const handle = await this.raw.getWindowHandle();
    this.shared.current = handle;
    return new WebKitBackend(this.raw, null, this.wd, handle, this.shared);
  }

  async close() {
    if (!this.service) {
      // A tab of another session: close it and go back to the first one.
      await (await this.use()).close();
      const [first] = await this.raw.getAllWindowHandles();
      if (first) {
        await this.raw.switchTo().window(first);
        this.shared.current = first;
      }
      return;
    }
    try {
      await this.raw.quit();
    } finally {
      await this.service.kill();
    }
  }
}

function miniBrowser() {
  if (process.env.MINIBROWSER) return process.env.MINIBROWSER;
  for (const dir of ['/usr/lib', '/usr/libexec']) {
    let entries = [];
    try {
      entries = readdirSync(dir);
    } catch {
      continue;
    }
    for (const sub of ['', ...entries]) {
      for (const api of ['webkit2gtk-4.1', 'webkit2gtk-4.0', 'webkitgtk-6.0']) {
        const p = path.join(dir, sub, api, 'MiniBrowser');
        if (existsSync(p)) return p;
      }
    }
  }
  throw new Error('no MiniBrowser found: run scripts/setup.sh (apt webkit2gtk-driver)');
}

async function launchWebKit() {
  const wd = await import('selenium-webdriver');
  const { default: remote } = await import('selenium-webdriver/remote/index.js');
  if (!process.env.DISPLAY) throw new Error('WebKit (MiniBrowser) has no headless mode: run the suite under xvfb-run -a');
  const driverPath = process.env.WEBKIT_DRIVER ?? '/usr/bin/WebKitWebDriver';
  if (!existsSync(driverPath)) throw new Error(`no WebKitWebDriver at ${driverPath}: run scripts/setup.sh (apt webkit2gtk-driver)`);
  const binary = miniBrowser();
  const engine = {
    name: 'webkit',
    label: 'WebKitGTK',
    version: '',
    /** Every session is its own WebKitWebDriver and MiniBrowser: an ephemeral profile. */
    async newSession({ width = 1280, height = 800 } = {}) {
      // Now and then (about one launch in twenty on a loaded machine) MiniBrowser never
      // answers its WebKitWebDriver and the new session waits forever: that launch is
      // given up after a while and made again, at most twice.
      let driver;
      let service;
      for (let attempt = 1; !driver; attempt++) {
        service = new remote.DriverService.Builder(driverPath).setHostname('127.0.0.1').build();
        const url = await service.start(TIMEOUT);
        const caps = new wd.Capabilities();
        caps.setBrowserName('MiniBrowser');
        caps.set('webkitgtk:browserOptions', { binary, args: ['--automation'] });
        caps.set('timeouts', { script: TIMEOUT, pageLoad: 2 * TIMEOUT, implicit: 0 });
        let timer;
        const hung = new Promise((_, reject) => {
          timer = setTimeout(() => reject(new Error(`MiniBrowser did not start within ${LAUNCH_MS} ms`)), LAUNCH_MS);
        });
        try {
          driver = await Promise.race([new wd.Builder().usingServer(url).withCapabilities(caps).build(), hung]);
        } catch (e) {
          await service.kill();
          if (attempt >= 3) throw e;
          console.log(`# webkit: launch ${attempt} failed (${e.message}); launching again`);
        } finally {
          clearTimeout(timer);
        }
      }
      if (!engine.version) {
        engine.version = (await driver.getCapabilities()).getBrowserVersion();
        engine.label = `WebKitGTK ${engine.version}`;
      }
      // The window is sized so that the page (the viewport) gets width × height.
      await driver.manage().window().setRect({ width, height });
      const inner = await driver.executeScript('return [innerWidth, innerHeight];');
      if (inner[0] !== width || inner[1] !== height) {
        await driver.manage().window().setRect({ width: 2 * width - inner[0], height: 2 * height - inner[1] });
      }
      return new Session(engine, new WebKitBackend(driver, service, wd, await driver.getWindowHandle()));
    },
    async close() {},
  };
  return engine;
}

/** The engine `ENGINE` names (`firefox` or `webkit`). */
export async function launchEngine(name = process.env.ENGINE ?? 'firefox') {
  if (name === 'firefox') return launchFirefox();
  if (name === 'webkit') return launchWebKit();
  throw new Error(`ENGINE must be firefox or webkit, not ${name}`);
}
