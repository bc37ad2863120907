#!/usr/bin/env python3
"""Writes cornell_box.gltf: the classic Cornell box as one self-contained glTF file.

Geometry follows the Cornell Program of Computer Graphics measurements, squared off to a
5.55-unit cube (1 unit = 100 mm) so that walls are exactly planar: white floor, ceiling and
back wall, red left wall, green right wall, a short and a tall block turned by about 17
degrees, and a 1.30 x 1.05 light just below the ceiling, facing down. The camera matches the
original (35 mm lens on a 25 mm sensor, so yfov = 2 atan(12.5 / 35)).

Every face is wound counter-clockwise seen from the side it faces (the box's interior, the
outside of the blocks, downwards for the light); build() asserts it. Materials set
KHR_materials_specular.specularFactor = 0 so that renderers implementing the full glTF BRDF
still see exact Lambert. Standard library only: run `python3 make_cornell_box.py`.
"""

import base64
import json
import math
import os
import struct

S = 5.55  # side of the box
LIGHT_Y = S - 0.005  # just below the ceiling, so the two never coincide
EMISSION = (17.0, 12.0, 4.0)  # the warm light of the classic renders

WHITE = (0.725, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def quad(p0, p1, p2, p3, facing):
    """A quad as two triangles, checked to be counter-clockwise seen from `facing`."""
    normal = cross(sub(p1, p0), sub(p2, p0))
    assert dot(normal, facing) > 0, (p0, p1, p2, p3, facing)
    return [p0, p1, p2, p3]


def room_quads():
    """Floor, ceiling, back, left (red, +x) and right (green, x = 0) walls, facing inward."""
    up, down = (0, 1, 0), (0, -1, 0)
    white = [
        quad((0, 0, 0), (0, 0, S), (S, 0, S), (S, 0, 0), up),  # floor
        quad((0, S, 0), (S, S, 0), (S, S, S), (0, S, S), down),  # ceiling
        quad((0, 0, S), (0, S, S), (S, S, S), (S, 0, S), (0, 0, -1)),  # back wall
    ]
    red = [quad((S, 0, 0), (S, 0, S), (S, S, S), (S, S, 0), (-1, 0, 0))]
    green = [quad((0, 0, 0), (0, S, 0), (0, S, S), (0, 0, S), (1, 0, 0))]
    return white, red, green


def light_quad():
    x0, x1, z0, z1 = 2.13, 3.43, 2.27, 3.32
    return [quad((x0, LIGHT_Y, z0), (x1, LIGHT_Y, z0), (x1, LIGHT_Y, z1), (x0, LIGHT_Y, z1),
                 (0, -1, 0))]


def unit_block_quads():
    """x and z in [-0.5, 0.5], y in [0, 1]; faces outward. Nodes scale and turn it.

    No bottom face: it would lie on the floor, where no light reaches it and where
    coincident triangles would only make intersection order matter."""
    a, b = -0.5, 0.5
    return [
        quad((a, 1, a), (a, 1, b), (b, 1, b), (b, 1, a), (0, 1, 0)),  # top
        quad((a, 0, a), (a, 1, a), (b, 1, a), (b, 0, a), (0, 0, -1)),  # front (-z)
        quad((a, 0, b), (b, 0, b), (b, 1, b), (a, 1, b), (0, 0, 1)),  # back (+z)
        quad((a, 0, a), (a, 0, b), (a, 1, b), (a, 1, a), (-1, 0, 0)),  # -x
        quad((b, 0, a), (b, 1, a), (b, 1, b), (b, 0, b), (1, 0, 0)),  # +x
    ]


def y_rotation(degrees):
    """Quaternion (x, y, z, w) turning `degrees` about +Y."""
    half = math.radians(degrees) / 2
    return [0.0, round(math.sin(half), 12), 0.0, round(math.cos(half), 12)]


class GltfWriter:
    """Collects quads into one buffer and writes a glTF with the buffer as a data: URI."""

    def __init__(self):
        self.data = bytearray()
        self.doc = {
            "asset": {"version": "2.0", "generator": "scenes/make_cornell_box.py"},
            "extensionsUsed": ["KHR_materials_specular", "KHR_materials_emissive_strength"],
            "scene": 0, "scenes": [{"name": "Scene", "nodes": []}], "nodes": [],
            "meshes": [], "materials": [], "cameras": [], "accessors": [], "bufferViews": [],
        }

    def _view(self, blob, target):
        while len(self.data) % 4:
            self.data.append(0)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data),
                                        "byteLength": len(blob), "target": target})
        self.data += blob
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, **fields):
        self.doc["accessors"].append(fields)
        return len(self.doc["accessors"]) - 1

    def material(self, name, color, emission=(0.0, 0.0, 0.0)):
        mat = {"name": name,
               "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0],
                                        "metallicFactor": 0.0, "roughnessFactor": 1.0},
               "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}
        strength = max(emission)
        if strength > 0:
            # emissiveFactor must lie in [0, 1]; the extension carries the rest.
            mat["emissiveFactor"] = [e / strength for e in emission]
            if strength > 1:
                mat["extensions"]["KHR_materials_emissive_strength"] = {
                    "emissiveStrength": strength}
        self.doc["materials"].append(mat)
        return len(self.doc["materials"]) - 1

    def primitive(self, quads, material):
        points = [p for q in quads for p in q]
        indices = [4 * i + k for i in range(len(quads)) for k in (0, 1, 2, 0, 2, 3)]
        pos_view = self._view(struct.pack("<%df" % (3 * len(points)),
                                          *[c for p in points for c in p]), 34962)
        idx_view = self._view(struct.pack("<%dH" % len(indices), *indices), 34963)
        pos = self._accessor(bufferView=pos_view, componentType=5126, count=len(points),
                             type="VEC3", min=[min(p[i] for p in points) for i in range(3)],
                             max=[max(p[i] for p in points) for i in range(3)])
        idx = self._accessor(bufferView=idx_view, componentType=5123, count=len(indices),
                             type="SCALAR")
        return {"attributes": {"POSITION": pos}, "indices": idx, "material": material,
                "mode": 4}

    def mesh(self, name, primitives):
        self.doc["meshes"].append({"name": name, "primitives": primitives})
        return len(self.doc["meshes"]) - 1

    def node(self, **fields):
        self.doc["nodes"].append(fields)
        self.doc["scenes"][0]["nodes"].append(len(self.doc["nodes"]) - 1)

    def write(self, path):
        uri = "data:application/octet-stream;base64," + base64.b64encode(self.data).decode()
        self.doc["buffers"] = [{"byteLength": len(self.data), "uri": uri}]
        with open(path, "w", encoding="ascii") as f:
            json.dump(self.doc, f, indent=1)
            f.write("\n")


