#!/usr/bin/env python3
"""A deliberately naive digital straight segment recognizer, to be checked by zdg:

    zdg check dss.recognize.minimal --against 'python3 naive_dss.py'

The naive idea: the segment's direction (b, a) is the vector from its first point to its last,
reduced; the path is a DSS when every remainder a x - b y fits in one period (max(|a|, |b|) for
an 8-connected path, |a| + |b| for a 4-connected one), and mu is the smallest remainder. It
accepts only paths whose end points give the slope, and it misses the minimal
characteristics when they are not the end-to-end direction.
Protocol: {"points": [["x", "y"], ...], "connectivity": "4" or "8"} per line; the answer has
the fields of `zdg dss recognize --json`: is_dss, a, b, mu, omega, or longest_prefix."""
import json
import math
import sys


def naive(points, conn):
    (x0, y0), (x1, y1) = points[0], points[-1]
    dx, dy = x1 - x0, y1 - y0
    if dx == 0 and dy == 0:
        return 0, 1, -y0, 1, len(points) == 1
    g = math.gcd(dx, dy)
    a, b = dy // g, dx // g
    omega = max(abs(a), abs(b)) if conn == 8 else abs(a) + abs(b)
    r = [a * x - b * y for x, y in points]
    return a, b, min(r), omega, max(r) - min(r) < omega


for line in sys.stdin:
    req = json.loads(line)
    pts = [(int(x), int(y)) for x, y in req["points"]]
    conn = int(req["connectivity"])
    a, b, mu, omega, ok = naive(pts, conn)
    if ok:
        ans = {"is_dss": True, "a": str(a), "b": str(b), "mu": str(mu), "omega": str(omega)}
    else:
        k = len(pts) - 1
        while k > 1 and not naive(pts[:k], conn)[4]:
            k -= 1
        ans = {"is_dss": False, "longest_prefix": k}
    ans["connectivity"] = conn
    print(json.dumps(ans), flush=True)
