#!/usr/bin/env python3
"""A peer on the same machine: renders one scene (--scene, one of SCENE_KINDS below) with Mitsuba 3 (the --variant
given, path tracer) and with Wavefront at the same resolution, max depth and samples per pixel,
and prints paths/s and relMSE x time of both, plus the wavefront/megakernel ratio from a
`wavefront bench --compare-megakernel` in the same run. A manual benchmark, not a test: it
needs `pip install mitsuba` (into a virtual environment of your own, not the project's CI).

    python3 -m venv /tmp/mi && /tmp/mi/bin/pip install mitsuba==3.9.1 numpy
    /tmp/mi/bin/python bench/mitsuba_peer.py [--variant scalar_rgb|llvm_ad_rgb|cuda_ad_rgb]
        [--scene cornell|mirror-glass|mesh|tiny-light|lamps|instances|glass-caustic] [--wavefront build/wavefront] [--width 256]
        [--spp 64] [--max-depth 8] [--reference-spp 512] [--repeats 3] [--sampler NAME]
        [--guiding on|off] [--integrator path|light|bdpt|vcm] [--json bench/results/peer.json]
    python3 bench/mitsuba_peer.py --self-test   # the reference-noise correction, numpy only

`llvm_ad_rgb` (Dr.Jit's LLVM JIT, vectorised: what a CPU user would pick) needs an LLVM that
Dr.Jit can drive: on Debian 12 `apt install libllvm19`; the script points DRJIT_LIBLLVM_PATH at
its libLLVM.so.19.1 when the variable is unset (Debian's LLVM 15 crashes Dr.Jit on AVX-512
machines). The JIT variants compile their kernels in a first, untimed render.

The Mitsuba scene is read from the very glTF Wavefront renders (bench/gltf_to_mitsuba.py: the
same triangles in world space, each material as the Mitsuba BSDF that is the same function, the
light's emission on its front face only, the same camera) with a box pixel filter. Each
renderer's relMSE is measured against its own high-spp reference (so a
small systematic difference between the two does not count as noise); the two references'
relMSE against each other is printed as a check that the scenes match. Each reference is the
mean of two independent halves (two seeds), whose difference measures the reference's own
noise: (a - b)^2 / 4 per pixel is an unbiased estimate of the mean's variance, and a timed
render's squared error against a noisy reference exceeds its error against the truth by just
that variance (the two are independent). The tables print both relMSE figures, the raw one
and the one with the reference's noise taken off, and the efficiencies of both; the raw one
charges the reference's noise to whichever renderer is closer to the truth.

A third row times Wavefront with Mitsuba's own estimator (`--sampler independent
--triangle-sampling area`: independent random numbers, the light sampled by area, as Mitsuba's
path integrator does), so that paths/s compares the same work; its relMSE is measured against
Wavefront's reference (the same expectation).

`--integrator light|bdpt|vcm` renders Wavefront's timed row and its reference with light tracing
or bidirectional path tracing (the matched-estimator row, measured against that reference, stays
the path tracer); vcm is consistent, not unbiased, so its reference is bdpt's (the path tracer's
expectation), and its relMSE includes merging's bias; `light` is then also timed against Mitsuba's own light tracer (`ptracer`, its
relMSE against a ptracer reference: a light tracer leaves Dirac surfaces seen directly black)
as a fourth row.

`--guiding on` renders Wavefront's timed row with path guiding (its training inside the timed
seconds, as the EXR header's `renderSeconds` counts it); its reference, the matched-estimator row and the
megakernel ratio stay unguided (the reference has the same expectation either way).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "scenes"))
import make_cornell_box as cornell  # noqa: E402
import gltf_to_mitsuba  # noqa: E402
import make_scaling_scene as scaling  # noqa: E402


# One scene of each kind the peer comparison covers, all in the Cornell box.
SCENE_KINDS = {
    "cornell": "the project's Cornell box (diffuse, one area light)",
    "mirror-glass": "a mirror block and a glass sphere in the box (specular chains)",
    "mesh": "300k diffuse triangles in the box (deep BVH)",
    "tiny-light": "the box lit by a light 1/100 the area, the same power (NEE carries it)",
    "lamps": "the box lit by 1,024 small lamps (many emitters)",
    "instances": "64 placements of one 17,688-triangle sphere (two-level BVH)",
    "glass-caustic": "the laboratory's glass ball on a floor under a small sphere light "
                     "(a caustic)",
}
SCENES = tuple(SCENE_KINDS)


def write_scene(name, folder):
    """The glTF both renderers render (SCENE_KINDS says what each is); the path of the file."""
    if name == "cornell":
        return os.path.join(ROOT, "scenes", "cornell_box.gltf")
    if name == "glass-caustic":
        return os.path.join(ROOT, "scenes", "glass_caustic.gltf")
    path = os.path.join(folder, name + ".gltf")
    if name == "mesh":
        g, _, _ = scaling.build(300000, 1, False, 0)
    else:
        g = {"mirror-glass": mirror_glass_box, "tiny-light": tiny_light_box,
             "lamps": lamps_box, "instances": instances_box}[name]()
    g.write(path)
    return path


def _replace_light(g, quads, emission):
    """The box of scenes/make_cornell_box.py with `quads` for its ceiling light."""
    light = g.material("small light", (0.78, 0.78, 0.78), emission)
    light_node = next(n for n in g.doc["nodes"] if n.get("name") == "light")
    g.doc["meshes"][light_node["mesh"]]["primitives"] = [g.primitive(quads, light)]
    return g


def _ceiling_quad(cx, cz, half_x, half_z):
    return cornell.quad((cx - half_x, cornell.LIGHT_Y, cz - half_z),
                        (cx + half_x, cornell.LIGHT_Y, cz - half_z),
                        (cx + half_x, cornell.LIGHT_Y, cz + half_z),
                        (cx - half_x, cornell.LIGHT_Y, cz + half_z), (0, -1, 0))


LIGHT_CENTRE = (2.78, 2.795)  # of the box's light quad, 1.3 x 1.05
LIGHT_AREA = 1.3 * 1.05


def tiny_light_box():
    """The Cornell box lit by a light a tenth the size each way, 100 times as bright (the same
    power): next-event estimation carries it, BSDF sampling almost never finds it."""
    quads = [_ceiling_quad(LIGHT_CENTRE[0], LIGHT_CENTRE[1], 0.065, 0.0525)]
    return _replace_light(cornell.build(), quads, tuple(100.0 * e for e in cornell.EMISSION))


def lamps_box():
    """The Cornell box lit by 1,024 small lamps (a 32 x 32 grid over the ceiling) of the same
    total power as its one light: many emitters to choose among."""
    n, side = 32, 0.05
    step = (cornell.S - 0.4) / n
    quads = [_ceiling_quad(0.2 + (i + 0.5) * step, 0.2 + (k + 0.5) * step, side / 2, side / 2)
             for i in range(n) for k in range(n)]
    scale = LIGHT_AREA / (n * n * side * side)
    return _replace_light(cornell.build(), quads, tuple(scale * e for e in cornell.EMISSION))


def instances_box():
    """64 placements (a 4 x 4 x 4 grid) of one 17,688-triangle diffuse sphere in the box with
    its light: 1.13 M triangles as placed, one mesh in memory (a two-level BVH)."""
    g = cornell.GltfWriter()
    white = cornell.lit_room(g)
    points, tris = scaling.uv_sphere(67)
    sphere = g.mesh("sphere", [scaling.sphere_primitive(g, points, tris, white)])
    n, lo, hi = 4, 0.5, cornell.S - 0.8
    spacing = (hi - lo) / n
    for j in range(n):
        for i in range(n):
            for k in range(n):
                g.node(name="sphere %d" % (16 * j + 4 * i + k), mesh=sphere,
                       translation=[lo + (i + 0.5) * spacing, lo + (j + 0.5) * spacing,
                                    lo + (k + 0.5) * spacing], scale=[0.4 * spacing] * 3)
    _camera(g)
    return g


def _camera(g):
    g.doc["cameras"].append({"type": "perspective", "name": "camera", "perspective": {
        "yfov": 2 * math.atan(12.5 / 35.0), "aspectRatio": 1.0, "znear": 0.1, "zfar": 100.0}})
    g.node(name="camera", camera=0, translation=[2.775, 2.73, -8.0],
           rotation=cornell.y_rotation(180.0))


def mirror_glass_box():
    """The box with a perfect mirror for the tall block and a smooth glass sphere for the short
    one: specular chains, the peer's worst case."""
    g = cornell.GltfWriter()
    cornell.lit_room(g)
    g.doc["materials"].append({"name": "mirror", "pbrMetallicRoughness": {
        "baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 1.0, "roughnessFactor": 0.0}})
    mirror = len(g.doc["materials"]) - 1
    g.doc["materials"].append({"name": "glass", "pbrMetallicRoughness": {
        "baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.0},
        "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1.0}}})
    glass = len(g.doc["materials"]) - 1
    g.doc["extensionsUsed"].append("KHR_materials_transmission")
    g.node(name="tall block", mesh=g.mesh("block", [g.primitive(cornell.unit_block_quads(),
                                                                mirror)]),
           translation=[3.685, 0.0, 3.5125], rotation=cornell.y_rotation(17.0),
           scale=[1.65, 3.30, 1.65])
    points, tris = scaling.uv_sphere(48)
    g.node(name="glass sphere", mesh=g.mesh("sphere", [scaling.sphere_primitive(
        g, points, tris, glass)]), translation=[1.855, 0.9, 1.69], scale=[0.9, 0.9, 0.9])
    _camera(g)
    return g


def find_libllvm19():
    """The libLLVM.so.19.1 of Debian's libllvm19, or None."""
    try:
        files = subprocess.run(["dpkg", "-L", "libllvm19"], capture_output=True, text=True,
                               check=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        return None
    return next((f for f in files if f.endswith("libLLVM.so.19.1")), None)


def render_mitsuba(mi, gltf, folder, width, height, spp, max_depth, rr_depth, seed=0,
                   integrator="path"):
    scene = mi.load_dict(gltf_to_mitsuba.scene_dict(mi, gltf, folder, width, height, spp,
                                                    max_depth, rr_depth, integrator))
    start = time.perf_counter()
    image = np.array(mi.render(scene, spp=spp, seed=seed), dtype=np.float64)[:, :, :3]
    return image, time.perf_counter() - start


# Wavefront's flags for the estimator Mitsuba's path integrator uses on this scene.
MITSUBA_ESTIMATOR = ["--sampler", "independent", "--triangle-sampling", "area"]


def render_wavefront(mi, exe, gltf, folder, width, height, spp, max_depth, rr_depth, tag,
                     seed=0, sampler=None, flags=()):
    out = os.path.join(folder, "wavefront_%s.exr" % tag)
    extra = (["--sampler", sampler] if sampler else []) + list(flags)
    subprocess.run([exe, "render", gltf, "-o", out,
                    "--width", str(width), "--height", str(height), "--spp", str(spp),
                    "--max-depth", str(max_depth), "--rr-depth", str(rr_depth),
                    "--seed", str(seed), "--quiet"] + extra, check=True)
    bitmap = mi.Bitmap(out)
    image = np.array(bitmap, dtype=np.float64)[:, :, :3]
    # The EXR header's renderSeconds is the JSON's `seconds`; without --json the render times
    # its waves alone, not every pass (per-pass timestamps cost lavapipe ~0.07 ms each).
    return image, float(bitmap.metadata()["renderSeconds"])


def rel_mse(image, reference):
    return float(np.mean((image - reference) ** 2 / (reference ** 2 + 1e-2)))


class Reference:
    """A reference image from two independent halves, and the relMSE its own noise adds to any
    independent image's relMSE against it: (a - b)^2 / 4 per pixel estimates the variance of
    their mean without bias, weighed as rel_mse weighs a squared error."""

    def __init__(self, half_a, half_b):
        self.image = 0.5 * (half_a + half_b)
        self.noise = float(np.mean((half_a - half_b) ** 2 / 4.0 / (self.image ** 2 + 1e-2)))


def self_test():
    """Reference's noise term on synthetic images of known truth: the timed images' relMSE
    with it taken off must match their relMSE against the truth, and the raw one must not."""
    rng = np.random.default_rng(7)
    truth = rng.uniform(0.05, 2.0, size=(128, 128, 3))
    half_sd, image_sd = 0.06 * truth, 0.08 * truth  # each half's noise and a timed image's
    reference = Reference(truth + rng.normal(0.0, 1.0, truth.shape) * half_sd,
                          truth + rng.normal(0.0, 1.0, truth.shape) * half_sd)
    images = [truth + rng.normal(0.0, 1.0, truth.shape) * image_sd for _ in range(4)]
    raw = np.mean([rel_mse(image, reference.image) for image in images])
    against_truth = np.mean([np.mean((image - truth) ** 2 / (reference.image ** 2 + 1e-2))
                             for image in images])
    cleaned = raw - reference.noise
    print("self-test: relMSE against the truth %.5g, raw %.5g, less the reference's noise %.5g"
          % (against_truth, raw, cleaned))
    if abs(cleaned / against_truth - 1.0) > 0.03 or raw / against_truth - 1.0 < 0.2:
        print("self-test FAILED", file=sys.stderr)
        return 1
    return 0


def render_reference(render_half, spp, seed):
    """Two halves of spp / 2 samples with seeds seed and seed + 500, and their Reference."""
    half_spp = max(1, spp // 2)
    a = render_half(half_spp, seed)
    b = render_half(half_spp, seed + 500)
    return Reference(a, b)


def bench_ratio(exe, gltf, folder, width, height, spp, max_depth):
    out = os.path.join(folder, "bench.json")
    subprocess.run([exe, "bench", gltf, "--width",
                    str(width), "--height", str(height), "--max-depth", str(max_depth),
                    "--frames", "4", "--warmup", "1", "--spp", str(max(1, spp // 4)),
                    "--compare-megakernel", "--json", out, "--quiet"], check=True,
                   stdout=subprocess.DEVNULL)
    return json.load(open(out))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--wavefront", default=os.path.join(ROOT, "build", "wavefront"))
    parser.add_argument("--width", type=int, default=256)
    parser.add_argument("--height", type=int, default=256)
    parser.add_argument("--spp", type=int, default=64)
    parser.add_argument("--max-depth", type=int, default=8)
    parser.add_argument("--rr-depth", type=int, default=3,
                        help="Wavefront's --rr-depth (bounce index); Mitsuba gets one more, as "
                             "its depth counts from 1")
    parser.add_argument("--reference-spp", type=int, default=512)
    parser.add_argument("--sampler", help="Wavefront's --sampler (default: its own default; "
                        "Mitsuba's is independent)")
    parser.add_argument("--guiding", default="off", choices=["off", "on"],
                        help="Wavefront's --guiding for its timed row (default off)")
    parser.add_argument("--integrator", default="path", choices=["path", "light", "bdpt", "vcm"],
                        help="Wavefront's --integrator for its timed row (default path)")
    parser.add_argument("--repeats", type=int, default=3,
                        help="timed renders of each, alternating (median time, mean relMSE)")
    parser.add_argument("--json", help="write the numbers here")
    parser.add_argument("--self-test", action="store_true",
                        help="check the reference-noise correction on synthetic images and exit "
                             "(needs numpy only)")
    parser.add_argument("--scene", default="cornell", choices=SCENES,
                        help="; ".join("%s: %s" % kind for kind in SCENE_KINDS.items()) +
                        " (default cornell)")
    parser.add_argument("--variant", default="scalar_rgb",
                        choices=["scalar_rgb", "llvm_ad_rgb", "cuda_ad_rgb"],
                        help="Mitsuba's variant (default scalar_rgb; llvm_ad_rgb is the fast one "
                             "on a CPU, cuda_ad_rgb on an NVIDIA GPU)")
    args = parser.parse_args()
    if args.self_test:
        sys.exit(self_test())

    if args.variant == "llvm_ad_rgb" and "DRJIT_LIBLLVM_PATH" not in os.environ:
        llvm = find_libllvm19()
        if llvm:
            os.environ["DRJIT_LIBLLVM_PATH"] = llvm
    import mitsuba as mi
    mi.set_variant(args.variant)
    mitsuba_name = "Mitsuba 3 " + args.variant
    w, h, spp, depth = args.width, args.height, args.spp, args.max_depth
    with tempfile.TemporaryDirectory() as folder:
        gltf = write_scene(args.scene, folder)
        # The references' seed is none of the timed renders' (0 .. repeats - 1): a reference
        # that shared a timed render's first samples would understate that render's error.
        ref_seed = 1000
        # A first render compiles the JIT variants' kernels; a new seed does not recompile.
        render_mitsuba(mi, gltf, folder, w, h, 4, depth, args.rr_depth + 1, ref_seed + 1)
        mi_ref = render_reference(
            lambda n, seed: render_mitsuba(mi, gltf, folder, w, h, n, depth, args.rr_depth + 1,
                                           seed)[0], args.reference_spp, ref_seed)
        # With the timed row's integrator: the same expectation as the path tracer's, and on
        # scenes of specular chains far less noise at the same samples.
        # vcm's own reference would carry its bias: bdpt's is unbiased.
        ref_integrator = "bdpt" if args.integrator == "vcm" else args.integrator
        wf_ref = render_reference(
            lambda n, seed: render_wavefront(mi, args.wavefront, gltf, folder, w, h, n, depth,
                                             args.rr_depth, "reference", seed, args.sampler,
                                             flags=["--integrator", ref_integrator])[0],
            args.reference_spp, ref_seed)
        # Timed renders alternate between the two, each with its own seed, so that a drift in
        # the machine's speed (other tenants) falls on both; times are medians, errors means.
        mi_runs, wf_runs, matched_runs, ptracer_runs = [], [], [], []
        if args.integrator == "light":  # compile ptracer's kernels untimed too
            render_mitsuba(mi, gltf, folder, w, h, 4, depth, args.rr_depth + 1, ref_seed + 1,
                           "ptracer")
            # Its own reference: a light tracer leaves Dirac surfaces seen directly black, so
            # its expectation is not the path tracer's.
            ptracer_ref = render_reference(
                lambda n, seed: render_mitsuba(mi, gltf, folder, w, h, n, depth,
                                               args.rr_depth + 1, seed, "ptracer")[0],
                args.reference_spp, ref_seed)
        for seed in range(args.repeats):
            if args.integrator == "light":
                ptracer_runs.append(render_mitsuba(mi, gltf, folder, w, h, spp, depth,
                                                   args.rr_depth + 1, seed, "ptracer"))
            mi_runs.append(render_mitsuba(mi, gltf, folder, w, h, spp, depth, args.rr_depth + 1,
                                          seed))
            wf_runs.append(render_wavefront(mi, args.wavefront, gltf, folder, w, h, spp, depth,
                                            args.rr_depth, "test", seed, args.sampler,
                                            flags=["--guiding", args.guiding,
                                                   "--integrator", args.integrator]))
            matched_runs.append(render_wavefront(mi, args.wavefront, gltf, folder, w, h, spp,
                                                 depth, args.rr_depth, "matched", seed,
                                                 flags=MITSUBA_ESTIMATOR))
        bench = bench_ratio(args.wavefront, gltf, folder, w, h, spp, depth)
    paths = w * h * spp
    rows = {}
    matched_name = "Wavefront, Mitsuba's estimator"
    # With light tracing Wavefront's reference is not the path tracer's expectation: the
    # matched (path-tracing) row then times paths only, its relMSE not measured (nan).
    timed = [(mitsuba_name, mi_runs, mi_ref), ("Wavefront", wf_runs, wf_ref),
             (matched_name, matched_runs, wf_ref if args.integrator != "light" else None)]
    if ptracer_runs:  # Mitsuba's light tracer, against its own reference
        timed.append((mitsuba_name + " ptracer", ptracer_runs, ptracer_ref))
    for name, runs, ref in timed:
        seconds = float(np.median([run[1] for run in runs]))
        err = (float(np.mean([rel_mse(run[0], ref.image) for run in runs])) if ref is not None
               else float("nan"))
        noise = ref.noise if ref is not None else float("nan")
        # Not positive where the reference is noisier than the timed image can show: no figure.
        clean = err - noise if err > noise else float("nan")
        rows[name] = {"seconds": seconds, "pathsPerSecond": paths / seconds, "relMSE": err,
                      "relMSETimesSeconds": err * seconds, "referenceNoise": noise,
                      "relMSEReferenceNoiseRemoved": clean,
                      "relMSEReferenceNoiseRemovedTimesSeconds": clean * seconds,
                      "imageMean": float(np.mean([run[0].mean() for run in runs])),
                      "runSeconds": [run[1] for run in runs]}
    ratio = rows["Wavefront"]["pathsPerSecond"] / rows[mitsuba_name]["pathsPerSecond"]
    efficiency = (rows[mitsuba_name]["relMSETimesSeconds"] /
                  rows["Wavefront"]["relMSETimesSeconds"])
    clean_key = "relMSEReferenceNoiseRemovedTimesSeconds"
    efficiency_clean = rows[mitsuba_name][clean_key] / rows["Wavefront"][clean_key]
    matched = rows[matched_name]["pathsPerSecond"] / rows[mitsuba_name]["pathsPerSecond"]
    print("%s %dx%d, %d spp, max depth %d; references %d spp; %d alternating timed renders "
          "each (median seconds, mean relMSE); Wavefront guiding %s, integrator %s" % (
              args.scene, w, h, spp, depth, args.reference_spp, args.repeats, args.guiding,
              args.integrator))
    print("| renderer | seconds | paths/s | relMSE | its reference's noise | relMSE less it | "
          "relMSE x seconds | the same less the noise | image mean |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, r in rows.items():
        print("| %s | %.2f | %.3f M | %.4g | %.3g | %.4g | %.4g | %.4g | %.4f |" % (
            name, r["seconds"], r["pathsPerSecond"] / 1e6, r["relMSE"], r["referenceNoise"],
            r["relMSEReferenceNoiseRemoved"], r["relMSETimesSeconds"], r[clean_key],
            r["imageMean"]))
    check = rel_mse(wf_ref.image, mi_ref.image)
    print("references: relMSE of Wavefront's against Mitsuba's %.4g (means %.4f vs %.4f)" % (
        check, wf_ref.image.mean(), mi_ref.image.mean()))
    print("Wavefront / Mitsuba: %.3f paths/s, %.3f efficiency (1 / relMSE x time), %.3f with "
          "the references' noise taken off" % (ratio, efficiency, efficiency_clean))
    print("Wavefront with Mitsuba's estimator / Mitsuba: %.3f paths/s" % matched)
    print("wavefront / megakernel (bench, same run): %.3f" % bench["wavefrontOverMegakernel"])
    ptracer_efficiency = ptracer_efficiency_clean = None
    if ptracer_runs:
        ptracer = rows[mitsuba_name + " ptracer"]
        ptracer_efficiency = ptracer["relMSETimesSeconds"] / rows["Wavefront"]["relMSETimesSeconds"]
        ptracer_efficiency_clean = ptracer[clean_key] / rows["Wavefront"][clean_key]
        print("Wavefront light / Mitsuba ptracer: %.3f efficiency, %.3f with the references' "
              "noise taken off" % (ptracer_efficiency, ptracer_efficiency_clean))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"mitsubaVariant": args.variant, "scene": args.scene,
                       "width": w, "height": h, "spp": spp, "maxDepth": depth,
                       "referenceSpp": args.reference_spp, "repeats": args.repeats,
                       "wavefrontSampler": args.sampler or "default",
                       "wavefrontGuiding": args.guiding,
                       "wavefrontIntegrator": args.integrator,
                       "wavefrontOverPtracerEfficiency": ptracer_efficiency,
                       "wavefrontOverPtracerEfficiencyReferenceNoiseRemoved":
                           ptracer_efficiency_clean,
                       "renderers": rows,
                       "referencesRelMSE": check, "wavefrontOverMitsubaPathsPerSecond": ratio,
                       "wavefrontOverMitsubaEfficiency": efficiency,
                       "wavefrontOverMitsubaEfficiencyReferenceNoiseRemoved": efficiency_clean,
                       "wavefrontMatchedOverMitsubaPathsPerSecond": matched,
                       "wavefrontMatchedFlags": MITSUBA_ESTIMATOR,
                       "wavefrontOverMegakernel": bench["wavefrontOverMegakernel"],
                       "device": bench["device"], "bench": bench}, f, indent=1)


if __name__ == "__main__":
    main()
