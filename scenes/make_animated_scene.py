#!/usr/bin/env python3
"""Writes animated_arm.gltf: glTF in motion, for the gallery and the animation tests' CLI runs.
Run `python3 make_animated_scene.py`. Over two seconds:

- a skinned arm: a square tube of 16 rings on two bones (the lower at the floor, the upper one
  unit up); the rings near the elbow blend both joints. The upper bone bends 80 degrees about z
  and back (LINEAR rotation keys, slerped); the lower one turns about y (CUBICSPLINE keys).
- a block sliding along x (CUBICSPLINE translation, eased by its tangents) and spinning (STEP
  would jerk; LINEAR rotation), the rigid motion that motion blur shows.
- a tent whose ridge rises and falls: one POSITION morph target, its weight animated (LINEAR).
- a white floor, a warm sphere light and a camera.
"""

import base64
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
F32, U8, U16 = 5126, 5121, 5123


class Doc:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0", "generator": "make_animated_scene.py"},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [],
                    "materials": [], "accessors": [], "bufferViews": [], "buffers": [],
                    "skins": [], "animations": [], "cameras": [],
                    "extensionsUsed": ["KHR_lights_punctual"],
                    "extensions": {"KHR_lights_punctual": {"lights": []}}}

    def accessor(self, values, fmt, ctype, kind, minmax=False):
        while len(self.bin) % 4:
            self.bin.append(0)
        width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4, "MAT4": 16}[kind]
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        self.doc["bufferViews"].append({"buffer": 0, "byteOffset": len(self.bin),
                                        "byteLength": len(data)})
        self.bin += data
        acc = {"bufferView": len(self.doc["bufferViews"]) - 1, "componentType": ctype,
               "count": len(values) // width, "type": kind}
        if minmax:
            acc["min"] = [min(values[i::width]) for i in range(width)]
            acc["max"] = [max(values[i::width]) for i in range(width)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def floats(self, values, kind, minmax=False):
        return self.accessor(values, "f", F32, kind, minmax)

    def material(self, color, roughness=0.6, metallic=0.0):
        self.doc["materials"].append({"pbrMetallicRoughness": {
            "baseColorFactor": list(color) + [1.0], "roughnessFactor": roughness,
            "metallicFactor": metallic}})
        return len(self.doc["materials"]) - 1

    def mesh(self, positions, indices, material, extra=None, targets=None, weights=None):
        attributes = {"POSITION": self.floats(positions, "VEC3", True)}
        attributes.update(extra or {})
        prim = {"attributes": attributes, "indices": self.accessor(indices, "H", U16, "SCALAR"),
                "material": material}
        if targets:
            prim["targets"] = [{"POSITION": self.floats(t, "VEC3", True)} for t in targets]
        mesh = {"primitives": [prim]}
        if weights:
            mesh["weights"] = weights
        self.doc["meshes"].append(mesh)
        return len(self.doc["meshes"]) - 1

    def node(self, root=True, **fields):
        self.doc["nodes"].append(fields)
        index = len(self.doc["nodes"]) - 1
        if root:
            self.doc["scenes"][0]["nodes"].append(index)
        return index

    def animate(self, channels):
        """channels: (node, path, times, values, interpolation)."""
        anim = {"name": "play", "channels": [], "samplers": []}
        for node, path, times, values, interpolation in channels:
            kind = {"translation": "VEC3", "scale": "VEC3", "rotation": "VEC4",
                    "weights": "SCALAR"}[path]
            anim["samplers"].append({"input": self.floats(times, "SCALAR", True),
                                     "output": self.floats(values, kind),
                                     "interpolation": interpolation})
            anim["channels"].append({"sampler": len(anim["samplers"]) - 1,
                                     "target": {"node": node, "path": path}})
        self.doc["animations"].append(anim)

    def write(self, path):
        self.doc["buffers"] = [{"byteLength": len(self.bin), "uri":
                                "data:application/octet-stream;base64," +
                                base64.b64encode(bytes(self.bin)).decode()}]
        with open(path, "w") as f:
            json.dump(self.doc, f, indent=1)


def quat(axis, degrees):
    s = math.sin(math.radians(degrees) / 2)
    return [axis[0] * s, axis[1] * s, axis[2] * s, math.cos(math.radians(degrees) / 2)]


def box(lo, hi):
    """An axis-aligned box, 12 triangles, counter-clockwise seen from outside."""
    p, idx = [], []
    for axis in range(3):
        for side in (0, 1):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            base = len(p) // 3
            for a, b in ((0, 0), (1, 0), (1, 1), (0, 1)):
                c = [0, 0, 0]
                c[axis] = (lo, hi)[side][axis]
                c[u] = (lo, hi)[a][u]
                c[v] = (lo, hi)[b][v]
                p += c
            quad = [0, 1, 2, 0, 2, 3] if side else [0, 2, 1, 0, 3, 2]
            idx += [base + q for q in quad]
    return p, idx


def arm(g, material):
    rings, half = 16, 0.18
    corners = [(-half, -half), (half, -half), (half, half), (-half, half)]
    p, joints, weights, idx = [], [], [], []
    for r in range(rings + 1):
        y = 2.0 * r / rings
        w1 = min(max((y - 0.8) / 0.4, 0.0), 1.0)  # blend across the elbow at y = 1
        for x, z in corners:
            p += [x, y, z]
            joints += [0, 1, 0, 0]
            weights += [1.0 - w1, w1, 0.0, 0.0]
    for r in range(rings):
        for k in range(4):
            a, b = r * 4 + k, r * 4 + (k + 1) % 4
            idx += [a, b, b + 4, a, b + 4, a + 4]
    top = rings * 4
    idx += [top, top + 2, top + 1, top, top + 3, top + 2]
    extra = {"JOINTS_0": g.accessor(joints, "B", U8, "VEC4"),
             "WEIGHTS_0": g.floats(weights, "VEC4")}
    mesh = g.mesh(p, idx, material, extra)
    ibm = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
           1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]
    upper = g.node(root=False, name="upper", translation=[0, 1, 0])
    lower = g.node(name="lower", translation=[-1.2, 0, 0], children=[upper])
    g.doc["skins"].append({"joints": [lower, upper], "skeleton": lower,
                           "inverseBindMatrices": g.floats(ibm, "MAT4")})
    g.node(name="arm", mesh=mesh, skin=0)
    return lower, upper


def main():
    g = Doc()
    white = g.material((0.8, 0.8, 0.8), roughness=0.9)
    orange = g.material((0.9, 0.35, 0.1), roughness=0.4)
    blue = g.material((0.15, 0.3, 0.8), roughness=0.3, metallic=0.6)
    green = g.material((0.2, 0.7, 0.3), roughness=0.7)
    s = 4.0
    g.node(name="floor", mesh=g.mesh([-s, 0, -s, -s, 0, s, s, 0, s, s, 0, -s],
                                     [0, 1, 2, 0, 2, 3], white))
    lower, upper = arm(g, orange)
    bp, bi = box((-0.3, 0.0, -0.3), (0.3, 0.6, 0.3))
    block = g.node(name="block", mesh=g.mesh(bp, bi, blue), translation=[0.6, 0, 1.0])
    # A tent: a ridge along z over a square; the target lifts the ridge by 0.8.
    tp = [-0.5, 0, -0.5, -0.5, 0, 0.5, 0, 0.2, 0.5, 0, 0.2, -0.5, 0.5, 0, 0.5, 0.5, 0, -0.5]
    ti = [0, 1, 2, 0, 2, 3, 3, 2, 4, 3, 4, 5]
    lift = [0, 0, 0, 0, 0, 0, 0, 0.8, 0, 0, 0.8, 0, 0, 0, 0, 0, 0, 0]
    tent = g.node(name="tent", mesh=g.mesh(tp, ti, green, targets=[lift], weights=[0.0]),
                  translation=[1.8, 0, -1.0])
    light = g.doc["extensions"]["KHR_lights_punctual"]["lights"]
    light.append({"type": "point", "color": [1.0, 0.85, 0.7], "intensity": 200.0,
                  "extras": {"radius": 0.35}})
    g.node(name="lamp", translation=[0.5, 4.0, 2.0], extensions={"KHR_lights_punctual":
                                                                {"light": 0}})
    g.doc["cameras"].append({"type": "perspective", "perspective": {
        "yfov": 0.75, "aspectRatio": 1.5, "znear": 0.05}})
    # Looking at (0.2, 0.9, 0) from (0.2, 2.3, 5.2): a pitch down about x.
    pitch = -math.degrees(math.atan2(1.4, 5.2))
    g.node(name="camera", camera=0, translation=[0.2, 2.3, 5.2], rotation=quat((1, 0, 0), pitch))
    t3 = [0.0, 1.0, 2.0]
    bend = quat((0, 0, 1), 0) + quat((0, 0, 1), 80) + quat((0, 0, 1), 0)
    # Cubic keys: in-tangent, value, out-tangent per key (quaternions; the result is normalised).
    turn = []
    for deg, slope in ((-30, 0.0), (30, 0.0)):
        q = quat((0, 1, 0), deg)
        turn += [0, 0, 0, 0] + q + [0, 0, 0, 0]
    slide = [0, 0, 0, 0.6, 0, 1.0, 1.5, 0, 0,   -1.5, 0, 0, 2.2, 0, 1.0, 0, 0, 0]
    spin = quat((0, 1, 0), 0) + quat((0, 1, 0), 90) + quat((0, 1, 0), 180)
    g.animate([
        (upper, "rotation", t3, bend, "LINEAR"),
        (lower, "rotation", [0.0, 2.0], turn, "CUBICSPLINE"),
        (block, "translation", [0.0, 2.0], slide, "CUBICSPLINE"),
        (block, "rotation", t3, spin, "LINEAR"),
        (tent, "weights", t3, [0.0, 1.0, 0.0], "LINEAR"),
    ])
    g.write(os.path.join(HERE, "animated_arm.gltf"))


if __name__ == "__main__":
    main()
