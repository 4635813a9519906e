#!/usr/bin/python3
"""A planted bug for `zdg check floor_sum.oracle --against`: the sum of (a i + b) / m with C's
truncating division instead of the floor. Right whenever every a i + b is >= 0 and m > 0, so
wrong only when an input is negative."""
import json
import sys


def trunc_div(x, m):
    q = abs(x) // abs(m)
    return q if (x >= 0) == (m > 0) else -q


for line in sys.stdin:
    r = json.loads(line)
    n, m, a, b = (int(r[k]) for k in ("n", "m", "a", "b"))
    s = sum(trunc_div(a * i + b, m) for i in range(n))
    print(json.dumps({"value": str(s)}), flush=True)
