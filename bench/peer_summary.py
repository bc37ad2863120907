#!/usr/bin/env python3
"""Summarises bench/mitsuba_peer.py's JSON files, one per scene kind, as one Markdown table:
each scene's paths/s of both renderers and Wavefront's ratios of paths/s and of efficiency
(1 / relMSE x time), then their geometric means over the scenes given, the one figure that
stands for all kinds, and the Vulkan driver Wavefront ran on (files of different drivers or
Mitsuba variants are refused). Standard library only.

    python3 bench/peer_summary.py bench/results/lavapipe_peer_llvm_*.json
"""
import json
import math
import sys


def geometric_mean(values):
    return math.exp(sum(math.log(v) for v in values) / len(values))


def main(paths):
    if not paths:
        sys.exit("usage: peer_summary.py PEER.json [PEER.json ...]")
    runs = [json.load(open(path)) for path in paths]
    variants = sorted({run["mitsubaVariant"] for run in runs})
    if len(variants) != 1:
        sys.exit("peer_summary.py: the files mix Mitsuba variants %s" % ", ".join(variants))
    drivers = sorted({run["bench"].get("driver", "unknown") for run in runs})
    if len(drivers) != 1:
        sys.exit("peer_summary.py: the files mix Vulkan drivers %s" % "; ".join(drivers))
    mitsuba = "Mitsuba 3 " + variants[0]
    print("| scene | %s paths/s | Wavefront paths/s | paths/s ratio | efficiency ratio |"
          % mitsuba)
    print("|---|---|---|---|---|")
    for run in runs:
        print("| %s | %.3f M | %.3f M | %.3f | %.3f |" % (
            run["scene"], run["renderers"][mitsuba]["pathsPerSecond"] / 1e6,
            run["renderers"]["Wavefront"]["pathsPerSecond"] / 1e6,
            run["wavefrontOverMitsubaPathsPerSecond"], run["wavefrontOverMitsubaEfficiency"]))
    print("| geometric mean (%d scenes) | | | %.3f | %.3f |" % (
        len(runs), geometric_mean([r["wavefrontOverMitsubaPathsPerSecond"] for r in runs]),
        geometric_mean([r["wavefrontOverMitsubaEfficiency"] for r in runs])))
    print("\nWavefront's Vulkan driver: %s" % drivers[0])


if __name__ == "__main__":
    main(sys.argv[1:])
