#!/usr/bin/env python3
"""Writes prism.gltf: KHR_materials_dispersion, a glass prism casting a rainbow on a floor.

A smooth glass prism (equilateral cross-section, ior 1.5, dispersion 5, i.e. an Abbe number
of 4: exaggerated, as the spec allows, so that the spectrum spreads over the floor) is held
above a white floor, apex up. A bright strip light low on the left, long along the prism's
axis, shines through a narrow slit in a dark wall, so a thin sheet of light meets the prism's
left face near minimum deviation; it leaves the right face bent down and split into its
colours, a rainbow on the floor beyond (violet nearest the prism, red farthest). Path tracing
finds that light by BSDF sampling from the floor through the glass and the slit, so the rainbow
is a caustic (docs/gltf.md says how it is traced): the strip and slit are long along the axis,
where their length blurs no colour, so that it converges in a few hundred samples per pixel.
prism_rough.gltf is the same scene with a rough prism (roughness 0.2): the beam leaves it
blurred, and a path's vertex on the prism's inside reaches the light by next-event estimation
(rough dispersive glass, where --spectral hero weighs four wavelengths). Run
`python3 make_prism.py`.
"""

import math
import os

from make_cornell_box import GltfWriter, quad
from make_failure_scenes import camera, floor, material, triangle_primitive


def prism(base_y, half_width, depth):
    """A closed triangular prism along z, apex up, counter-clockwise seen from outside."""
    h = half_width * math.sqrt(3.0)
    a, b, c = (-half_width, base_y), (half_width, base_y), (0.0, base_y + h)
    z0, z1 = -depth / 2, depth / 2
    p = lambda v, z: (v[0], v[1], z)
    sides = [
        quad(p(a, z0), p(b, z0), p(b, z1), p(a, z1), (0, -1, 0)),  # base
        quad(p(b, z0), p(c, z0), p(c, z1), p(b, z1), (math.sqrt(3) / 2, 0.5, 0)),  # right
        quad(p(c, z0), p(a, z0), p(a, z1), p(c, z1), (-math.sqrt(3) / 2, 0.5, 0)),  # left
    ]
    tris = [(q[0], q[1], q[2]) for q in sides] + [(q[0], q[2], q[3]) for q in sides]
    tris += [(p(a, z1), p(b, z1), p(c, z1)), (p(a, z0), p(c, z0), p(b, z0))]  # the two ends
    return tris


def slit_wall(x, height, half_depth, slit_y, slit_height, slit_half_depth):
    """A wall in the plane x facing +x, with a horizontal slit cut out of it."""
    def rect(y0, y1, z0, z1):
        return quad((x, y0, z1), (x, y0, z0), (x, y1, z0), (x, y1, z1), (1, 0, 0))
    y0, y1 = slit_y, slit_y + slit_height
    return [rect(0.0, y0, -half_depth, half_depth), rect(y1, height, -half_depth, half_depth),
            rect(y0, y1, -half_depth, -slit_half_depth),
            rect(y0, y1, slit_half_depth, half_depth)]


def dispersive(g, index, dispersion):
    mat = g.doc["materials"][index]
    mat.setdefault("extensions", {})["KHR_materials_dispersion"] = {"dispersion": dispersion}
    if "KHR_materials_dispersion" not in g.doc["extensionsUsed"]:
        g.doc["extensionsUsed"].append("KHR_materials_dispersion")
    return index


def prism_scene(roughness=0.0):
    g = GltfWriter()
    white = material(g, "floor", (0.8, 0.8, 0.8), lambert=True)
    glass = dispersive(g, material(g, "dispersive glass", (1.0, 1.0, 1.0), roughness=roughness,
                                   transmission=1.0, ior=1.5), 5.0)
    g.node(name="floor", mesh=g.mesh("floor", [g.primitive(floor(10.0), white)]))
    dark = material(g, "wall", (0.05, 0.05, 0.05), lambert=True)
    g.node(name="prism", mesh=g.mesh("prism", [triangle_primitive(
        g, prism(0.6, 0.35, 2.4), glass)]))
    g.node(name="slit wall", mesh=g.mesh("slit wall", [g.primitive(
        slit_wall(-1.6, 4.0, 4.0, 0.685, 0.035, 1.4), dark)]))
    strip = material(g, "strip light", (0.0, 0.0, 0.0), lambert=True,
                     emission=(600.0, 600.0, 600.0))
    x, y0, y1, z = -4.5, 0.25, 0.4, 2.5
    g.node(name="strip light", mesh=g.mesh("strip light", [g.primitive(
        [quad((x, y0, z), (x, y0, -z), (x, y1, -z), (x, y1, z), (1, 0, 0))], strip)]))
    camera(g, (2.2, 2.8, 3.4), (1.0, 0.3, 0.0), 0.8, aspect=1.5)
    return g


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for name, roughness in (("prism", 0.0), ("prism_rough", 0.2)):
        doc = prism_scene(roughness)
        doc.doc["asset"]["generator"] = "scenes/make_prism.py"
        doc.write(os.path.join(here, name + ".gltf"))
