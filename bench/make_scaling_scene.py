#!/usr/bin/env python3
"""Writes a scene of about N triangles for the scaling benchmark: the Cornell box room and light
(scenes/make_cornell_box.py) filled with a grid of UV spheres in several materials (Lambert,
rough metal, glossy plastic, glass), so that both the BVH and the shading see a real load.
Spheres of one material share one mesh, placed by many nodes, so even 10^6 triangles make a
file of a few kilobytes; generate scenes at run time rather than committing them.

--unique gives every sphere a mesh of its own (a file as large as its triangles), so that the
triangles stay unique whatever `--instancing` says. --instanced-triangles N adds a floor of
small "pebbles", one mesh of about 10^5 triangles placed N / 10^5 times: the renderer keeps
it once and instances it (a two-level BVH).

    python3 bench/make_scaling_scene.py OUT.gltf --triangles 100000 [--materials 4] [--unique]
        [--instanced-triangles 1000000000]
"""
import argparse
import math
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes"))
import make_cornell_box as cornell  # noqa: E402

# name, base colour, metallic, roughness, extras: four kinds of lobe the shading must handle.
MATERIALS = [
    ("lambert", (0.8, 0.75, 0.7), 0.0, 1.0, {"KHR_materials_specular": {"specularFactor": 0.0}}),
    ("metal", (0.9, 0.6, 0.3), 1.0, 0.3, {}),
    ("plastic", (0.2, 0.3, 0.8), 0.0, 0.4, {}),
    ("glass", (1.0, 1.0, 1.0), 0.0, 0.0, {"KHR_materials_transmission": {
        "transmissionFactor": 1.0}}),
]


def uv_sphere(rings):
    """Unit sphere with `rings` latitude bands and 2 * rings segments: 4 r (r - 1) triangles,
    counter-clockwise seen from outside, none degenerate (the poles are fans)."""
    segments = 2 * rings
    points = [(0.0, 1.0, 0.0)]
    for r in range(1, rings):
        theta = math.pi * r / rings
        for s in range(segments):
            phi = 2 * math.pi * s / segments
            points.append((math.sin(theta) * math.cos(phi), math.cos(theta),
                           math.sin(theta) * math.sin(phi)))
    points.append((0.0, -1.0, 0.0))
    south = len(points) - 1
    ring = lambda r, s: 1 + (r - 1) * segments + s % segments  # noqa: E731
    tris = []
    for s in range(segments):
        tris.append((0, ring(1, s + 1), ring(1, s)))
        tris.append((south, ring(rings - 1, s), ring(rings - 1, s + 1)))
    for r in range(1, rings - 1):
        for s in range(segments):
            a, b = ring(r, s), ring(r, s + 1)
            c, d = ring(r + 1, s), ring(r + 1, s + 1)
            tris += [(a, b, d), (a, d, c)]
    return points, tris


def sphere_primitive(g, points, tris, material):
    pos_view = g._view(struct.pack("<%df" % (3 * len(points)), *[c for p in points for c in p]),
                       34962)
    flat = [i for t in tris for i in t]
    idx_view = g._view(struct.pack("<%dI" % len(flat), *flat), 34963)
    pos = g._accessor(bufferView=pos_view, componentType=5126, count=len(points), type="VEC3",
                      min=[-1.0, -1.0, -1.0], max=[1.0, 1.0, 1.0])
    idx = g._accessor(bufferView=idx_view, componentType=5125, count=len(flat), type="SCALAR")
    return {"attributes": {"POSITION": pos}, "indices": idx, "material": material, "mode": 4}


PEBBLE_RINGS = 160  # 4 r (r - 1) = 101,760 triangles a pebble


