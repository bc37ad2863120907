#!/usr/bin/env python3
"""Writes a larger animated scene for timing render --frames (docs/animation.md): a static
rippled ground of 2 x GRID^2 triangles, a UV-sphere blob of about 4 x BLOB^2 triangles that
breathes (one POSITION morph target, its weight animated LINEAR) while it slides across the
ground, a ring of spinning boxes (rigid rotation) and an emissive panel gliding overhead (moving
emissive triangles, so the light table changes every frame), over two seconds at 24 fps.

    python3 bench/make_animated_field.py out/field.gltf --grid 400 --blob 120

(--grid 400 --blob 120: 320k static and 58k moving triangles). Writes OUT.gltf with its
buffer in OUT.bin beside it. Generate at run time; don't commit scenes.
"""

import argparse
import array
import json
import math
import os

F32, U32 = 5126, 5125


class Doc:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "make_animated_field.py"},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [],
                    "materials": [], "accessors": [], "bufferViews": [], "buffers": [],
                    "animations": [{"name": "play", "channels": [], "samplers": []}],
                    "cameras": []}

    def accessor(self, values, code, ctype, kind, minmax=False):
        while len(self.bin) % 4:
            self.bin.append(0)
        data = array.array(code, values).tobytes()
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin),
                                        "byteLength": len(data)})
        self.bin += data
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[kind]
        acc = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": ctype,
               "count": len(values) // width, "type": kind}
        if minmax:
            acc["min"] = [min(values[i::width]) for i in range(width)]
            acc["max"] = [max(values[i::width]) for i in range(width)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def floats(self, values, kind, minmax=False):
        return self.accessor(values, "f", F32, kind, minmax)

    def material(self, color, roughness=0.6, emissive=None):
        m = {"pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0],
                                      "roughnessFactor": roughness, "metallicFactor": 0.0}}
        if emissive:
            m["emissiveFactor"] = [1.0, 1.0, 1.0]
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": emissive}}
            self.doc.setdefault("extensionsUsed", []).append("KHR_materials_emissive_strength")
        self.doc["materials"].append(m)
        return len(self.doc["materials"]) - 1

    def mesh(self, positions, indices, material, targets=None):
        prim = {"attributes": {"POSITION": self.floats(positions, "VEC3", True)},
                "indices": self.accessor(indices, "I", U32, "SCALAR"), "material": material}
        mesh = {"primitives": [prim]}
        if targets:
            prim["targets"] = [{"POSITION": self.floats(t, "VEC3", True)} for t in targets]
            mesh["weights"] = [0.0] * len(targets)
        self.doc["meshes"].append(mesh)
        return len(self.doc["meshes"]) - 1

    def node(self, **fields):
        self.doc["nodes"].append(fields)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)
        return len(self.doc["nodes"]) - 1

    def channel(self, node, path, times, values, interpolation="LINEAR"):
        kind = {"translation": "VEC3", "rotation": "VEC4", "weights": "SCALAR"}[path]
        anim = self.doc["animations"][0]
        anim["samplers"].append({"input": self.floats(times, "SCALAR", True),
                                 "output": self.floats(values, kind),
                                 "interpolation": interpolation})
        anim["channels"].append({"sampler": len(anim["samplers"]) - 1,
                                 "target": {"node": node, "path": path}})

    def write(self, path):
        bin_name = os.path.splitext(os.path.basename(path))[0] + ".bin"
        with open(os.path.join(os.path.dirname(path) or ".", bin_name), "wb") as f:
            f.write(self.bin)
        self.doc["buffers"] = [{"byteLength": len(self.bin), "uri": bin_name}]
        with open(path, "w") as f:
            json.dump(self.doc, f)


def grid(n, size):
    """n x n quads over [-size, size]^2 at y = a gentle ripple, counter-clockwise from above."""
    p, idx = [], []
    for j in range(n + 1):
        for i in range(n + 1):
            x, z = -size + 2 * size * i / n, -size + 2 * size * j / n
            p += [x, 0.05 * math.sin(3 * x) * math.cos(2 * z), z]
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            idx += [a, a + n + 1, a + 1, a + 1, a + n + 1, a + n + 2]
    return p, idx


