#!/usr/bin/env python3
"""What a wasm module is made of: code bytes per crate (and per module of the project's own
crates), from the function names the linker keeps (a cargo build before wasm-bindgen and
wasm-opt, or any module with a name section), plus the data segments.

Usage: python3 scripts/wasm-breakdown.py FILE.wasm [--depth N] [--top N]
"""
import re
import sys
from collections import defaultdict


def leb(b, i):
    r = s = 0
    while True:
        x = b[i]; i += 1
        r |= (x & 0x7F) << s; s += 7
        if x < 0x80:
            return r, i


def sections(b):
    i = 8
    while i < len(b):
        sid = b[i]; i += 1
        size, i = leb(b, i)
        yield sid, b[i:i + size]
        i += size


def demangle_segments(name):
    """Legacy Rust mangling `_ZN3foo3bar17h…E` → ['foo', 'bar']."""
    m = re.match(r'_?_ZN(.*)E$', name)
    if not m:
        return None
    s, out, i = m.group(1), [], 0
    while i < len(s):
        j = i
        while j < len(s) and s[j].isdigit():
            j += 1
        if j == i:
            break
        n = int(s[i:j]); out.append(s[j:j + n]); i = j + n
    if out and re.fullmatch(r'h[0-9a-f]{16}', out[-1]):
        out.pop()
    return out


def owner(name, depth):
    segs = demangle_segments(name)
    if segs is None:
        return name.split('::')[0] if '::' in name else '(other: ' + ('C/runtime' if not name.startswith('_') else 'mangled') + ')'
    first = segs[0]
    text = '::'.join(segs)
    text = text.replace('$LT$', '<').replace('$GT$', '>').replace('..', '::').replace('$u20$', ' ')
    text = text.replace('$RF$', '&').replace('$C$', ',').replace('$BP$', '*').replace('$u7b$', '{').replace('$u7d$', '}')
    # `<T as Trait>::f` belongs to T's crate; a plain path to its first segment.
    m = re.match(r'_?<(?:&(?:mut )?)?([A-Za-z_][A-Za-z0-9_]*(?:::[A-Za-z_][A-Za-z0-9_]*)*)', text)
    path = m.group(1).split('::') if m else [p for p in text.split('::') if p]
    path = [p for p in path if p and not p.startswith('{')]
    crate = path[0] if path else first
    if crate in ('plc_core', 'plc_web') and len(path) > 1:
        return '::'.join(path[:1 + depth])
    return crate


def main():
    args = sys.argv[1:]
    depth = int(args[args.index('--depth') + 1]) if '--depth' in args else 1
    top = int(args[args.index('--top') + 1]) if '--top' in args else 40
    b = open(args[0], 'rb').read()
    imported = 0
    bodies = []
    names = {}
    data = 0
    for sid, body in sections(b):
        if sid == 2:
            n, i = leb(body, 0)
            for _ in range(n):
                for _ in range(2):
                    l, i = leb(body, i); i += l
                kind = body[i]; i += 1
                if kind == 0:
                    imported += 1; _, i = leb(body, i)
                elif kind == 1:
                    i += 1; fl = body[i]; i += 1; _, i = leb(body, i)
                    if fl & 1: _, i = leb(body, i)
                elif kind == 2:
                    fl = body[i]; i += 1; _, i = leb(body, i)
                    if fl & 1: _, i = leb(body, i)
                elif kind == 3:
                    i += 2
                else:
                    i += 2
        elif sid == 10:
            n, i = leb(body, 0)
            for _ in range(n):
                size, i = leb(body, i)
                bodies.append(size + 1); i += size
        elif sid == 11:
            data = len(body)
        elif sid == 0:
            l, i = leb(body, 0)
            if body[i:i + l] == b'name':
                i += l
                while i < len(body):
                    sub = body[i]; i += 1
                    size, i = leb(body, i)
                    end = i + size
                    if sub == 1:
                        n, i = leb(body, i)
                        for _ in range(n):
                            idx, i = leb(body, i)
                            nl, i = leb(body, i)
                            names[idx] = body[i:i + nl].decode('utf-8', 'replace'); i += nl
                    i = end
    total = sum(bodies)
    groups = defaultdict(int)
    for k, size in enumerate(bodies):
        groups[owner(names.get(imported + k, '?'), depth)] += size
    print(f'{args[0]}: code {total} bytes in {len(bodies)} functions, data {data} bytes')
    for g, size in sorted(groups.items(), key=lambda x: -x[1])[:top]:
        print(f'  {size:9d}  {100 * size / total:5.1f} %  {g}')


main()
