"""Writes a KHR_materials_variants test file: one emissive triangle, white by its own material,
red in variant 0 "red", blue in variant 1 "blue". Usage: variants_gltf.py OUT.gltf"""
import base64
import json
import struct
import sys

data = base64.b64encode(struct.pack("9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)).decode()


def material(colour):
    return {"pbrMetallicRoughness": {"baseColorFactor": colour + [1]}, "emissiveFactor": colour}


json.dump({
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "materials": [material([1, 1, 1]), material([1, 0, 0]), material([0, 0, 1])],
    "extensionsUsed": ["KHR_materials_variants"],
    "extensions": {"KHR_materials_variants": {"variants": [{"name": "red"}, {"name": "blue"}]}},
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0,
        "extensions": {"KHR_materials_variants": {"mappings": [
            {"material": 1, "variants": [0]}, {"material": 2, "variants": [1]}]}}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64," + data}],
}, open(sys.argv[1], "w"))
