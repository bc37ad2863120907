#!/usr/bin/env python3
"""Compare sample patterns on a scene: relMSE against render time, log-log, median of seeds.

Usage: compare_samplers.py [SCENE.gltf] [CHART.png] [--time SECONDS]
Defaults: the Cornell box of scenes/, compare_samplers.png, 2 seconds per method and seed.
"""
import argparse
from pathlib import Path

import matplotlib
matplotlib.use("Agg")

import wavefront as wf

HERE = Path(__file__).resolve().parent
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("scene", nargs="?", default=HERE.parent / "scenes" / "cornell_box.gltf")
parser.add_argument("chart", nargs="?", default="compare_samplers.png")
parser.add_argument("--time", type=float, default=2.0, help="seconds per method and seed")
args = parser.parse_args()

with wf.Renderer() as r:
    scene = r.load(args.scene)
    # The reference: many samples of the default method, at a seed the runs do not use.
    reference = r.render(scene, width=64, spp=2048, seed=1000003, max_depth=8).image
    runs = r.converge(scene, reference=reference, methods=["independent", "halton", "sobol"],
                      seeds=range(1, 4), time=args.time, max_depth=8)
for method in runs.methods:
    spp, seconds, error = runs.medians(method)[-1]
    print(f"{method:16s} {spp:6d} spp in {seconds:6.3f} s GPU: relMSE {error:.4g}")
ax = runs.plot(path=args.chart)
print("wrote", args.chart)