def lit_room(g):
    """The room's walls and its ceiling light, with their materials, into writer `g`; the
    white material's index. The Cornell box and the bench scenes (bench/) start from it."""
    white = g.material("white", WHITE)
    red = g.material("red", RED)
    green = g.material("green", GREEN)
    light = g.material("light", (0.78, 0.78, 0.78), EMISSION)

    white_quads, red_quads, green_quads = room_quads()
    room = g.mesh("room", [g.primitive(white_quads, white), g.primitive(red_quads, red),
                           g.primitive(green_quads, green)])
    g.node(name="room", mesh=room)
    g.node(name="light", mesh=g.mesh("light", [g.primitive(light_quad(), light)]))
    return white


def build():
    g = GltfWriter()
    white = lit_room(g)
    block = g.mesh("block", [g.primitive(unit_block_quads(), white)])
    g.node(name="short block", mesh=block, translation=[1.855, 0.0, 1.69],
           rotation=y_rotation(-17.0), scale=[1.65, 1.65, 1.65])
    g.node(name="tall block", mesh=block, translation=[3.685, 0.0, 3.5125],
           rotation=y_rotation(17.0), scale=[1.65, 3.30, 1.65])

    # glTF cameras look down -Z; half a turn about +Y makes this one look into the box (+Z).
    g.doc["cameras"].append({"type": "perspective", "name": "camera", "perspective": {
        "yfov": 2 * math.atan(12.5 / 35.0), "aspectRatio": 1.0, "znear": 0.1, "zfar": 100.0}})
    g.node(name="camera", camera=0, translation=[2.775, 2.73, -8.0],
           rotation=y_rotation(180.0))
    return g


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    build().write(os.path.join(here, "cornell_box.gltf"))
