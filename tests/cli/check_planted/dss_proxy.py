#!/usr/bin/python3
"""Planted bugs for `zdg check dss.recognize.minimal --against`: answers come from
`zdg serve dss recognize` (argv[1] is the zdg program), then one bug is applied (argv[2]):

  four-omega  4-connected DSS: omega = max(|a|, |b|), the period of a naive line instead of
              |a| + |b| (wrong only for 4-connected paths, with a != 0 and b != 0)
  octant      DSS whose direction (b, a) has 0 < a < b (the first octant, open): mu off by
              one (wrong only on that octant)
"""
import json
import subprocess
import sys

zdg, bug = sys.argv[1], sys.argv[2]
serve = subprocess.Popen([zdg, "serve", "dss", "recognize"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, text=True)
for line in sys.stdin:
    serve.stdin.write(line)
    serve.stdin.flush()
    ans = json.loads(serve.stdout.readline())
    req = json.loads(line)
    if ans.get("is_dss"):
        a, b = int(ans["a"]), int(ans["b"])
        if bug == "four-omega" and int(req["connectivity"]) == 4:
            ans["omega"] = str(max(abs(a), abs(b)))
        if bug == "octant" and 0 < a < b:
            ans["mu"] = str(int(ans["mu"]) + 1)
    print(json.dumps(ans), flush=True)
