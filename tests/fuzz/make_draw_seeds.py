#!/usr/bin/env python3
"""Writes the hand-made seeds of the draw-path fuzz target into
tests/fuzz/seeds/draw/: a lit, textured cube in view under several device
configurations, so that fuzzing starts from inputs that draw pixels.
The byte layout is the one mote_fuzz_draw reads (tests/fuzz/fuzz_entry.c)."""
import os
import struct

def f(x):
    """A float the reader decodes exactly: (b - 120) / 30 for b < 240."""
    b = round(x * 30 + 120)
    assert 0 <= b < 240
    return bytes([b])

def u16(v):
    return struct.pack('<H', v)

def config(w, h, color_fmt, depth_fmt, pad=0, subpixel=8, band=0, arena=0, parallel=0):
    fm = color_fmt | (depth_fmt << 3) | (0x80 if pad else 0)
    out = u16(w - 1) + u16(h - 1) + bytes([fm])
    if pad:
        out += bytes([pad - 1])
    out += bytes([subpixel - 4 if subpixel else 5])
    bm = (1 if band else 0) | (arena << 1) | (parallel << 3)
    out += bytes([bm])
    if band:
        out += u16(band - 1)
    out += bytes([2])            # tile size 8 << 2 = 32
    out += bytes([1, 20, 30, 60, 255])  # clear colour, no clear depth
    out += bytes([0])            # not broken
    return out

def frame():
    cf = 1                       # camera position given
    out = bytes([cf]) + f(2) + f(1.5) + f(-3.5)
    out += bytes([2 | 8])        # one light, with ambient
    out += bytes([1]) + f(3) + f(3.9) + f(-3) + f(0) + f(0) + f(0) + bytes([0])
    out += f(0.1) + f(0.1) + f(0.1)
    return out

CUBE_V = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
          (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
CUBE_I = [0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
          2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3]

def mesh(textured):
    out = bytes([len(CUBE_V)])
    for i, v in enumerate(CUBE_V):
        out += b''.join(f(c) for c in v)
        out += bytes([2]) + f(i & 1) + f((i >> 1) & 1)   # uv given, normal = position
    out += bytes([len(CUBE_I) // 3, 0]) + bytes(CUBE_I)
    out += bytes([2]) + f(0.3) + f(0.5) + f(0)          # rotation
    mf = 1 | (2 if textured else 0)
    out += bytes([mf, 230, 200, 160])
    if textured:
        out += bytes([0])
    return out

def draw_desc(mode, cull=1, persp=1, filt=1):
    return bytes([mode, cull, persp | (filt << 6)])

def seed(cfg, modes, textured=True, tex=(8, 8, 0, 1)):
    out = cfg + frame()
    out += bytes([1 if textured else 0, 0, len(modes) - 1])
    if textured:
        w, h, fmt, sm = tex
        out += bytes([0, w - 1, h - 1, fmt, sm, 0])
    for m in modes:
        out += bytes([0, 0]) + draw_desc(*m)
    out += mesh(textured)
    out += bytes([0, 0, 0])      # no row conversion
    if textured:
        w, h = tex[0], tex[1]
        for y in range(h):
            for x in range(w):
                out += bytes([(x * 32) & 255, (y * 32) & 255, ((x ^ y) & 1) * 255, 255])
    return out

def main():
    d = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'seeds', 'draw')
    os.makedirs(d, exist_ok=True)
    seeds = {
        'cube-rgba-full': seed(config(64, 48, 1, 1), [(5,)]),
        'cube-rgba-arena': seed(config(64, 48, 1, 1, arena=1, parallel=2), [(5, 1, 1, 2)]),
        'cube-565-bands': seed(config(40, 30, 2, 2, band=7), [(4,), (3,)], tex=(5, 3, 3, 2)),
        'cube-grey-tiny-arena': seed(config(120, 90, 4, 1, arena=2, subpixel=4),
                                     [(5, 2, 2, 2), (1,), (2,)], tex=(3, 7, 5, 1)),
        'cube-swapped-nodepth': seed(config(33, 17, 3, 3, pad=2), [(5, 3, 3, 1)]),
        'cube-300-subspan': seed(config(300, 300, 1, 2, arena=1, parallel=3),
                                 [(5, 1, 3, 2)], tex=(16, 16, 0, 2)),
        'cube-wire-points': seed(config(50, 50, 1, 1), [(1,), (2,)], textured=False),
    }
    for name, data in seeds.items():
        with open(os.path.join(d, name), 'wb') as fp:
            fp.write(data)

if __name__ == '__main__':
    main()
