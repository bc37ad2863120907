#!/usr/bin/env python3
"""Render a scene with its AOVs (albedo, normal, depth) and show them side by side.

Usage: aov_side_by_side.py [SCENE.gltf] [FIGURE.png]
Defaults: the Cornell box of scenes/, aov_side_by_side.png.
"""
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import wavefront as wf

HERE = Path(__file__).resolve().parent
scene_path = sys.argv[1] if len(sys.argv) > 1 else HERE.parent / "scenes" / "cornell_box.gltf"
figure_path = sys.argv[2] if len(sys.argv) > 2 else "aov_side_by_side.png"

with wf.Renderer() as r:
    scene = r.load(scene_path)
    out = r.render(scene, width=160, spp=32, aov=("albedo", "normal", "depth"))
print(out, f"{out.stats['pathsPerSecond'] / 1e6:.2f} M paths/s")

srgb = lambda x: np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)
panels = {
    "radiance (sRGB)": srgb(np.clip(out.image, 0, 1)),
    "albedo": np.clip(out.aov["albedo"], 0, 1),
    "normal (0.5 + n/2)": np.clip(0.5 + 0.5 * out.aov["normal"], 0, 1),
    "depth": out.aov["depth"],
}
fig, axes = plt.subplots(1, 4, figsize=(12, 3.4))
for ax, (title, image) in zip(axes, panels.items()):
    ax.imshow(image, cmap="viridis" if image.ndim == 2 else None)
    ax.set_title(title, fontsize=10)
    ax.axis("off")
fig.tight_layout()
fig.savefig(figure_path, dpi=100)
print("wrote", figure_path)