def sphere(rings, radius):
    """A UV sphere (2 x rings segments) and a morph target pushing bumps out radially."""
    segs = 2 * rings
    p, bumps, idx = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segs + 1):
            phi = 2 * math.pi * s / segs
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)]
            p += [radius * c for c in n]
            bump = 0.35 * radius * max(0.0, math.sin(5 * phi) * math.sin(4 * theta))
            bumps += [bump * c for c in n]
    for r in range(rings):
        for s in range(segs):
            a, b = r * (segs + 1) + s, (r + 1) * (segs + 1) + s
            if r > 0:
                idx += [a, a + 1, b]
            if r < rings - 1:
                idx += [a + 1, b + 1, b]
    return p, idx, bumps


def box(h):
    p, idx = [], []
    for axis in range(3):
        for side in (-h, h):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            base = len(p) // 3
            for a, b in ((-h, -h), (h, -h), (h, h), (-h, h)):
                c = [0.0, 0.0, 0.0]
                c[axis], c[u], c[v] = side, a, b
                p += c
            idx += [base + q for q in ([0, 1, 2, 0, 2, 3] if side > 0 else [0, 2, 1, 0, 3, 2])]
    return p, idx


def quat_y(degrees):
    return [0.0, math.sin(math.radians(degrees) / 2), 0.0, math.cos(math.radians(degrees) / 2)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--grid", type=int, default=400, help="ground quads per side")
    ap.add_argument("--blob", type=int, default=120, help="blob rings")
    args = ap.parse_args()
    d = Doc()
    times = [i / 12 for i in range(25)]  # 0 .. 2 s
    ground = d.mesh(*grid(args.grid, 4.0), d.material([0.7, 0.7, 0.7], 0.8))
    d.node(name="ground", mesh=ground)
    p, idx, bumps = sphere(args.blob, 0.8)
    blob = d.node(name="blob", mesh=d.mesh(p, idx, d.material([0.8, 0.3, 0.2], 0.4),
                                           targets=[bumps]), translation=[-1.5, 0.9, 0])
    d.channel(blob, "weights", times, [0.5 - 0.5 * math.cos(math.pi * t) for t in times])
    d.channel(blob, "translation", times,
              [c for t in times for c in (-1.5 + 1.5 * t, 0.9, 0.3 * math.sin(math.pi * t))])
    cube = d.mesh(*box(0.2), d.material([0.2, 0.5, 0.8], 0.3))
    for k in range(12):
        a = 2 * math.pi * k / 12
        n = d.node(name="box%d" % k, mesh=cube, translation=[3 * math.cos(a), 0.25,
                                                             3 * math.sin(a)])
        d.channel(n, "rotation", times, [c for t in times for c in quat_y(90 * t * (1 + k % 3))])
    panel = d.mesh([-0.6, 0, -0.6, 0.6, 0, -0.6, 0.6, 0, 0.6, -0.6, 0, 0.6], [0, 1, 2, 0, 2, 3],
                   d.material([0, 0, 0], 1.0, emissive=12.0))
    light = d.node(name="panel", mesh=panel, translation=[-1, 3, 0])
    d.channel(light, "translation", times, [c for t in times for c in (-1 + t, 3, 0)])
    d.doc["cameras"].append({"type": "perspective",
                             "perspective": {"yfov": 0.7, "aspectRatio": 1.5, "znear": 0.1}})
    # Looking down the -z axis from above and behind, tilted 25 degrees down.
    tilt = math.radians(-25) / 2
    d.node(name="camera", camera=0, translation=[0, 3.2, 6.5],
           rotation=[math.sin(tilt), 0, 0, math.cos(tilt)])
    d.write(args.out)
    triangles = 2 * args.grid ** 2 + 2 * (2 * args.blob) * (args.blob - 1) + 12 * 12 + 2
    print("wrote %s: about %d triangles" % (args.out, triangles))


if __name__ == "__main__":
    main()
