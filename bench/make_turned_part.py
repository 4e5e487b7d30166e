#!/usr/bin/env python3
"""Writes a turned part (a candlestick-like solid of revolution about y) as OBJ, for timing the textured
part export (docs/performance.md): SEGMENTS around x PROFILE points, about 2 * SEGMENTS * PROFILE
triangles. Usage: make_turned_part.py OUT.obj [SEGMENTS] [PROFILE]"""
import math
import sys

out = sys.argv[1]
segments = int(sys.argv[2]) if len(sys.argv) > 2 else 64
profile = int(sys.argv[3]) if len(sys.argv) > 3 else 40
height = 36.0  # mm, fits the 40 mm demo block


def radius(t):  # t in [0, 1] from bottom to top: a foot, a waist, a bead, a cup
    return 7.0 + 4.0 * math.exp(-((t - 0.05) / 0.08) ** 2) - 3.0 * math.sin(math.pi * t) ** 2 \
        + 2.5 * math.exp(-((t - 0.6) / 0.05) ** 2) + 3.0 * t ** 4


with open(out, "w") as f:
    f.write("# turned part for Kerf's part export timing\n")
    for i in range(profile):
        t = i / (profile - 1)
        y = -height / 2 + height * t
        for s in range(segments):
            a = 2 * math.pi * s / segments
            f.write(f"v {radius(t) * math.cos(a):.5f} {y:.5f} {-radius(t) * math.sin(a):.5f}\n")
    f.write(f"v 0 {-height / 2:.5f} 0\nv 0 {height / 2:.5f} 0\n")
    bottom, top = profile * segments + 1, profile * segments + 2
    for i in range(profile - 1):
        for s in range(segments):
            a, b = i * segments + s + 1, i * segments + (s + 1) % segments + 1
            c, d = a + segments, b + segments
            f.write(f"f {a} {b} {d}\nf {a} {d} {c}\n")
    for s in range(segments):
        f.write(f"f {bottom} {(s + 1) % segments + 1} {s + 1}\n")
        last = (profile - 1) * segments
        f.write(f"f {top} {last + s + 1} {last + (s + 1) % segments + 1}\n")
