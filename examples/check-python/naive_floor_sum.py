#!/usr/bin/env python3
"""A deliberately naive floor sum, to be checked by zdg:

    zdg check floor_sum.oracle --against 'python3 naive_floor_sum.py'

sum_{i=0}^{n-1} floor((a i + b) / m), computed the way one writes it first: in floating point.
Right for small numbers, wrong once a i + b no longer fits the 53 bits of a double.
The line-JSON protocol: one request {"n": "...", "m": "...", "a": "...", "b": "..."} per line
(integers as decimal strings), one answer {"value": "..."} per line, flushed."""
import json
import math
import sys

for line in sys.stdin:
    r = json.loads(line)
    n, m, a, b = (int(r[k]) for k in ("n", "m", "a", "b"))
    value = sum(math.floor((a * i + b) / m) for i in range(n))
    print(json.dumps({"value": str(value)}), flush=True)
