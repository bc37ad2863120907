#!/usr/bin/env python3
"""Writes lamp_shades.gltf: KHR_materials_diffuse_transmission beside its plain counterpart.

Two paper lamp shades (open cylinders round a small sphere light each) of the same warm base
colour on a grey floor: the left one's paper lets 70% of its diffuse light through
(diffuseTransmissionFactor 0.7, a warm diffuseTransmissionColorFactor), so it glows from
inside and lights the floor round it; the right one is the same paper without the extension,
opaque, lighting only the floor below its open bottom and the ceiling-less dark above. A thin
leaf (a quad with diffuse transmission 0.5, green) stands in front of the left lamp, lit from
behind. Run `python3 make_lamp_shades.py`.
"""

import math
import os

from make_cornell_box import GltfWriter, quad
from make_failure_scenes import camera, floor, material, sphere_light


def cylinder(center, radius, height, segments=48):
    """An open cylinder's side, counter-clockwise seen from outside."""
    cx, cy, cz = center
    quads = []
    for j in range(segments):
        a0, a1 = 2 * math.pi * j / segments, 2 * math.pi * (j + 1) / segments
        p = lambda a, y: (cx + radius * math.cos(a), y, cz + radius * math.sin(a))
        mid = 0.5 * (a0 + a1)
        outward = (math.cos(mid), 0.0, math.sin(mid))
        quads.append(quad(p(a0, cy), p(a0, cy + height), p(a1, cy + height), p(a1, cy),
                          outward))
    return quads


def translucent(g, index, factor, color):
    mat = g.doc["materials"][index]
    mat.setdefault("extensions", {})["KHR_materials_diffuse_transmission"] = {
        "diffuseTransmissionFactor": factor, "diffuseTransmissionColorFactor": list(color)}
    mat["doubleSided"] = True
    if "KHR_materials_diffuse_transmission" not in g.doc["extensionsUsed"]:
        g.doc["extensionsUsed"].append("KHR_materials_diffuse_transmission")
    return index


def lamp_shades():
    g = GltfWriter()
    grey = material(g, "floor", (0.5, 0.5, 0.5), lambert=True)
    paper = (0.85, 0.75, 0.6)
    glowing = translucent(g, material(g, "translucent paper", paper, roughness=0.6), 0.7,
                          (1.0, 0.8, 0.55))
    opaque = material(g, "opaque paper", paper, roughness=0.6)
    opaque_doc = g.doc["materials"][opaque]
    opaque_doc["doubleSided"] = True
    leaf = translucent(g, material(g, "leaf", (0.15, 0.35, 0.08), roughness=0.5), 0.5,
                       (0.45, 0.8, 0.2))
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(8.0), grey)]))
    for name, x, mat in (("translucent shade", -0.8, glowing), ("opaque shade", 0.8, opaque)):
        g.node(name=name, mesh=g.mesh(name, [g.primitive(cylinder((x, 0.5, 0.0), 0.35, 0.6),
                                                          mat)]))
        sphere_light(g, name + " bulb", (x, 0.8, 0.0), 0.06, 6.0, (1.0, 0.9, 0.75))
    # The leaf: 30 cm, upright, between the camera and the translucent shade, facing the camera.
    s = 0.15
    c = (-0.75, 0.35, 0.75)
    g.node(name="leaf", mesh=g.mesh("leaf", [g.primitive(
        [quad((c[0] - s, c[1] - s, c[2]), (c[0] + s, c[1] - s, c[2]), (c[0] + s, c[1] + s, c[2]),
              (c[0] - s, c[1] + s, c[2]), (0, 0, 1))], leaf)]))
    camera(g, (0.0, 1.2, 3.2), (0.0, 0.55, 0.0), 0.75, aspect=1.5)
    return g


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    doc = lamp_shades()
    doc.doc["asset"]["generator"] = "scenes/make_lamp_shades.py"
    doc.write(os.path.join(here, "lamp_shades.gltf"))
