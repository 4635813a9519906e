#!/usr/bin/python3
"""A planted bug for `zdg check floor_sum.oracle --against`: the inputs are read into 64-bit
two's complement integers (as a C implementation with int64_t arguments would), then the sum is
exact. Right whenever every input is in [-2^63, 2^63), so wrong only past 2^63."""
import json
import sys


def wrap64(v):
    return (v + 2**63) % 2**64 - 2**63


for line in sys.stdin:
    r = json.loads(line)
    n, m, a, b = (wrap64(int(r[k])) for k in ("n", "m", "a", "b"))
    if m == 0:
        print(json.dumps({"error": "m = 0 after conversion"}), flush=True)
        continue
    s = sum((a * i + b) // m for i in range(n))
    print(json.dumps({"value": str(s)}), flush=True)
