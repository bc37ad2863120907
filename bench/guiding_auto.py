#!/usr/bin/env python3
"""--guiding auto against off (and on) on every gallery scene: docs/guiding.md, "auto".

    python3 bench/guiding_auto.py BUILD/wavefront [--width 128] [--spp 256] [--reps 3]
                                  [--modes off,auto,on] [--out DIR]

Per scene: one warm-up render of each variant (fills the shader caches), then --reps rounds
of the modes in alternating order (a change in machine load hits each alike), each a render
with --json. Prints one JSON line per scene: auto's decision, whether auto's image equals
off's bit for bit (wf_region_check --same, beside the binary under tests/), each mode's
seconds (render passes plus guide rebuilds), its own relMSE estimate, and efficiency
1 / (relMSE x median seconds).
"""
import argparse
import json
import statistics
import subprocess
from pathlib import Path

GALLERY = ["cornell_box", "glass_caustic", "many_lamps", "sphere_near_floor", "tiny_light",
           "veach_mis", "animated_arm"]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("wavefront")
    p.add_argument("--width", default="128")
    p.add_argument("--spp", default="256")
    p.add_argument("--reps", type=int, default=3)
    p.add_argument("--modes", default="off,auto,on")
    p.add_argument("--out", default="/tmp/guiding_auto")
    p.add_argument("--scenes", default=",".join(GALLERY), help="comma-separated gallery scenes")
    a = p.parse_args()
    binary = Path(a.wavefront).resolve()
    check = binary.parent / "tests" / "wf_region_check"
    scenes = Path(__file__).resolve().parents[1] / "scenes"
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    modes = a.modes.split(",")
    for scene in a.scenes.split(","):
        gltf = str(scenes / f"{scene}.gltf")
        for mode in ("off", "on"):
            subprocess.run([binary, "render", gltf, "-o", out / "warm.exr", "--width", "16",
                            "--spp", "4", "--guiding", mode, "--quiet"], check=True)
        runs = {}
        for rep in range(a.reps):
            for mode in (modes if rep % 2 == 0 else modes[::-1]):
                exr = out / f"{scene}_{mode}_{rep}.exr"
                js = exr.with_suffix(".json")
                subprocess.run([binary, "render", gltf, "-o", exr, "--width", a.width, "--spp",
                                a.spp, "--seed", "1", "--guiding", mode, "--quiet", "--json", js],
                               check=True)
                d = json.loads(js.read_text())
                rebuild = sum(i["rebuildSeconds"]
                              for i in d.get("guiding", {}).get("iterations", []))
                runs.setdefault(mode, []).append(
                    (d["seconds"] + rebuild, d["errorEstimate"]["relMse"], d["guidingDecision"]))
        line = {"scene": scene, "decision": runs[modes[0]][0][2]}
        if "auto" in runs and "off" in runs:
            line["autoImageIsOffs"] = subprocess.run(
                [check, "--same", out / f"{scene}_auto_0.exr", out / f"{scene}_off_0.exr"],
                capture_output=True).returncode == 0
            line["decision"] = runs["auto"][0][2]
        for mode, v in runs.items():
            seconds = [x[0] for x in v]
            line[mode] = {"seconds": seconds, "relMse": v[0][1],
                          "efficiency": 1.0 / (v[0][1] * statistics.median(seconds))}
        print(json.dumps(line), flush=True)


if __name__ == "__main__":
    main()
