// What runs inside the page for every engine: finds elements by ARIA role and accessible
// name, as a person (or a screen reader) names them, and reads or sets what a person reads
// or sets. Both drivers send the same function, so a flow finds the same elements in
// Firefox and in WebKit. Like Playwright's getByRole (which the Chromium suite uses), the
// role and name are computed here from the DOM (the subset of HTML-AAM and accname the app
// uses): implicit roles of HTML elements, `role`, `aria-labelledby`, `aria-label`,
// `<label>`, `alt`, `<title>`, `<legend>`, `<caption>` and name from content.
//
// A query is `{ role, name, exact, css, hasText, within, nth, state }`:
//   role     ARIA role ('button', 'textbox', …), or none with `css`;
//   name     accessible name: a string (whole name, whitespace collapsed) or
//            `{ re, flags }` (a regular expression); `exact: false` matches a part, any case;
//   css      a CSS selector instead of (or with) a role;
//   hasText  only elements whose text contains this;
//   within   a query the element must be inside (resolved to exactly one element);
//   nth      which of several matches (otherwise more than one is an error);
//   state    'visible' (default: rendered with a size), 'attached' (in the page), 'hidden'
//            (no visible match) or 'detached' (none in the page).

/* eslint-disable no-undef */
export function pageOp(op, q, arg) {
  const NAME_FROM_CONTENT = new Set([
    'button', 'cell', 'checkbox', 'columnheader', 'gridcell', 'heading', 'link', 'menuitem',
    'menuitemcheckbox', 'menuitemradio', 'option', 'radio', 'row', 'rowheader', 'switch', 'tab',
    'tooltip', 'treeitem', 'listitem',
  ]);
  const norm = (s) => (s ?? '').replace(/\s+/g, ' ').trim();

  const hiddenForAria = (el) => {
    for (let e = el; e && e.nodeType === 1; e = e.parentElement) {
      if (e.getAttribute('aria-hidden') === 'true') return true;
      if (e.hasAttribute('inert')) return true;
    }
    if (el.localName === 'option') {
      const sel = el.closest('select');
      return sel ? hiddenForAria(sel) : false;
    }
    const style = getComputedStyle(el);
    if (style.visibility !== 'visible') return true;
    if (typeof el.checkVisibility === 'function') return !el.checkVisibility();
    for (let e = el; e && e.nodeType === 1; e = e.parentElement) {
      if (getComputedStyle(e).display === 'none') return true;
    }
    return false;
  };

  const hasSize = (el) => {
    if (el.localName === 'option') {
      const sel = el.closest('select');
      return sel ? hasSize(sel) : false;
    }
    const r = el.getBoundingClientRect();
    return r.width > 0 && r.height > 0;
  };

  const tableRole = (el) => {
    const t = el.closest('table');
    return t ? roleOf(t) : null;
  };

  function roleOf(el) {
    const explicit = el.getAttribute('role');
    if (explicit && explicit.trim()) return explicit.trim().split(/\s+/)[0];
    const tag = el.localName;
    switch (tag) {
      case 'button': return 'button';
      case 'a': case 'area': return el.hasAttribute('href') ? 'link' : null;
      case 'input': {
        const t = (el.getAttribute('type') || 'text').toLowerCase();
        if (['button', 'submit', 'reset', 'image'].includes(t)) return 'button';
        if (t === 'checkbox') return 'checkbox';
        if (t === 'radio') return 'radio';
        if (t === 'number') return 'spinbutton';
        if (t === 'range') return 'slider';
        if (['hidden', 'file', 'color', 'date', 'time', 'datetime-local', 'month', 'week'].includes(t)) return null;
        if (el.hasAttribute('list')) return 'combobox';
        if (t === 'search') return 'searchbox';
        return 'textbox';
      }
      case 'textarea': return 'textbox';
      case 'select': return el.multiple || el.size > 1 ? 'listbox' : 'combobox';
      case 'option': return 'option';
      case 'optgroup': return 'group';
      case 'img': return el.getAttribute('alt') === '' ? 'presentation' : 'img';
      case 'h1': case 'h2': case 'h3': case 'h4': case 'h5': case 'h6': return 'heading';
      case 'ul': case 'ol': case 'menu': return 'list';
      case 'li': return 'listitem';
      case 'table': return 'table';
      case 'thead': case 'tbody': case 'tfoot': return 'rowgroup';
      case 'tr': return 'row';
      case 'td': return tableRole(el) === 'grid' || tableRole(el) === 'treegrid' ? 'gridcell' : 'cell';
      case 'th': {
        const scope = el.getAttribute('scope');
        if (scope === 'row' || scope === 'rowgroup') return 'rowheader';
        if (scope === 'col' || scope === 'colgroup') return 'columnheader';
        return el.closest('thead') || !el.parentElement?.querySelector('td') ? 'columnheader' : 'rowheader';
      }
      case 'section': return el.hasAttribute('aria-label') || el.hasAttribute('aria-labelledby') ? 'region' : null;
      case 'aside': return 'complementary';
      case 'nav': return 'navigation';
      case 'main': return 'main';
      case 'article': return 'article';
      case 'dialog': return 'dialog';
      case 'fieldset': case 'details': return 'group';
      case 'form': return el.hasAttribute('aria-label') || el.hasAttribute('aria-labelledby') ? 'form' : null;
      case 'progress': return 'progressbar';
      case 'meter': return 'meter';
      case 'output': return 'status';
      case 'hr': return 'separator';
      case 'p': return 'paragraph';
      case 'header': return el.closest('article, aside, main, nav, section') ? null : 'banner';
      case 'footer': return el.closest('article, aside, main, nav, section') ? null : 'contentinfo';
      default: return null;
    }
  }

  const isBlock = (el) => {
    const d = getComputedStyle(el).display;
    return !d.startsWith('inline') && d !== 'contents';
  };

  /** The text an element gives a name computed from content (accname step 2F). */
  function contentText(el, self, seen) {
    let out = '';
    for (const child of el.childNodes) {
      if (child.nodeType === 3) { out += child.data; continue; }
      if (child.nodeType !== 1 || child === self) continue;
      if (child.localName === 'title' && child.parentElement instanceof SVGElement) continue;
      if (['script', 'style', 'template'].includes(child.localName)) continue;
      if (hiddenForAria(child)) continue;
      const part = nameOf(child, seen, true);
      out += isBlock(child) ? ` ${part} ` : part;
    }
    return out;
  }

  /** The accessible name (accname 1.2, as far as the app needs it). */
  function nameOf(el, seen = new Set(), embedded = false) {
    if (seen.has(el)) return '';
    seen.add(el);
    const labelledby = el.getAttribute('aria-labelledby');
    if (labelledby && !embedded) {
      const parts = labelledby.split(/\s+/).map((id) => document.getElementById(id)).filter(Boolean)
        .map((ref) => norm(ref.getAttribute('aria-label') || contentText(ref, null, seen)));
      const joined = norm(parts.join(' '));
      if (joined) return joined;
    }
    const label = el.getAttribute('aria-label');
    if (label && label.trim()) return norm(label);
    const role = roleOf(el);
    const tag = el.localName;
    if (embedded) {
      // A control inside another element's name gives its value (accname step 2C).
      if (role === 'textbox' || role === 'searchbox') return el.value ?? el.textContent;
      if (role === 'combobox' && tag === 'select') return el.selectedOptions[0]?.textContent ?? '';
      if (role === 'spinbutton' || role === 'slider') return String(el.value ?? '');
    }
    if (tag === 'input' || tag === 'textarea' || tag === 'select' || tag === 'meter' || tag === 'progress' || tag === 'output') {
      const t = (el.getAttribute('type') || '').toLowerCase();
      if (tag === 'input' && ['button', 'submit', 'reset'].includes(t)) {
        return norm(el.value || (t === 'submit' ? 'Submit' : t === 'reset' ? 'Reset' : ''));
      }
      if (tag === 'input' && t === 'image') return norm(el.getAttribute('alt') || el.getAttribute('title'));
      const labels = el.labels ? [...el.labels] : [];
      const fromLabels = norm(labels.map((l) => contentText(l, el, seen)).join(' '));
      if (fromLabels) return fromLabels;
      return norm(el.getAttribute('title') || el.getAttribute('placeholder'));
    }
    if (tag === 'img' || tag === 'area') return norm(el.getAttribute('alt') || el.getAttribute('title'));
    if (el instanceof SVGElement) {
      const title = [...el.children].find((c) => c.localName === 'title');
      if (title && norm(title.textContent)) return norm(title.textContent);
    }
    if (tag === 'fieldset') {
      const legend = [...el.children].find((c) => c.localName === 'legend');
      if (legend) return norm(contentText(legend, null, seen));
    }
    if (tag === 'table') {
      const caption = [...el.children].find((c) => c.localName === 'caption');
      if (caption) return norm(contentText(caption, null, seen));
    }
    if (tag === 'figure') {
      const caption = [...el.children].find((c) => c.localName === 'figcaption');
      if (caption) return norm(contentText(caption, null, seen));
    }
    if (embedded || NAME_FROM_CONTENT.has(role)) {
      const text = norm(contentText(el, null, seen));
      if (text) return text;
    }
    return norm(el.getAttribute('title'));
  }

  const nameMatches = (name, want, exact) => {
    if (want === undefined || want === null) return true;
    if (typeof want === 'object') return new RegExp(want.re, want.flags).test(name);
    if (exact === false) return name.toLowerCase().includes(norm(want).toLowerCase());
    return name === norm(want);
  };

  const describe = (el) => {
    const role = roleOf(el);
    const id = el.id ? `#${el.id}` : '';
    const cls = typeof el.className === 'string' && el.className ? `.${el.className.trim().split(/\s+/).join('.')}` : '';
    return `<${el.localName}${id}${cls}${role ? ` role=${role}` : ''} name="${nameOf(el).slice(0, 80)}">`;
  };

  function candidates(query) {
    let scopes = [document];
    if (query.within) {
      const inner = resolve(query.within);
      if (typeof inner === 'string') return inner;
      scopes = [inner];
    }
    const state = query.state ?? 'visible';
    const out = [];
    for (const scope of scopes) {
      const all = scope.querySelectorAll(query.css ?? '*');
      for (const el of all) {
        if (query.role) {
          if (roleOf(el) !== query.role) continue;
          if (hiddenForAria(el)) continue;
          if (!nameMatches(nameOf(el), query.name, query.exact)) continue;
        }
        if (query.hasText !== undefined && !norm(el.textContent).includes(norm(query.hasText))) continue;
        if ((state === 'visible' || state === 'hidden') && (hiddenForAria(el) || !hasSize(el))) continue;
        out.push(el);
      }
    }
    return out;
  }

  const show = (query) => {
    const parts = [];
    if (query.role) parts.push(query.role);
    if (query.name !== undefined) parts.push(typeof query.name === 'object' ? `/${query.name.re}/` : `"${query.name}"`);
    if (query.css) parts.push(query.css);
    if (query.hasText !== undefined) parts.push(`with text "${query.hasText}"`);
    if (query.nth !== undefined) parts.push(`#${query.nth}`);
    const self = parts.join(' ');
    return query.within ? `${show(query.within)} > ${self}` : self;
  };

  /** Exactly one element, or a sentence saying why not. */
  function resolve(query) {
    const found = candidates(query);
    if (typeof found === 'string') return found;
    if (query.nth !== undefined) {
      const i = query.nth < 0 ? found.length + query.nth : query.nth;
      return found[i] ?? `${show(query)}: ${found.length} found`;
    }
    if (found.length === 1) return found[0];
    if (found.length === 0) return `${show(query)}: none found`;
    return `${show(query)}: ${found.length} found: ${found.slice(0, 5).map(describe).join(', ')}`;
  }

  const one = (fn) => {
    const el = resolve(q);
    if (typeof el === 'string') return { ok: false, why: el };
    return fn(el);
  };

  // Whether a press on `node` is a press on `el` (inside it, or on its label).
  const pressesOn = (el, node) => Boolean(el.contains(node) || el.labels?.[0]?.contains(node));

  // Guards the press about to be made at (x, y) on `el`, as a person's press lands where
  // the element is when the finger comes down: if the page moved between finding the
  // point and the press (a scroll, a redraw), the press would land on something else. The
  // first event of the press decides: on the element (found anew, it may have been redrawn)
  // it goes through untouched; elsewhere the whole press is stopped before the page sees it
  // and the driver presses again where the element is now.
  function guardPress(el, x, y) {
    window.__e2ePress?.off();
    const types = ['pointerdown', 'mousedown', 'pointerup', 'mouseup', 'click', 'auxclick', 'contextmenu'];
    const g = { hit: null, on: null };
    const on = (e) => {
      if (g.hit === null) {
        const now = resolve(q);
        const target = typeof now === 'string' ? el : now;
        g.hit = pressesOn(target, e.target) || pressesOn(el, e.target);
        g.on = g.hit ? null : `${describe(e.target)} at (${Math.round(x)}, ${Math.round(y)})`;
        if (g.hit) { g.off(); return; }
      }
      e.preventDefault();
      e.stopImmediatePropagation();
      if (e.type === 'click') g.off();
    };
    g.off = () => { for (const t of types) window.removeEventListener(t, on, true); };
    for (const t of types) window.addEventListener(t, on, true);
    window.__e2ePress = g;
  }

  switch (op) {
    case 'count': {
      const found = candidates(q);
      return typeof found === 'string' ? { ok: true, value: 0 } : { ok: true, value: found.length };
    }
    case 'wait': {
      const found = candidates(q);
      const n = typeof found === 'string' ? 0 : found.length;
      if (q.state === 'hidden' || q.state === 'detached') return n === 0 ? { ok: true } : { ok: false, why: `${show(q)}: ${n} still ${q.state === 'hidden' ? 'shown' : 'in the page'}` };
      const el = resolve(q);
      return typeof el === 'string' ? { ok: false, why: el } : { ok: true };
    }
    case 'names': {
      const found = candidates(q);
      return { ok: true, value: typeof found === 'string' ? [] : found.map((el) => nameOf(el)) };
    }
    case 'point': return one((el) => {
      // Where a person would press: the middle of the element, scrolled into view, and only
      // once nothing else covers that point.
      const r0 = el.getBoundingClientRect();
      if (r0.top < 0 || r0.left < 0 || r0.bottom > innerHeight || r0.right > innerWidth) {
        el.scrollIntoView({ block: 'center', inline: 'center' });
      }
      const r = el.getBoundingClientRect();
      const x = r.left + r.width / 2 + (arg?.dx ?? 0);
      const y = r.top + r.height / 2 + (arg?.dy ?? 0);
      const hit = document.elementFromPoint(x, y);
      if (!hit || !pressesOn(el, hit)) {
        return { ok: false, why: `${show(q)} is covered at (${Math.round(x)}, ${Math.round(y)}) by ${hit ? describe(hit) : 'nothing'}` };
      }
      if (el.disabled) return { ok: false, why: `${show(q)} is disabled` };
      if (arg?.guard) guardPress(el, x, y);
      return { ok: true, value: { x, y } };
    });
    case 'pressed': {
      // What the guarded press hit: true, false (it landed elsewhere and was stopped), or
      // null (no press arrived, or the page was replaced).
      const g = window.__e2ePress;
      window.__e2ePress = undefined;
      g?.off();
      return { ok: true, value: g ? { hit: g.hit, on: g.on } : { hit: null } };
    }
    case 'box': return one((el) => {
      const r0 = el.getBoundingClientRect();
      if (arg?.scroll !== false && (r0.top < 0 || r0.bottom > innerHeight)) el.scrollIntoView({ block: 'center' });
      const r = el.getBoundingClientRect();
      return { ok: true, value: { x: r.left, y: r.top, width: r.width, height: r.height } };
    });
    case 'focus': return one((el) => { el.focus(); return { ok: document.activeElement === el, why: `${show(q)} takes no focus` }; });
    case 'fill': return one((el) => {
      // As pasting over a selection: the control gets the text through the editing
      // commands (beforeinput/input events), as when a person pastes.
      if (el.disabled || el.readOnly) return { ok: false, why: `${show(q)} is not editable` };
      el.focus();
      if (typeof el.select === 'function') el.select();
      let done = false;
      if (arg === '') {
        done = document.execCommand('delete', false);
      } else {
        done = document.execCommand('insertText', false, arg);
      }
      if (!done || el.value !== arg) {
        const proto = el.localName === 'textarea' ? HTMLTextAreaElement.prototype : HTMLInputElement.prototype;
        Object.getOwnPropertyDescriptor(proto, 'value').set.call(el, arg);
        el.dispatchEvent(new InputEvent('input', { bubbles: true, inputType: 'insertReplacementText', data: arg }));
        // Set from outside the editing commands, the control would not report a change
        // when it loses the focus; a person's edit would.
        el.dispatchEvent(new Event('change', { bubbles: true }));
      }
      return { ok: el.value === arg, why: `${show(q)} holds "${String(el.value).slice(0, 40)}", not the text filled` };
    });
    case 'select': return one((el) => {
      // As choosing from the list: the option by value or by its text, then input and change.
      if (el.disabled) return { ok: false, why: `${show(q)} is disabled` };
      const opt = [...el.options].find((o) => o.value === arg) ?? [...el.options].find((o) => norm(o.textContent) === norm(arg));
      if (!opt) return { ok: false, why: `${show(q)} has no option "${arg}" (it has ${[...el.options].map((o) => `"${o.value}"`).join(', ')})` };
      if (opt.disabled) return { ok: false, why: `option "${arg}" of ${show(q)} is disabled` };
      el.focus();
      el.value = opt.value;
      el.dispatchEvent(new Event('input', { bubbles: true }));
      el.dispatchEvent(new Event('change', { bubbles: true }));
      return { ok: true };
    });
    case 'value': return one((el) => ({ ok: true, value: el.value }));
    case 'checked': return one((el) => ({ ok: true, value: el.checked ?? el.getAttribute('aria-checked') === 'true' }));
    case 'attr': return one((el) => ({ ok: true, value: el.getAttribute(arg) }));
    case 'text': return one((el) => ({ ok: true, value: el.textContent }));
    case 'name': return one((el) => ({ ok: true, value: nameOf(el) }));
    case 'focused': return one((el) => ({ ok: true, value: document.activeElement === el }));
    case 'options': return one((el) => ({ ok: true, value: [...el.options].map((o) => norm(o.textContent)) }));
    default: return { ok: false, why: `unknown operation ${op}` };
  }
}

export const PAGE_SRC = pageOp.toString();