def add_pebbles(g, instanced_triangles, material):
    """A square grid of small spheres on the floor, one mesh placed by every node."""
    points, tris = uv_sphere(PEBBLE_RINGS)
    per_pebble = len(tris)
    count = max(1, round(instanced_triangles / per_pebble))
    mesh = g.mesh("pebble", [sphere_primitive(g, points, tris, material)])
    side = math.ceil(math.sqrt(count))
    spacing = (cornell.S - 0.2) / side
    radius = 0.4 * spacing
    for p in range(count):
        i, k = p % side, p // side
        g.node(name="pebble %d" % p, mesh=mesh, scale=[radius] * 3,
               translation=[0.1 + (i + 0.5) * spacing, radius, 0.1 + (k + 0.5) * spacing])
    return count * per_pebble


def build(triangles, material_count, unique=False, instanced_triangles=0):
    g = cornell.GltfWriter()
    g.doc["asset"]["generator"] = "bench/make_scaling_scene.py"
    g.doc["extensionsUsed"].append("KHR_materials_transmission")
    white = cornell.lit_room(g)
    fixed = 12  # room and light

    # Few spheres for small scenes (the sphere itself needs ~80 triangles), up to a few
    # thousand for large ones; each sphere's tessellation makes up the rest.
    clutter = max(triangles - fixed, 24)
    count_guess = max(1, min(2500, clutter // 400))
    rings = max(3, round((1 + math.sqrt(1 + clutter / count_guess)) / 2))
    per_sphere = 4 * rings * (rings - 1)
    count = max(1, round(clutter / per_sphere))
    points, tris = uv_sphere(rings)
    meshes = []
    for k in range(material_count):
        name, color, metallic, roughness, ext = MATERIALS[k % len(MATERIALS)]
        mat = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0],
                                                      "metallicFactor": metallic,
                                                      "roughnessFactor": roughness}}
        if ext:
            mat["extensions"] = ext
        g.doc["materials"].append(mat)
        index = len(g.doc["materials"]) - 1
        meshes.append(index if unique else
                      g.mesh("sphere " + name, [sphere_primitive(g, points, tris, index)]))

    # A cubic grid filling the box below the light, radius under half the spacing.
    n = math.ceil(count ** (1 / 3))
    lo, hi = 0.4, cornell.S - 0.6
    spacing = (hi - lo) / n
    radius = 0.42 * spacing
    placed = 0
    for j in range(n):
        for i in range(n):
            for k in range(n):
                if placed == count:
                    break
                centre = [lo + (i + 0.5) * spacing, lo + (j + 0.5) * spacing,
                          lo + (k + 0.5) * spacing]
                mesh = meshes[placed % material_count]
                if unique:  # its own copy of the sphere, under the material's index
                    mesh = g.mesh("sphere %d" % placed,
                                  [sphere_primitive(g, points, tris, mesh)])
                g.node(name="sphere %d" % placed, mesh=mesh, translation=centre,
                       scale=[radius] * 3)
                placed += 1
    g.doc["cameras"].append({"type": "perspective", "name": "camera", "perspective": {
        "yfov": 2 * math.atan(12.5 / 35.0), "aspectRatio": 1.0, "znear": 0.1, "zfar": 100.0}})
    g.node(name="camera", camera=0, translation=[2.775, 2.73, -8.0],
           rotation=cornell.y_rotation(180.0))
    pebbles = add_pebbles(g, instanced_triangles, len(g.doc["materials"]) - material_count) \
        if instanced_triangles > 0 else 0
    return g, fixed + count * per_sphere, pebbles


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output")
    parser.add_argument("--triangles", type=int, default=100000, help="about this many")
    parser.add_argument("--materials", type=int, default=4, help="sphere materials, 1 to 4")
    parser.add_argument("--unique", action="store_true",
                        help="a mesh per sphere: every triangle unique")
    parser.add_argument("--instanced-triangles", type=int, default=0,
                        help="add a floor of one pebble mesh placed to about this many")
    args = parser.parse_args()
    g, total, pebbles = build(args.triangles, max(1, min(args.materials, len(MATERIALS))),
                              args.unique, args.instanced_triangles)
    g.write(args.output)
    print("%s: %d triangles%s" % (args.output, total, " + %d instanced pebble triangles"
                                  % pebbles if pebbles else ""))


if __name__ == "__main__":
    main()
