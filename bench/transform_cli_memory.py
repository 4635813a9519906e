#!/usr/bin/python3
"""Peak memory and time of `zdg transform dt` against the in-process transform (issue #15, 1).

For a ball of radius 0.45 n in n^3 (uint8 .npy, l2 by default), runs
`zdg transform dt IN.npy -o OUT.npy --json` and reports, from the same run:
  - the peak resident set of the process (getrusage of the child) against the budget of the
    issue, 1.15 x (input bytes + output bytes) + 100 MB;
    (GNU time's %M, Debian package `time`);
  - the wall time of the whole command (reading, transform, writing, exit) against the
    in-process time of the transform that the command prints ("seconds"): the ratio should
    be at most 1.2.

  /usr/bin/python3 bench/transform_cli_memory.py --zdg build/bin/zdg --n 512 [--metric l2]

With --memory SIZE (e.g. 256M, binary units as zdg reads them) the command runs out of core
(`--out-of-core --memory SIZE`) and the peak is compared with that budget instead: the slabs
and blocks are sized to it, so the peak should stay within it plus the program's own pages
(about 10 MB).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def ball(n):
    z, y, x = np.ogrid[:n, :n, :n]
    c = (n - 1) / 2.0
    r = 0.45 * n
    return ((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2 < r * r).astype(np.uint8)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--zdg", default="build/bin/zdg")
    ap.add_argument("--n", type=int, default=512)
    ap.add_argument("--metric", default="l2")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--memory", default="", help="out of core with this budget (e.g. 256M)")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory(dir=os.environ.get("TMPDIR", "/tmp")) as d:
        src, out = os.path.join(d, "in.npy"), os.path.join(d, "out.npy")
        np.save(src, ball(a.n))
        in_bytes = os.path.getsize(src)
        rows = []
        for _ in range(a.runs):
            # GNU time measures the peak of the zdg process itself (getrusage of this script's
            # children would count the script's own pages, copied by fork before the exec).
            stats = os.path.join(d, "time.txt")
            # Each run writes a new output, as a first run does: replacing the previous one
            # would add the filesystem's freeing of its pages to the command (18 ms for 512 MB
            # on the development VM, inside rename(2)).
            if os.path.exists(out):
                os.remove(out)
            t0 = time.perf_counter()
            r = subprocess.run(["/usr/bin/time", "-o", stats, "-f", "%M",
                                a.zdg, "transform", "dt", src, "-o", out, "--force", "--json",
                                "--metric", a.metric, "--threads", str(a.threads)] +
                               (["--out-of-core", "--memory", a.memory] if a.memory else []),
                               capture_output=True, text=True)
            wall = time.perf_counter() - t0
            if r.returncode != 0:
                sys.exit("zdg failed: " + r.stderr.strip())
            with open(stats) as f:
                peak = int(f.read().split()[-1]) * 1024  # KiB
            j = json.loads(r.stdout)
            rows.append((wall, float(j["seconds"]), peak, j["dtype"]))
        out_bytes = os.path.getsize(out)
        wall = min(x[0] for x in rows)
        inproc = min(x[1] for x in rows)
        peak = max(x[2] for x in rows)
        print(f"zdg transform dt, ball {a.n}^3, {a.metric}, output {rows[0][3]}")
        print(f"  input {in_bytes / 1e6:.1f} MB, output {out_bytes / 1e6:.1f} MB")
        if a.memory:
            limit = int(json.loads(r.stdout)["memory_budget"])  # as zdg read --memory
            print(f"  out of core, budget {limit / 1e6:.1f} MB: peak RSS {peak / 1e6:.1f} MB, "
                  f"ratio {peak / limit:.2f}; command {wall:.3f} s")
            return
        budget = 1.15 * (in_bytes + out_bytes) + 100e6
        print(f"  peak RSS {peak / 1e6:.1f} MB, budget 1.15 x (in + out) + 100 MB = "
              f"{budget / 1e6:.1f} MB: ratio {peak / budget:.2f} ({'met' if peak <= budget else 'NOT met'})")
        print(f"  command {wall:.3f} s, in-process transform {inproc:.3f} s: ratio "
              f"{wall / inproc:.2f} (target <= 1.2: {'met' if wall <= 1.2 * inproc else 'NOT met'})")


if __name__ == "__main__":
    main()
