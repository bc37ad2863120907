#!/usr/bin/env python3
"""Colour and luminance noise of --spectral single against hero (docs/gltf.md, Dispersion).

    PYTHONPATH=build/python python3 bench/spectral_noise.py [--seeds 8] [--spp 16]
        [--width 64] scenes/prism.gltf scenes/dispersion_pair.gltf ...

Per scene and mode, `seeds` independent renders (seeds 1..N) of `spp` samples. Per pixel,
luminance Y = 0.2126 r + 0.7152 g + 0.0722 b and the two chroma differences r - Y, b - Y
(YCbCr's axes, unscaled); their variance over the seeds is the pixel's noise, divided by its
mean Y squared plus 1% of the image's mean Y squared (relMSE's denominator), then averaged
over the pixels:
    luminance noise = mean(Var(Y) / (Ybar^2 + eps)),
    colour noise    = mean((Var(r - Y) + Var(b - Y)) / (Ybar^2 + eps)).
Both scale as 1 / spp for an unbiased render, so "at equal time" multiplies each by the
render's seconds (mean over seeds, after an untimed render that compiles the shaders; the ratio single / hero of noise x seconds is hero's
efficiency gain). Prints a markdown table.
"""
import argparse
import os

import numpy as np
import wavefront as wf


def noise(images):
    stack = np.stack(images).astype(np.float64)  # seeds, h, w, 3
    y = 0.2126 * stack[..., 0] + 0.7152 * stack[..., 1] + 0.0722 * stack[..., 2]
    mean_y = y.mean(axis=0)
    denominator = mean_y ** 2 + 0.01 * mean_y.mean() ** 2
    luminance = (y.var(axis=0, ddof=1) / denominator).mean()
    colour = ((stack[..., 0] - y).var(axis=0, ddof=1) +
              (stack[..., 2] - y).var(axis=0, ddof=1)) / denominator
    return luminance, colour.mean()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("scenes", nargs="+")
    parser.add_argument("--seeds", type=int, default=8)
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--width", type=int, default=64)
    parser.add_argument("--max-depth", type=int, default=16)
    args = parser.parse_args()
    renderer = wf.Renderer()
    print("| scene | mode | s/render | luminance noise | colour noise | "
          "single/hero luminance, equal spp / time | single/hero colour, equal spp / time |")
    print("|---|---|---|---|---|---|---|")
    for path in args.scenes:
        scene = renderer.load(path)
        rows = {}
        for mode in ("single", "hero"):
            images, seconds = [], []
            # Untimed first: the shaders compile on a mode's first render.
            renderer.render(scene, spp=1, width=args.width, max_depth=args.max_depth,
                            spectral=mode)
            for seed in range(1, args.seeds + 1):
                out = renderer.render(scene, spp=args.spp, width=args.width, seed=seed,
                                      max_depth=args.max_depth, spectral=mode)
                images.append(out.image)
                seconds.append(out.seconds)
            rows[mode] = (float(np.mean(seconds)),) + noise(images)
        for mode in ("single", "hero"):
            t, lum, col = rows[mode]
            ratios = ["", ""]
            if mode == "hero":
                ts, ls, cs = rows["single"]
                ratios = ["%.2f / %.2f" % (ls / lum, ls * ts / (lum * t)),
                          "%.2f / %.2f" % (cs / col, cs * ts / (col * t))]
            print("| %s | %s | %.3f | %.4g | %.4g | %s | %s |" % (
                os.path.basename(path), mode, t, lum, col, ratios[0], ratios[1]))


if __name__ == "__main__":
    main()
