#!/usr/bin/python3
"""Planted bugs for `zdg check --against` on the operations dss cover, transform voronoi,
topology skeleton and plane probe: each request is passed to `zdg serve OPERATION` (argv[1] is
the zdg program), with one bug (argv[2]) applied to the request or to the answer:

  cover-naive      dss cover: 4-connected paths segmented as naive (8-connected) ones, the
                   standard DSS taken for naive ones (wrong only for 4-connected paths)
  voronoi-l1       transform voronoi: the nearest site in the l1 metric instead of l2
  skeleton-3d      topology skeleton: in 3D, the complementary adjacency pair (26,6 <-> 6,26);
                   right in 2D
  probe-octant     plane probe: on the octant a < 0 < b, c the normal loses the sign of a
  surface-cavities surface: one surface per object component, cavities forgotten (the rows
                   and the total agree with each other)
"""
import json
import subprocess
import sys

zdg, bug = sys.argv[1], sys.argv[2]
op = {"cover-naive": ["dss", "cover"], "voronoi-l1": ["transform", "voronoi"],
      "skeleton-3d": ["topology", "skeleton"], "probe-octant": ["plane", "probe"], "surface-cavities": ["surface"]}[bug]
serve = subprocess.Popen([zdg, "serve"] + op, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                         text=True)
swap = {"26,6": "6,26", "6,26": "26,6"}
for line in sys.stdin:
    req = json.loads(line)
    if bug == "cover-naive" and str(req.get("connectivity")) == "4":
        req["connectivity"] = "8"
    if bug == "voronoi-l1":
        req["metric"] = "l1"
    if bug == "skeleton-3d" and req.get("adjacency") in swap:
        req["adjacency"] = swap[req["adjacency"]]
    serve.stdin.write(json.dumps(req) + "\n")
    serve.stdin.flush()
    ans = json.loads(serve.stdout.readline())
    if bug == "probe-octant" and int(req["a"]) < 0 < int(req["b"]) and int(req["c"]) > 0:
        ans["normal"][0] = str(abs(int(ans["normal"][0])))
    if bug == "surface-cavities" and "components" in ans:
        for row in ans["components"]:
            row["surfaces"] = "1"
        ans["surfaces"] = str(len(ans["components"]))
    print(json.dumps(ans), flush=True)
