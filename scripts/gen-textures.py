#!/usr/bin/env python3
"""Writes the shipped textures of scenes/textured/ (PNG, RGB8 or RGBA8, standard library only).

- checker.png: 64 x 64, 8 x 8 squares of 8 texels, white and dark blue: the grazing-plane
  scene's texture, where perspective-incorrect interpolation bends the squares' edges.
- crate.png: 128 x 128, a wooden crate's face: planks with a darker frame and grain, the
  texture of crate.obj's material (crate.mtl, map_Kd).
- level0.png to level6.png: 64 x 64 down to 1 x 1, each mip level one colour (red, orange,
  yellow, green, cyan, blue, magenta) with a faint grid of its texels: mip-levels.json's
  levels, showing which level the level of detail selects where.
- badge.png: 64 x 64 RGBA, a yellow disc on a magenta ring, transparent outside (alpha 0) and
  half transparent on the ring: env-modes.json's texture, where DECAL, BLEND and ADD differ.

Run from the repository root: python3 scripts/gen-textures.py
"""
import math
import struct
import zlib


def png(path, width, height, pixel):
    """Writes an RGB8 PNG, or RGBA8 when pixel gives four values; pixel(x, y) gives
    (r, g, b[, a]) with y = 0 the top row."""
    channels = len(pixel(0, 0))
    rows = b"".join(
        b"\x00" + bytes(c for x in range(width) for c in pixel(x, y)) for y in range(height)
    )

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    head = struct.pack(">IIBBBBB", width, height, 8, 6 if channels == 4 else 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", head) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def checker(x, y):
    return (240, 240, 240) if (x // 8 + y // 8) % 2 == 0 else (30, 50, 140)


def crate(x, y):
    frame = min(x, y, 127 - x, 127 - y) < 12 or abs(x - y) < 9
    plank = y // 29
    grain = 0.5 + 0.5 * math.sin(0.35 * x + 2.0 * math.sin(0.09 * y + plank))
    base = (150, 100, 50) if frame else (190, 140, 80)
    shade = 0.8 + 0.2 * grain - (0.25 if (y % 29 == 0 and not frame) else 0.0)
    return tuple(max(0, min(255, round(c * shade))) for c in base)


LEVEL_COLOURS = [(255, 0, 0), (255, 128, 0), (255, 255, 0), (0, 200, 0), (0, 220, 220), (40, 40, 255), (220, 0, 220)]


def level(colour):
    def pixel(x, y):
        return colour if (x + y) % 2 == 0 else tuple(c * 7 // 8 for c in colour)
    return pixel


def badge(x, y):
    r = math.hypot(x + 0.5 - 32, y + 0.5 - 32)
    if r < 20:
        return (250, 220, 40, 255)
    if r < 28:
        return (200, 30, 160, 128)
    return (0, 0, 0, 0)


png("scenes/textured/checker.png", 64, 64, checker)
png("scenes/textured/badge.png", 64, 64, badge)
png("scenes/textured/crate.png", 128, 128, crate)
for k, colour in enumerate(LEVEL_COLOURS):
    png(f"scenes/textured/level{k}.png", 64 >> k, 64 >> k, level(colour))
