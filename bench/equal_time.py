#!/usr/bin/env python3
"""Equal-time relMSE from `wavefront converge`'s convergence.csv: per method and seed, the
relMSE interpolated (log-log) at each time budget between the two checkpoints around it; the
median over seeds (at least 3 must reach the budget); each method's ratio to the first one.

    python3 bench/equal_time.py DIR/convergence.csv 0.75,1.5,3 [gpu_seconds|wall_seconds]

docs/guiding.md's equal-time tables (guided against unguided MIS) come from it.
"""
import csv
import math
import statistics
import sys
from collections import defaultdict


def at(points, t):
    points = sorted(points)
    for (t0, e0), (t1, e1) in zip(points, points[1:]):
        if t0 <= t <= t1 and t0 > 0 and e0 > 0 and e1 > 0:
            f = (math.log(t) - math.log(t0)) / (math.log(t1) - math.log(t0)) if t1 > t0 else 0
            return math.exp(math.log(e0) + f * (math.log(e1) - math.log(e0)))
    return None


def main():
    path, budgets = sys.argv[1], [float(t) for t in sys.argv[2].split(",")]
    column = sys.argv[3] if len(sys.argv) > 3 else "gpu_seconds"
    runs, order = defaultdict(lambda: defaultdict(list)), []
    for row in csv.DictReader(open(path)):
        if row["method"] not in order:
            order.append(row["method"])
        runs[row["method"]][row["seed_index"]].append((float(row[column]),
                                                       float(row["relmse"])))
    medians = {}
    for method in order:
        medians[method] = []
        for t in budgets:
            values = [v for v in (at(p, t) for p in runs[method].values()) if v is not None]
            medians[method].append(statistics.median(values) if len(values) >= 3 else math.nan)
    print("| method | " + " | ".join("relMSE at %g s" % t for t in budgets) + " |")
    print("|---|" + "---|" * len(budgets))
    for method in order:
        print("| %s | %s |" % (method, " | ".join("%.4g" % v for v in medians[method])))
    first = order[0]
    for method in order[1:]:
        print("%s / %s relMSE (> 1: %s lower): %s" % (
            first, method, method,
            ", ".join("%.2f" % (a / b) for a, b in zip(medians[first], medians[method]))))


if __name__ == "__main__":
    main()
