#!/usr/bin/env python3
"""What the Python module costs against the CLI on the Cornell box, in one run.

Usage: PYTHONPATH=build/python python3 bench/python_overhead.py [--wavefront build/wavefront]
       [--width 256] [--spp 64] [--runs 5]
Alternates CLI renders (`wavefront render --json`) and module renders (Renderer.render) with
the same settings and seeds, and prints the medians: paths/s of the render loop (the --json
"pathsPerSecond", the same measure both ways), and the module's whole call (options, render,
readback, numpy arrays, stats) against its render loop's time. The CLI's process start, scene
load and pipeline creation are not counted; the module's first render (pipelines) is a warm-up.
"""
import argparse
import json
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import wavefront as wf

ROOT = Path(__file__).resolve().parents[1]
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--wavefront", default=ROOT / "build" / "wavefront")
parser.add_argument("--scene", default=ROOT / "scenes" / "cornell_box.gltf")
parser.add_argument("--width", type=int, default=256)
parser.add_argument("--spp", type=int, default=64)
parser.add_argument("--runs", type=int, default=5)
args = parser.parse_args()

cli_rates, module_rates, call_overheads = [], [], []
with tempfile.TemporaryDirectory() as tmp, wf.Renderer() as r:
    scene = r.load(args.scene)
    options = dict(width=args.width, spp=args.spp)
    r.render(scene, seed=1000, **options)  # warm-up: pipelines
    for run in range(args.runs):
        out = Path(tmp) / "cli.exr"
        stats = Path(tmp) / "cli.json"
        subprocess.run([str(args.wavefront), "render", str(args.scene), "-o", str(out), "--quiet",
                        "--width", str(args.width), "--spp", str(args.spp), "--seed", str(run),
                        "--json", str(stats)], check=True)
        cli_rates.append(json.loads(stats.read_text())["pathsPerSecond"])
        start = time.perf_counter()
        result = r.render(scene, seed=run, **options)
        wall = time.perf_counter() - start
        module_rates.append(result.stats["pathsPerSecond"])
        call_overheads.append(wall / result.seconds - 1.0)
    device = r.device_name

cli, module = statistics.median(cli_rates), statistics.median(module_rates)
print(f"Cornell box {args.width} wide, {args.spp} spp, {args.runs} runs each, alternating, "
      f"on {device}")
print(f"  CLI    render loop: {cli / 1e6:7.3f} M paths/s (median; runs {min(cli_rates) / 1e6:.3f}"
      f"..{max(cli_rates) / 1e6:.3f})")
print(f"  module render loop: {module / 1e6:7.3f} M paths/s (median; runs "
      f"{min(module_rates) / 1e6:.3f}..{max(module_rates) / 1e6:.3f})")
print(f"  module / CLI: {module / cli:.3f}; the module's call beyond its render loop: "
      f"{100 * statistics.median(call_overheads):+.1f}% (median)")
