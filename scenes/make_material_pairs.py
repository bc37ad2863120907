#!/usr/bin/env python3
"""Writes the material gallery's pairs (issue 48): each scene shows an extension's material
beside the same material without it, under the same light.

- anisotropy_pair.gltf: two brushed-gold spheres (metal, roughness 0.35) under a long strip
  light; the right one has KHR_materials_anisotropy (strength 0.8 along its UV tangent, the
  sphere's longitude), so its highlight stretches along the latitudes; the left is isotropic.
- iridescence_pair.gltf: two dark glossy spheres; the right one carries a thin film
  (KHR_materials_iridescence, factor 1, film ior 1.3, 400 nm): its reflections turn coloured
  with the angle; the left reflects white.
- dispersion_pair.gltf: two glass balls on a white floor under a small light; the right one
  has KHR_materials_dispersion 5 (an Abbe number of 4, exaggerated): its caustic spreads into
  colours; the left one's is white.
(KHR_materials_diffuse_transmission's pair is lamp_shades.gltf.) Run
`python3 make_material_pairs.py`.
"""

import math
import os
import struct

from make_cornell_box import GltfWriter, quad
from make_failure_scenes import camera, floor, material, sphere_light


def smooth_sphere(g, center, radius, material_index, rings=32, segments=64):
    """A UV sphere with normals and texture coordinates (u along the longitude), so that the
    loader builds tangents for anisotropy."""
    cx, cy, cz = center
    positions, normals, uvs, indices = [], [], [], []
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments + 1):
            phi = 2.0 * math.pi * j / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
            positions += [cx + radius * n[0], cy + radius * n[1], cz + radius * n[2]]
            normals += list(n)
            uvs += [j / segments, i / rings]
    for i in range(rings):
        for j in range(segments):
            a = i * (segments + 1) + j
            b = a + segments + 1
            # The pole rows' other triangle would have two corners at the pole.
            if i > 0:
                indices += [a, a + 1, b]
            if i < rings - 1:
                indices += [a + 1, b + 1, b]
    count = len(positions) // 3
    pos = g._accessor(bufferView=g._view(struct.pack("<%df" % len(positions), *positions),
                                         34962),
                      componentType=5126, count=count, type="VEC3",
                      min=[min(positions[k::3]) for k in range(3)],
                      max=[max(positions[k::3]) for k in range(3)])
    nrm = g._accessor(bufferView=g._view(struct.pack("<%df" % len(normals), *normals), 34962),
                      componentType=5126, count=count, type="VEC3")
    tex = g._accessor(bufferView=g._view(struct.pack("<%df" % len(uvs), *uvs), 34962),
                      componentType=5126, count=count, type="VEC2")
    idx = g._accessor(bufferView=g._view(struct.pack("<%dH" % len(indices), *indices), 34963),
                      componentType=5123, count=len(indices), type="SCALAR")
    return {"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": tex},
            "indices": idx, "material": material_index, "mode": 4}


def use_extension(g, index, name, fields):
    g.doc["materials"][index].setdefault("extensions", {})[name] = fields
    if name not in g.doc["extensionsUsed"]:
        g.doc["extensionsUsed"].append(name)


def pair_scene(make_material, light):
    """Two spheres of radius 0.5 on a grey floor, left plain, right with the extension."""
    g = GltfWriter()
    grey = material(g, "floor", (0.5, 0.5, 0.5), lambert=True)
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(8.0), grey)]))
    for name, x, extended in (("plain", -0.65, False), ("extended", 0.65, True)):
        index = make_material(g, name, extended)
        g.node(name=name, mesh=g.mesh(name, [smooth_sphere(g, (x, 0.5, 0.0), 0.5, index)]))
    light(g)
    camera(g, (0.0, 1.3, 3.2), (0.0, 0.45, 0.0), 0.6, aspect=2.0)
    return g


def strip_light(g):
    lamp = material(g, "strip", (0.0, 0.0, 0.0), lambert=True, emission=(12.0, 11.5, 10.5))
    g.node(name="strip", mesh=g.mesh("strip", [g.primitive(
        [quad((-2.0, 2.5, -0.12), (2.0, 2.5, -0.12), (2.0, 2.5, 0.12), (-2.0, 2.5, 0.12),
              (0, -1, 0))], lamp)]))
    sphere_light(g, "fill", (-1.5, 2.0, 2.5), 0.3, 8.0)


def anisotropy_pair():
    def make(g, name, extended):
        index = material(g, name, (1.0, 0.78, 0.34), metallic=1.0, roughness=0.35)
        if extended:
            use_extension(g, index, "KHR_materials_anisotropy", {"anisotropyStrength": 0.8})
        return index
    return pair_scene(make, strip_light)


def iridescence_pair():
    def make(g, name, extended):
        index = material(g, name, (0.04, 0.04, 0.05), roughness=0.15)
        if extended:
            use_extension(g, index, "KHR_materials_iridescence", {
                "iridescenceFactor": 1.0, "iridescenceIor": 1.3,
                "iridescenceThicknessMinimum": 400.0, "iridescenceThicknessMaximum": 400.0})
        return index
    return pair_scene(make, strip_light)


def dispersion_pair():
    def make(g, name, extended):
        index = material(g, name, (1.0, 1.0, 1.0), roughness=0.0, transmission=1.0, ior=1.5)
        if extended:
            use_extension(g, index, "KHR_materials_dispersion", {"dispersion": 5.0})
        return index

    def small_light(g):
        sphere_light(g, "light", (0.0, 3.0, -1.2), 0.06, 40.0)
    return pair_scene(make, small_light)


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for name, build in (("anisotropy_pair", anisotropy_pair),
                        ("iridescence_pair", iridescence_pair),
                        ("dispersion_pair", dispersion_pair)):
        doc = build()
        doc.doc["asset"]["generator"] = "scenes/make_material_pairs.py"
        doc.write(os.path.join(here, name + ".gltf"))
