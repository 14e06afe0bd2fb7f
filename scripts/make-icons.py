#!/usr/bin/env python3
"""Draws the app's PNG icons (public/icons/icon-192.png, icon-512.png and the maskable
icon-maskable-512.png) from the shapes of public/favicon.svg: a rounded dark-blue square,
two light-blue bars and a yellow dot. Plain Python (zlib), so no image tool is needed;
run it again only when the icon changes."""
import struct
import zlib
from pathlib import Path

BLUE, BARS, DOT = (0x1F, 0x4E, 0x79), (0x9F, 0xD3, 0xFF), (0xFF, 0xD5, 0x4F)


def inside_rounded(x, y, size, r):
    cx = min(max(x, r), size - r)
    cy = min(max(y, r), size - r)
    return (x - cx) ** 2 + (y - cy) ** 2 <= r * r


def pixel(x, y, size, maskable):
    # Work in the favicon's 32 × 32 units; a maskable icon keeps its shapes in the
    # central 80 % (the safe zone) and fills the whole square with the background.
    u = 32 / size
    if maskable:
        gx, gy = (x * u - 3.2) / 0.8, (y * u - 3.2) / 0.8
    else:
        gx, gy = x * u, y * u
    if not maskable and not inside_rounded(x + 0.5, y + 0.5, size, size * 6 / 32):
        return (0, 0, 0, 0)
    if (gx - 16) ** 2 + (gy - 16) ** 2 <= 2.5 ** 2:
        return DOT + (255,)
    if 10 <= gy < 22 and (7 <= gx < 13 or 19 <= gx < 25):
        return BARS + (255,)
    return BLUE + (255,)


def png(size, maskable):
    rows = b''.join(
        b'\x00' + b''.join(bytes(pixel(x, y, size, maskable)) for x in range(size))
        for y in range(size)
    )

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data))

    header = struct.pack('>IIBBBBB', size, size, 8, 6, 0, 0, 0)
    return b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) + chunk(b'IDAT', zlib.compress(rows, 9)) + chunk(b'IEND', b'')


out = Path(__file__).resolve().parent.parent / 'public' / 'icons'
out.mkdir(parents=True, exist_ok=True)
for name, size, maskable in [('icon-192.png', 192, False), ('icon-512.png', 512, False), ('icon-maskable-512.png', 512, True)]:
    (out / name).write_bytes(png(size, maskable))
    print(out / name)
