#!/usr/bin/env python3
"""Writes a large glTF scene (default ~350k triangles) for load, BVH and render measurements:
a rolling height-field terrain (one indexed mesh with normals) and a grid of UV spheres (one
mesh instanced by many nodes), lit by a warm emissive panel and a sky. It is generated at test
or run time instead of being committed: the .glb is about 3 MB.

    python3 scenes/make_big_scene.py out/big_scene.glb [--terrain N] [--spheres K]
"""
import argparse
import json
import math
import struct


def terrain(n, size=40.0):
    """(n+1)^2 vertices of a smooth height field over [-size/2, size/2]^2, 2n^2 triangles."""
    def height(x, z):
        return 0.8 * math.sin(0.35 * x) * math.cos(0.29 * z) + 0.3 * math.sin(1.1 * x + 0.7 * z)
    pos, nrm, idx = [], [], []
    step = size / n
    for j in range(n + 1):
        for i in range(n + 1):
            x, z = -size / 2 + i * step, -size / 2 + j * step
            y = height(x, z)
            dx = (height(x + 1e-3, z) - height(x - 1e-3, z)) / 2e-3
            dz = (height(x, z + 1e-3) - height(x, z - 1e-3)) / 2e-3
            length = math.sqrt(dx * dx + 1 + dz * dz)
            pos += [x, y, z]
            nrm += [-dx / length, 1 / length, -dz / length]
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            b, c, d = a + 1, a + n + 1, a + n + 2
            idx += [a, c, b, b, c, d]  # counter-clockwise seen from above (+y)
    return pos, nrm, idx


def sphere(segments, rings):
    pos, nrm, idx = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)]
            pos += n
            nrm += n
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b, c, d = a + 1, a + segments + 1, a + segments + 2
            idx += [a, b, c, b, d, c]  # outward-facing
    return pos, nrm, idx


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("output")
    parser.add_argument("--terrain", type=int, default=256, help="terrain quads per side")
    parser.add_argument("--spheres", type=int, default=10, help="spheres per side of the grid")
    args = parser.parse_args()

    blob = bytearray()
    views, accessors = [], []

    def add(values, fmt, kind, target, minmax=False):
        while len(blob) % 4:
            blob.append(0)
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": len(data),
                      "target": target})
        blob.extend(data)
        n = {"VEC3": 3, "SCALAR": 1}[kind]
        acc = {"bufferView": len(views) - 1, "componentType": 5126 if fmt == "f" else 5125,
               "count": len(values) // n, "type": kind}
        if minmax:
            acc["min"] = [min(values[i::3]) for i in range(3)]
            acc["max"] = [max(values[i::3]) for i in range(3)]
        accessors.append(acc)
        return len(accessors) - 1

    def mesh(geometry, material):
        pos, nrm, idx = geometry
        return {"primitives": [{"attributes": {"POSITION": add(pos, "f", "VEC3", 34962, True),
                                               "NORMAL": add(nrm, "f", "VEC3", 34962)},
                                "indices": add(idx, "I", "SCALAR", 34963),
                                "material": material}]}

    panel = ([-4, 12, -4, 4, 12, -4, 4, 12, 4, -4, 12, 4], [0, -1, 0] * 4, [0, 2, 1, 0, 3, 2])
    meshes = [mesh(terrain(args.terrain), 0), mesh(sphere(48, 24), 1), mesh(panel, 2)]
    nodes = [{"mesh": 0, "name": "terrain"}, {"mesh": 2, "name": "light panel"}]
    k = args.spheres
    for j in range(k):
        for i in range(k):
            x, z = (i - (k - 1) / 2) * 3.2, (j - (k - 1) / 2) * 3.2
            r = 0.5 + 0.4 * ((i * 7 + j * 3) % 5) / 4
            nodes.append({"mesh": 1, "translation": [x, 2.2 + r, z], "scale": [r, r, r]})
    nodes.append({"camera": 0, "name": "overview", "translation": [0, 14, 26],
                  "rotation": [-0.2588190, 0, 0, 0.9659258]})
    doc = {
        "asset": {"version": "2.0", "generator": "wavefront scenes/make_big_scene.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}], "nodes": nodes,
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1}}],
        "meshes": meshes,
        "materials": [
            {"name": "ground", "pbrMetallicRoughness": {"baseColorFactor": [0.45, 0.5, 0.35, 1],
                                                        "metallicFactor": 0, "roughnessFactor": 0.9}},
            {"name": "spheres", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.3, 0.2, 1],
                                                         "metallicFactor": 0, "roughnessFactor": 0.4}},
            {"name": "panel", "emissiveFactor": [1, 0.9, 0.75], "doubleSided": True,
             "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 6}}}],
        "accessors": accessors, "bufferViews": views,
        "buffers": [{"byteLength": len(blob)}],
    }
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    blob.extend(b"\0" * (-len(blob) % 4))
    with open(args.output, "wb") as out:
        out.write(b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + 8 + len(blob)))
        out.write(struct.pack("<I", len(text)) + b"JSON" + text)
        out.write(struct.pack("<I", len(blob)) + b"BIN\0" + bytes(blob))
    triangles = 2 * args.terrain ** 2 + k * k * 2 * 48 * (24 - 1) + 2  # poles: 1 per quad
    print("wrote %s: %d triangles" % (args.output, triangles))


if __name__ == "__main__":
    main()
