#!/usr/bin/env python3
"""Times render --frames per mode, alternating the modes' runs (these machines drift by 10-30%
from minute to minute) and printing medians over the runs: the first frame, then per later
frame the load and pose, BVH, upload and render times (docs/animation.md quotes its tables).

    python3 bench/frame_reuse.py SCENE.gltf --frames 0..48:6 --modes rebuild,refit,auto \\
        --runs 3 -- --width 240 --spp 4

A mode `main=PATH` runs another wavefront binary (e.g. a build of the commit before the
renderer was kept between frames) with no --frame-bvh flag.
"""
import argparse
import os
import re
import statistics
import subprocess
import tempfile

LINE = re.compile(r"^wavefront: frame (\d+) \(t = [^)]*\) ([\d.]+) s: load and pose ([\d.]+), "
                  r"BVH ([\d.]+)(?: \((\w+), cost ([\d.]+)x built\))?, (?:upload \(pipelines "
                  r"kept\)|pipelines and upload) ([\d.]+), render ([\d.]+)")


def run(binary, scene, frames, mode, extra, folder):
    cmd = [binary, "render", scene, "--frames", frames, "-o",
           os.path.join(folder, "f_%04d.exr")] + extra
    if mode:
        cmd += ["--frame-bvh", mode]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stderr
    rows = [LINE.match(line) for line in out.splitlines()]
    rows = [m for m in rows if m]
    if not rows:
        raise SystemExit("no per-frame lines in:\n" + out)
    return [dict(total=float(m[2]), load=float(m[3]), bvh=float(m[4]), how=m[5] or "built",
                 cost=float(m[6] or 1.0), upload=float(m[7]), render=float(m[8])) for m in rows]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("--frames", default="0..48:6")
    ap.add_argument("--modes", default="rebuild,refit,auto")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--wavefront", default="build/wavefront")
    args, extra = ap.parse_known_args()  # the rest: render's flags (after --)
    args.extra = [a for a in extra if a != "--"]
    modes = args.modes.split(",")
    results = {m: [] for m in modes}
    with tempfile.TemporaryDirectory() as folder:
        for _ in range(args.runs):
            for m in modes:
                binary, mode = (m.split("=", 1)[1], None) if m.startswith("main=") else \
                    (args.wavefront, m)
                results[m].append(run(binary, args.scene, args.frames, mode, args.extra, folder))
    med = statistics.median
    print("| mode | first frame s | later frames: total s | load and pose | BVH | upload | "
          "render | refit frames | cost vs built (max) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for m in modes:
        runs = results[m]
        first = med(r[0]["total"] for r in runs)
        later = lambda key: med(statistics.mean(f[key] for f in r[1:]) for r in runs)
        refits = sum(f["how"] == "refit" for f in runs[0][1:])
        worst = max(f["cost"] for f in runs[0])
        name = "main (a renderer per frame)" if m.startswith("main=") else m
        print(f"| {name} | {first:.3f} | {later('total'):.3f} | {later('load'):.3f} | "
              f"{later('bvh'):.3f} | {later('upload'):.3f} | {later('render'):.3f} | "
              f"{refits}/{len(runs[0]) - 1} | {worst:.2f}x |")


if __name__ == "__main__":
    main()
