#!/usr/bin/env python3
"""The time of a convergence sweep on P MPI ranks, modelled from its measured run costs.

Reads a results.csv of `zdg converge` or `zdg paper` (column `seconds`: each run's own time),
groups its runs into the jobs `zdg converge --mpi` hands out (one (shape, h, translation) per
estimator, or of the estimators that share a computation: the 3D integral invariants ii-*, the
jets jet-*, the corrected normal currents cnc-*; Estimator::shared_computation), and replays the hand-out of
cli/mpi_sweep.hpp: jobs in plan order (finest h first, then shape, then translation: the
largest-first order when the shapes share their box, as the CVIU 2014 3D shapes do), each to
the first rank that is free. --copies K counts each job K times (a sweep measured with one
translation standing for one with K); --scale F multiplies every cost (runs timed on a loaded
machine, whose seconds include waits for a core, scaled to the CPU time the sweep took). Prints, per P, the replayed time and its two lower
bounds, max(job) and sum(jobs)/P; Graham's bound for any such list schedule is
sum/P + max(job).

    bench/sweep_mpi_model.py out/results.csv --ranks 1,2,4,64 [--copies 10] [--scale 0.43]
"""
import argparse
import csv
import heapq
from collections import OrderedDict

def shared_tag(name, dimension):
    """The estimators' shared computation (convergence/estimators_*.cpp), or None."""
    if name.startswith("ii-") and dimension == 3:
        return "ii-3d"
    for prefix in ("jet-", "cnc-"):
        if name.startswith(prefix):
            return prefix + "3d"
    return None


def jobs_of(path):
    jobs = OrderedDict()
    shapes = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            name = row["estimator"].split(":")[0]
            group = shared_tag(name, len(row["offset"].split())) or row["estimator"]
            if row["shape"] not in shapes:
                shapes.append(row["shape"])
            level = float(row["h"]) if row["h"] else -float(row.get("samples") or 0)
            key = (level, shapes.index(row["shape"]), group, int(row["translation"]))
            jobs[key] = jobs.get(key, 0.0) + float(row["seconds"])
    # Plan order: the finest level first (smallest h, largest N), then shape, translation.
    return [jobs[k] for k in sorted(jobs, key=lambda k: (k[0], k[1], k[3]))]


def replay(costs, ranks):
    free = [(0.0, r) for r in range(ranks)]
    heapq.heapify(free)
    end = 0.0
    for c in costs:
        t, r = heapq.heappop(free)
        heapq.heappush(free, (t + c, r))
        end = max(end, t + c)
    return end


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("--ranks", default="1,2,4,64")
    ap.add_argument("--copies", type=int, default=1)
    ap.add_argument("--scale", type=float, default=1.0)
    a = ap.parse_args()
    one = jobs_of(a.csv)
    costs = [c * a.scale for c in one for _ in range(a.copies)]
    total, largest = sum(costs), max(costs)
    print(f"{len(costs)} jobs, sum {total:.1f} s, largest {largest:.2f} s")
    print("| ranks | replayed | max(job) | sum/P | sum/P + max(job) |")
    print("|---|---|---|---|---|")
    for p in (int(x) for x in a.ranks.split(",")):
        print(f"| {p} | {replay(costs, p):.1f} s | {largest:.2f} s | {total / p:.1f} s | "
              f"{total / p + largest:.1f} s |")


if __name__ == "__main__":
    main()
