#!/usr/bin/env python3
"""Writes knot.obj: a trefoil knot as a closed tube (no boundary edges, shared vertices),
centred at the origin and about 2 units across. Made for pbrlab; rerun to regenerate:

    python3 scenes/meshes/make_knot.py > scenes/meshes/knot.obj

A finer tube for benchmarks: `make_knot.py ALONG AROUND` (2400 24 gives 115,200 triangles;
tools/bench_render.sh writes that one to a temporary folder).
"""
import math
import sys

ALONG, AROUND, TUBE = 96, 12, 0.18


def curve(t):
    # The trefoil (2, 3) torus knot, scaled to about 2 units across.
    x = math.sin(t) + 2 * math.sin(2 * t)
    y = math.cos(t) - 2 * math.cos(2 * t)
    z = -math.sin(3 * t)
    return (x / 3.2, y / 3.2, z / 3.2)


def sub(a, b):
    return tuple(p - q for p, q in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    n = math.sqrt(sum(c * c for c in a))
    return tuple(c / n for c in a)


def main():
    global ALONG, AROUND
    if len(sys.argv) == 3:
        ALONG, AROUND = int(sys.argv[1]), int(sys.argv[2])
    print("# A trefoil knot tube for pbrlab: %d x %d quads as triangles, closed." % (ALONG, AROUND))
    print("o knot")
    for i in range(ALONG):
        t = 2 * math.pi * i / ALONG
        p = curve(t)
        tangent = normalize(sub(curve(t + 1e-4), curve(t - 1e-4)))
        side = normalize(cross(tangent, (0.0, 0.0, 1.0)))
        up = cross(side, tangent)
        for j in range(AROUND):
            a = 2 * math.pi * j / AROUND
            v = tuple(p[k] + TUBE * (math.cos(a) * side[k] + math.sin(a) * up[k]) for k in range(3))
            print("v %.6f %.6f %.6f" % v)
    for i in range(ALONG):
        for j in range(AROUND):
            a = i * AROUND + j + 1
            b = ((i + 1) % ALONG) * AROUND + j + 1
            c = ((i + 1) % ALONG) * AROUND + (j + 1) % AROUND + 1
            d = i * AROUND + (j + 1) % AROUND + 1
            print("f %d %d %d" % (a, b, c))
            print("f %d %d %d" % (a, c, d))


main()
