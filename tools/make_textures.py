#!/usr/bin/env python3
"""Writes the small procedural textures of textures/ as binary PPM/PGM files.

Standard library only, fixed seeds: the output is identical on every run, so the PNGs
committed in textures/ can always be regenerated (tools/make_textures.sh converts to PNG).
Usage: make_textures.py OUT_DIR
"""
import math
import random
import sys
from pathlib import Path

SIZE = 256  # <= 256^2: albedo textures only need to suggest a material


def smooth_noise(rng, cells):
    """Value noise on a cells x cells lattice, sampled bilinearly with a smoothstep (tileable)."""
    lattice = [[rng.random() for _ in range(cells)] for _ in range(cells)]

    def sample(u, v):
        x, y = u * cells, v * cells
        x0, y0 = int(x) % cells, int(y) % cells
        x1, y1 = (x0 + 1) % cells, (y0 + 1) % cells
        fx, fy = x - math.floor(x), y - math.floor(y)
        fx, fy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)
        top = lattice[y0][x0] * (1 - fx) + lattice[y0][x1] * fx
        bottom = lattice[y1][x0] * (1 - fx) + lattice[y1][x1] * fx
        return top * (1 - fy) + bottom * fy

    return sample


def write_ppm(path, size, pixel):
    """pixel(x, y) -> (r, g, b) in [0, 1]."""
    data = bytearray()
    for y in range(size):
        for x in range(size):
            data.extend(max(0, min(255, round(c * 255))) for c in pixel(x, y))
    path.write_bytes(b"P6\n%d %d\n255\n" % (size, size) + bytes(data))


def write_pgm(path, size, value):
    data = bytes(max(0, min(255, round(value(x, y) * 255))) for y in range(size) for x in range(size))
    path.write_bytes(b"P5\n%d %d\n255\n" % (size, size) + data)


def wood(out):
    # Grain lines along x, bent by low-frequency noise; two browns mixed by the line profile.
    warp = smooth_noise(random.Random(11), 4)
    fine = smooth_noise(random.Random(12), 32)
    light, dark = (0.72, 0.52, 0.33), (0.45, 0.29, 0.16)

    def pixel(x, y):
        u, v = x / SIZE, y / SIZE
        t = 0.5 + 0.5 * math.sin(2 * math.pi * (9 * v + 1.5 * warp(u, v)))
        t = t ** 3 * 0.8 + 0.2 * fine(u, v)
        return tuple(l * (1 - t) + d * t for l, d in zip(light, dark))

    write_ppm(out / "wood.ppm", SIZE, pixel)


def paper(out):
    # Construction paper: a flat warm colour with faint fibres.
    rng = random.Random(21)
    fibres = smooth_noise(random.Random(22), 64)
    base = (0.78, 0.42, 0.30)

    def pixel(x, y):
        k = 0.93 + 0.07 * fibres(x / SIZE, y / SIZE) + 0.03 * (rng.random() - 0.5)
        return tuple(c * k for c in base)

    write_ppm(out / "paper.ppm", SIZE, pixel)


def sandpaper(out):
    # Sandpaper: dark backing with bright random grains.
    rng = random.Random(31)

    def pixel(x, y):
        g = 0.22 + 0.08 * rng.random()
        if rng.random() < 0.12:
            g = 0.45 + 0.35 * rng.random()
        return (g, g * 0.95, g * 0.85)

    write_ppm(out / "sandpaper.ppm", SIZE, pixel)


def heightfield(out):
    # Rolling hills (sum of two noise octaves) plus one dome, in [0, 1]; 128^2 is plenty for
    # a 64-segment tessellation.
    size = 128
    low, mid = smooth_noise(random.Random(41), 4), smooth_noise(random.Random(42), 8)

    def value(x, y):
        u, v = x / (size - 1), y / (size - 1)
        dome = math.exp(-((u - 0.5) ** 2 + (v - 0.5) ** 2) / 0.03)
        return 0.45 * low(u, v) + 0.2 * mid(u, v) + 0.35 * dome

    write_pgm(out / "heightfield.pgm", size, value)


def main():
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    for make in (wood, paper, sandpaper, heightfield):
        make(out)


if __name__ == "__main__":
    main()
