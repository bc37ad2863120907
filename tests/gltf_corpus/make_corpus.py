#!/usr/bin/env python3
"""Writes the hand-made glTF corpus beside this script: valid files (each loads, exercising one
feature) and invalid ones (each refused with one clear line), plus expected.tsv, which
tests/unit/test_gltf_corpus.cpp checks and the fuzzer uses as seeds. Each case is a few lines
here, so what a file breaks is readable without opening it. Run: python3 make_corpus.py"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
F32, U8, U16, U32, I8, I16 = 5126, 5121, 5123, 5125, 5120, 5122
# An 8x8 checker, light grey (240) and green (40, 200, 40) in 4x4 blocks, as lossless WebP
# (written once with libwebp 1.2.4's WebPEncodeLosslessRGBA).
WEBP = base64.b64decode("UklGRiQAAABXRUJQVlA4TBgAAAAvB8ABAA9wbPjjwB8Hfv7jAX+Aj+h/PAA=")
# An 8x8 two-colour checker as baseline JPEG (written once with stbi_write_jpg).
JPEG = base64.b64decode("/9j/4AAQSkZJRgABAQAAAQABAAD/2wCEAAMCAgMCAgMDAwMEAwMEBQgFBQQEBQoHBwYIDAoMDAsKCwsNDhIQDQ4RDgsLEBYQERMUFRUVDA8XGBYUGBIUFRQBAwQEBQQFCQUFCRQNCw0UFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFP/AABEIAAgACAMBIgACEQEDEQH/xAGiAAABBQEBAQEBAQAAAAAAAAAAAQIDBAUGBwgJCgsQAAIBAwMCBAMFBQQEAAABfQECAwAEEQUSITFBBhNRYQcicRQygZGhCCNCscEVUtHwJDNicoIJChYXGBkaJSYnKCkqNDU2Nzg5OkNERUZHSElKU1RVVldYWVpjZGVmZ2hpanN0dXZ3eHl6g4SFhoeIiYqSk5SVlpeYmZqio6Slpqeoqaqys7S1tre4ubrCw8TFxsfIycrS09TV1tfY2drh4uPk5ebn6Onq8fLz9PX29/j5+gEAAwEBAQEBAQEBAQAAAAAAAAECAwQFBgcICQoLEQACAQIEBAMEBwUEBAABAncAAQIDEQQFITEGEkFRB2FxEyIygQgUQpGhscEJIzNS8BVictEKFiQ04SXxFxgZGiYnKCkqNTY3ODk6Q0RFRkdISUpTVFVWV1hZWmNkZWZnaGlqc3R1dnd4eXqCg4SFhoeIiYqSk5SVlpeYmZqio6Slpqeoqaqys7S1tre4ubrCw8TFxsfIycrS09TV1tfY2dri4+Tl5ufo6ery8/T19vf4+fr/2gAMAwEAAhEDEQA/AI/+TLP+px/4SX/tx+zfZ/8Av7v3faPbG3vng/4bp/6kn/yrf/aKP26f+ZJ/7fv/AG3r5UrfhLhLJeOslocQ8Q0PbYutzc8+acL8k5Qj7sJRirRjFaRV7Xd22zkzDMMTlWJng8HPlpxtZWTtdJvVpvdvqf/Z")


def png(width, height, rgba):
    """A minimal RGBA8 PNG: one IDAT, filter 0 on every row."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(
            ">I", zlib.crc32(kind + data) & 0xffffffff)
    rows = b"".join(b"\0" + bytes(rgba[y * width * 4:(y + 1) * width * 4]) for y in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def checker_png(size=8, alpha_hole=False):
    px = []
    for y in range(size):
        for x in range(size):
            on = (x // (size // 2) + y // (size // 2)) % 2
            a = 0 if (alpha_hole and on) else 255
            px += [220, 40, 40, a] if on else [240, 240, 240, 255]
    return png(size, size, px)


def normal_png(size=8):
    """A bumpy tangent-space normal map: rows tilt alternately towards +x and -x."""
    px = []
    for y in range(size):
        for x in range(size):
            px += [200 if (x // 2) % 2 else 56, 128, 230, 255]
    return png(size, size, px)


class Gltf:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "scene": 0,
                    "nodes": [], "meshes": [], "accessors": [], "bufferViews": [],
                    "buffers": []}

    def view(self, data, stride=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        v = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            v["byteStride"] = stride
        self.bin += data
        self.doc["bufferViews"].append(v)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, data, ctype, count, kind, **extra):
        acc = {"componentType": ctype, "count": count, "type": kind}
        if data is not None:
            acc["bufferView"] = self.view(data)
        acc.update(extra)
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def floats(self, values, kind):
        n = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        return self.accessor(struct.pack("<%df" % len(values), *values), F32, len(values) // n,
                             kind)

    def indices(self, values, ctype=U16):
        fmt = {U8: "B", U16: "H", U32: "I"}[ctype]
        return self.accessor(struct.pack("<%d%s" % (len(values), fmt), *values), ctype,
                             len(values), "SCALAR")

    def mesh(self, attributes, indices=None, material=None, mode=None):
        prim = {"attributes": attributes}
        if indices is not None:
            prim["indices"] = indices
        if material is not None:
            prim["material"] = material
        if mode is not None:
            prim["mode"] = mode
        self.doc["meshes"].append({"primitives": [prim]})
        return len(self.doc["meshes"]) - 1

    def node(self, **members):
        self.doc["nodes"].append(members)
        return len(self.doc["nodes"]) - 1

    def image(self, data, mime="image/png", in_buffer=False):
        self.doc.setdefault("images", [])
        if in_buffer:
            self.doc["images"].append({"bufferView": self.view(data), "mimeType": mime})
        else:
            self.doc["images"].append(
                {"uri": "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())})
        return len(self.doc["images"]) - 1

    def texture(self, image, sampler=None):
        self.doc.setdefault("textures", [])
        t = {"source": image}
        if sampler is not None:
            t["sampler"] = sampler
        self.doc["textures"].append(t)
        return len(self.doc["textures"]) - 1

    def material(self, **members):
        self.doc.setdefault("materials", [])
        self.doc["materials"].append(members)
        return len(self.doc["materials"]) - 1

    def raw(self, data):
        """Bytes in buffer 0 without a bufferView of their own (compressed data); their offset."""
        while len(self.bin) % 4:
            self.bin.append(0)
        self.bin += data
        return len(self.bin) - len(data)

    def finish(self, uri=None):
        buf = {"byteLength": len(self.bin)}
        if uri is not False:
            buf["uri"] = uri or "data:application/octet-stream;base64," + base64.b64encode(
                bytes(self.bin)).decode()
        self.doc["buffers"] = ([buf] if self.bin or uri else []) + getattr(self, "more_buffers", [])
        return self.doc

    def glb(self):
        self.finish(uri=False)
        text = json.dumps(self.doc).encode()
        text += b" " * (-len(text) % 4)
        data = bytes(self.bin) + b"\0" * (-len(self.bin) % 4)
        out = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + 8 + len(data))
        out += struct.pack("<I", len(text)) + b"JSON" + text
        return out + struct.pack("<I", len(data)) + b"BIN\0" + data


QUAD = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]
QUAD_UV = [0, 1, 1, 1, 1, 0, 0, 0]
QUAD_INDICES = [0, 1, 2, 0, 2, 3]


def quad(g, material=None, uv=True, normals=False, extra=None):
    attrs = {"POSITION": g.floats(QUAD, "VEC3")}
    if uv:
        attrs["TEXCOORD_0"] = g.floats(QUAD_UV, "VEC2")
    if normals:
        attrs["NORMAL"] = g.floats([0, 0, 1] * 4, "VEC3")
    attrs.update(extra or {})
    g.node(mesh=g.mesh(attrs, g.indices(QUAD_INDICES), material))
    return g


def textured(image_bytes, mime="image/png", in_buffer=False, **material):
    g = Gltf()
    tex = g.texture(g.image(image_bytes, mime, in_buffer))
    m = g.material(pbrMetallicRoughness={"baseColorTexture": {"index": tex}}, **material)
    return quad(g, m)


CASES = []  # (file name, expectation, document bytes or Gltf, extra files)


def case(name, expect, g, files=None):
    CASES.append((name, expect, g, files or {}))


def tri():
    g = Gltf()
    g.node(mesh=g.mesh({"POSITION": g.floats([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3")}))
    return g


# Compressed data, written once from QUAD and QUAD_INDICES (and, quantized, the same quad as
# u16 positions and octahedral int8 normals) with draco::Encoder (libdraco 1.5.5, positions at
# 14 bits) and meshopt_encodeVertexBuffer / meshopt_encodeIndexBuffer / meshopt_encodeFilterOct
# (meshoptimizer 0.18).
DRACO_QUAD = base64.b64decode("RFJBQ08CAgEBAAAABAIAAgAAAR//AREB/wAAAQAJAwAAAgEBAQADAwEwARADACiCmA"
                              "AAAAAA/z8AAAAAAAAAAAAAAAAAAAAAgD8O")
MESHOPT_POSITIONS = base64.b64decode(
    "oAAAATMAAAD//wEzAAAAfn0AAAEMAAAA/wEMAAAAfgAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA==")
MESHOPT_TRIANGLES = base64.b64decode("4PAAAHaHVmd4qYZliWiYAWkAAA==")
MESHOPT_U16_POSITIONS = base64.b64decode(
    "oAESAAAAARIAAAABBAAAAAEEAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA")
MESHOPT_OCT_NORMALS = base64.b64decode(
    "oAEwAAAAawEPAAAAbGsAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA2AH8A")
DRACO = "KHR_draco_mesh_compression"


def draco_quad(indices=True, count=4, index_count=6, attribute_id=0, data=DRACO_QUAD):
    g = Gltf()
    g.doc["extensionsUsed"] = g.doc["extensionsRequired"] = [DRACO]
    view = g.view(data)
    prim = {"attributes": {"POSITION": g.accessor(None, F32, count, "VEC3")},
            "extensions": {DRACO: {"bufferView": view, "attributes": {"POSITION": attribute_id}}}}
    if indices:
        prim["indices"] = g.accessor(None, U16, index_count, "SCALAR")
    g.doc["meshes"].append({"primitives": [prim]})
    g.node(mesh=0)
    return g


class Meshopt:
    """A quad whose views decode into fallback buffer 1 (no uri) from data in buffer 0."""
    def __init__(self, name="EXT_meshopt_compression", fallback_bytes=1024):
        self.g, self.name, self.fallback = Gltf(), name, 0
        self.g.more_buffers = [{"byteLength": fallback_bytes,
                                "extensions": {name: {"fallback": True}}}]
        self.g.doc["extensionsUsed"] = self.g.doc["extensionsRequired"] = [name]

    def view(self, data, stride, count, mode, filter=None, view_stride=True):
        ext = {"buffer": 0, "byteOffset": self.g.raw(data), "byteLength": len(data),
               "byteStride": stride, "count": count, "mode": mode}
        if filter:
            ext["filter"] = filter
        v = {"buffer": 1, "byteOffset": self.fallback, "byteLength": stride * count,
             "extensions": {self.name: ext}}
        if mode == "ATTRIBUTES" and view_stride:
            v["byteStride"] = stride
        self.fallback += (stride * count + 3) // 4 * 4
        self.g.doc["bufferViews"].append(v)
        return len(self.g.doc["bufferViews"]) - 1

    def quad(self, positions=None, indices=None):
        """The float quad; `positions`/`indices` override a view's extension members."""
        pos = self.view(MESHOPT_POSITIONS, 12, 4, "ATTRIBUTES")
        idx = self.view(MESHOPT_TRIANGLES, 2, 6, "TRIANGLES")
        self.g.doc["bufferViews"][pos]["extensions"][self.name].update(positions or {})
        self.g.doc["bufferViews"][idx]["extensions"][self.name].update(indices or {})
        self.g.doc["accessors"] += [{"bufferView": pos, "componentType": F32, "count": 4,
                                     "type": "VEC3"},
                                    {"bufferView": idx, "componentType": U16, "count": 6,
                                     "type": "SCALAR"}]
        self.g.node(mesh=self.g.mesh({"POSITION": 0}, 1))
        return self.g


# --- Valid files: each loads; the expectation counts triangles and what the scene keeps. ---
case("valid/triangle.gltf", "loads 1 env=1", tri())
case("valid/triangle.glb", "loads 1", tri())
g = tri()
case("valid/external_buffer.gltf", "loads 1", g, {"valid/external_buffer.bin": "BIN"})
for ctype, name in ((U8, "u8"), (U16, "u16"), (U32, "u32")):
    g = Gltf()
    g.node(mesh=g.mesh({"POSITION": g.floats(QUAD, "VEC3")}, g.indices(QUAD_INDICES, ctype)))
    case("valid/indices_%s.gltf" % name, "loads 2 normals=0", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0], "VEC3")},
                   mode=5))
case("valid/triangle_strip.gltf", "loads 3", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 1, 0],
                                         "VEC3")}, g.indices([0, 1, 2, 3, 4]), mode=6))
case("valid/triangle_fan_indexed.gltf", "loads 3", g)
g = Gltf()
pos = g.floats(QUAD, "VEC3")
g.doc["accessors"][pos]["sparse"] = {
    "count": 1, "indices": {"bufferView": g.view(struct.pack("<H", 2)), "componentType": U16},
    "values": {"bufferView": g.view(struct.pack("<3f", 2, 2, 0))}}
g.node(mesh=g.mesh({"POSITION": pos}, g.indices(QUAD_INDICES)))
case("valid/sparse_positions.gltf", "loads 2", g)
g = Gltf()
pos = g.accessor(None, F32, 3, "VEC3", sparse={
    "count": 2, "indices": {"bufferView": g.view(struct.pack("<2B", 1, 2)), "componentType": U8},
    "values": {"bufferView": g.view(struct.pack("<6f", 1, 0, 0, 0, 1, 0))}})
g.node(mesh=g.mesh({"POSITION": pos}))
case("valid/sparse_without_bufferview.gltf", "loads 1", g)
# EXT_mesh_gpu_instancing: three instances (one with short-normalized rotation) of a triangle.
g = tri()
g.doc["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
g.doc["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": {
    "TRANSLATION": g.floats([0, 0, 0, 2, 0, 0, 4, 0, 0], "VEC3"),
    "ROTATION": g.accessor(struct.pack("<12h", 0, 0, 0, 32767, 0, 0, 32767, 0, 0, 0, 0, 32767),
                           I16, 3, "VEC4", normalized=True),
    "_ID": g.floats([0, 1, 2], "SCALAR")}}}
case("valid/gpu_instancing.gltf", "loads 3", g)
g = Gltf()
g.doc["extensionsUsed"] = g.doc["extensionsRequired"] = ["KHR_mesh_quantization"]
pos = g.accessor(struct.pack("<12h", 0, 0, 0, 0, 32767, 0, 0, 0, 0, 32767, 0, 0), I16, 3, "VEC3",
                 normalized=True)
g.doc["bufferViews"][-1]["byteStride"] = 8  # 16-bit VEC3 padded to 8 bytes, as exporters do
g.node(mesh=g.mesh({"POSITION": pos, "NORMAL": g.accessor(
    struct.pack("<12b", 0, 0, 127, 0, 0, 90, 90, 0, 0, 0, 127, 0), I8, 3, "VEC3",
    normalized=True)}), scale=[2, 2, 2])
g.doc["bufferViews"][-1]["byteStride"] = 4
case("valid/quantized_short_normalized.gltf", "loads 1 normals=1", g)
g = Gltf()
g.doc["extensionsUsed"] = ["KHR_mesh_quantization"]
g.node(mesh=g.mesh({"POSITION": g.accessor(bytes([0, 0, 0, 0, 10, 0, 0, 0, 0, 0, 10, 0]), U8, 3,
                                           "VEC3")}))
g.doc["bufferViews"][-1]["byteStride"] = 4
case("valid/quantized_ubyte.gltf", "loads 1", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3"),
                    "NORMAL": g.floats([0, 0, 1, 0.6, 0, 0.8, 0, 0.6, 0.8], "VEC3")}))
case("valid/smooth_normals.gltf", "loads 1 normals=1", g)
case("valid/flat_normals_need_no_buffer.gltf", "loads 2 normals=0", quad(Gltf(), normals=True))
g = Gltf()
red = g.material(pbrMetallicRoughness={"baseColorFactor": [1, 0, 0, 1], "metallicFactor": 0})
blue = g.material(pbrMetallicRoughness={"baseColorFactor": [0, 0, 1, 1]})
p0 = g.floats([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3")
p1 = g.floats([0, 0, 1, 1, 0, 1, 0, 1, 1], "VEC3")
g.doc["meshes"].append({"primitives": [{"attributes": {"POSITION": p0}, "material": red},
                                       {"attributes": {"POSITION": p1}, "material": blue},
                                       {"attributes": {"POSITION": p1}, "mode": 0},
                                       {"attributes": {"POSITION": p1}, "mode": 3}]})
g.node(mesh=0)
case("valid/primitives_points_lines_skipped.gltf", "loads 2", g)
g = tri()
g.doc["nodes"] = [{"children": [1], "matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1]},
                  {"children": [2], "rotation": [0, 0.7071068, 0, 0.7071068]},
                  {"mesh": 0, "scale": [-1, 1, 1], "translation": [0, 1, 0]}]
case("valid/hierarchy_matrix_trs_mirror.gltf", "loads 1", g)
g = tri()
del g.doc["scenes"], g.doc["scene"]
case("valid/no_scenes.gltf", "loads 1", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats([0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0],
                                         "VEC3")}))
case("valid/degenerate_dropped.gltf", "loads 1", g)
g = Gltf()
g.doc["nodes"] = [{}]
case("valid/empty_scene.gltf", "loads 0", g)
case("valid/texture_png.gltf", "loads 2 images=1 uv0=1", textured(checker_png()))
case("valid/texture_jpeg_in_bufferview.glb", "loads 2 images=1", textured(JPEG, "image/jpeg",
                                                                        True))
# COLOR_0 multiplies the base colour: float RGB on one mesh, normalized u8 RGBA on another,
# and a third mesh without it (opaque white).
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats(QUAD, "VEC3"),
                    "COLOR_0": g.floats([1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1], "VEC3")},
                   g.indices(QUAD_INDICES)))
g.node(mesh=g.mesh({"POSITION": g.floats([x + (2 if i % 3 == 0 else 0) for i, x in enumerate(QUAD)], "VEC3"),
                    "COLOR_0": g.accessor(bytes([255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0,
                                                 255, 255, 255, 255]), U8, 4, "VEC4",
                                          normalized=True)},
                   g.indices(QUAD_INDICES)))
g.node(mesh=g.mesh({"POSITION": g.floats([x + (4 if i % 3 == 0 else 0) for i, x in enumerate(QUAD)], "VEC3")},
                   g.indices(QUAD_INDICES)))
g.doc["scenes"][0]["nodes"] = [0, 1, 2]
case("valid/vertex_colors.gltf", "loads 6", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats(QUAD, "VEC3"), "COLOR_0": g.floats([1, 0, 0] * 3, "VEC3")},
                   g.indices(QUAD_INDICES)))
case("invalid/vertex_colors_wrong_count.gltf", "refused COLOR_0 has 3 elements but POSITION has 4", g)

# KHR_materials_unlit: the base colour as seen (an emitter of it that scatters nothing).
g = quad(Gltf(), 0)
g.material(pbrMetallicRoughness={"baseColorFactor": [0.2, 0.4, 0.6, 1]},
           extensions={"KHR_materials_unlit": {}})
g.doc["extensionsUsed"] = g.doc["extensionsRequired"] = ["KHR_materials_unlit"]
case("valid/unlit.gltf", "loads 2", g)
g = textured(checker_png(), extensions={"KHR_materials_unlit": {}})
g.doc["extensionsUsed"] = ["KHR_materials_unlit"]
case("valid/unlit_textured.gltf", "loads 2 images=1 uv0=1", g)
# EXT_texture_webp: its source wins over the core one (a PNG here, for viewers without WebP).
for name, in_buffer in (("valid/texture_webp.gltf", False), ("valid/texture_webp_in_bufferview.glb", True)):
    g = textured(checker_png(), in_buffer=in_buffer)
    g.doc["textures"][0]["extensions"] = {"EXT_texture_webp": {"source": g.image(WEBP, "image/webp", in_buffer)}}
    g.doc["extensionsUsed"] = ["EXT_texture_webp"]
    case(name, "loads 2 images=1 uv0=1", g)
g = textured(checker_png())
g.doc["textures"][0] = {"extensions": {"EXT_texture_webp": {"source": g.image(WEBP, "image/webp")}}}
g.doc["extensionsUsed"] = g.doc["extensionsRequired"] = ["EXT_texture_webp"]
case("valid/texture_webp_only.gltf", "loads 2 images=1 uv0=1", g)
g = textured(b"", "image/png")
g.doc["images"][0] = {"uri": "checker.png"}
case("valid/texture_external_file.gltf", "loads 2 images=1", g,
     {"valid/checker.png": checker_png()})
g = textured(checker_png())
g.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
    "KHR_texture_transform": {"offset": [0.5, 0], "rotation": 0.3, "scale": [2, 2]}}
g.doc["extensionsUsed"] = ["KHR_texture_transform"]
g.doc["samplers"] = [{"wrapS": 33648, "wrapT": 33071, "magFilter": 9728}]
g.doc["textures"][0]["sampler"] = 0
case("valid/texture_transform_sampler.gltf", "loads 2 images=1", g)
g = Gltf()
tex = g.texture(g.image(checker_png()))
m = g.material(pbrMetallicRoughness={"baseColorTexture": {"index": tex, "texCoord": 1}})
quad(g, m, extra={"TEXCOORD_1": g.floats([0, 0, 2, 0, 2, 2, 0, 2], "VEC2")})
case("valid/texcoord1.gltf", "loads 2 uv1=1", g)
g = Gltf()
m = g.material(normalTexture={"index": g.texture(g.image(normal_png())), "scale": 0.8})
case("valid/normal_map_generated_tangents.gltf", "loads 2 normals=1 tangents=1", quad(g, m))
g = Gltf()
m = g.material(normalTexture={"index": g.texture(g.image(normal_png()))})
quad(g, m, normals=True, extra={"TANGENT": g.floats([1, 0, 0, 1] * 4, "VEC4")})
case("valid/normal_map_with_tangents.gltf", "loads 2 normals=1 tangents=1", g)
# A smooth, UV-mapped cylinder with a normal map and no TANGENT (MikkTSpace frames are known in
# closed form: the tangent is dP/du), placed as it is and mirrored.
pos, nrm, uv, idx = [], [], [], []
for j in range(3):
    for i in range(17):
        a = 2 * math.pi * i / 16
        pos += [math.sin(a), j / 2, math.cos(a)]
        nrm += [math.sin(a), 0, math.cos(a)]
        uv += [i / 16, 1 - j / 2]
for j in range(2):
    for i in range(16):
        a, b, c, d = j * 17 + i, j * 17 + i + 1, (j + 1) * 17 + i + 1, (j + 1) * 17 + i
        idx += [a, b, c, a, c, d]
cylinder = (pos, nrm, uv, idx)
for name, tangents in (("normal_map_cylinder_mirrored.gltf", False),
                       ("normal_map_cylinder_with_tangents.gltf", True)):
    g = Gltf()
    m = g.material(normalTexture={"index": g.texture(g.image(normal_png()))})
    attrs = {"POSITION": g.floats(pos, "VEC3"), "NORMAL": g.floats(nrm, "VEC3"),
             "TEXCOORD_0": g.floats(uv, "VEC2")}
    if tangents:  # the MikkTSpace frames in closed form: dP/du, w = +1
        tan = []
        for k in range(0, len(nrm), 3):
            tan += [nrm[k + 2], 0, -nrm[k], 1]
        attrs["TANGENT"] = g.floats(tan, "VEC4")
    mesh = g.mesh(attrs, g.indices(idx), m)
    g.node(mesh=mesh)
    g.node(mesh=mesh, scale=[-1, 1, 1], translation=[3, 0, 0])
    g.doc["scenes"][0]["nodes"] = [0, 1]
    case("valid/" + name, "loads 128 normals=1 tangents=1", g)
g = Gltf()
tex = g.texture(g.image(checker_png(alpha_hole=True)))
mr = g.texture(g.image(checker_png()))
m = g.material(pbrMetallicRoughness={"baseColorTexture": {"index": tex},
                                     "metallicRoughnessTexture": {"index": mr}},
               emissiveTexture={"index": mr}, emissiveFactor=[1, 1, 1], alphaMode="MASK",
               alphaCutoff=0.4, doubleSided=True)
case("valid/alpha_mask_all_textures.gltf", "loads 2 images=2 env=0", quad(g, m))
case("valid/alpha_blend.gltf", "loads 2", textured(checker_png(alpha_hole=True),
                                                    alphaMode="BLEND"))
g = textured(b"")
g.doc["images"][0] = {"uri": "does_not_exist.png"}
case("valid/missing_image_warns.gltf", "loads 2 images=1", g)
case("valid/gif_image_warns.gltf", "loads 2 images=1",
     textured(b"GIF89a\x01\x00\x01\x00\x00\x00\x00;", "image/gif"))
case("valid/hdr_bytes_never_decoded.gltf", "loads 2 images=1",
     textured(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 1\n\x02\x02\x00\x01", "image/png"))
g = textured(checker_png())
g.doc["images"][0] = {"uri": "../outside.png"}
case("valid/image_outside_folder_warns.gltf", "loads 2 images=1", g)
g = tri()
g.doc["extensionsUsed"] = ["KHR_lights_punctual"]
g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
    {"type": "point", "color": [1, 0.5, 0.25], "intensity": 10},
    {"type": "spot", "intensity": 5, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
    {"type": "directional", "intensity": 2},
    {"type": "point", "intensity": 100, "extras": {"radius": 0.25}},
    {"type": "spot", "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.5}},
    {"type": "area"}]}}
for i in range(6):
    g.node(translation=[i, 2, 0], extensions={"KHR_lights_punctual": {"light": i}})
g.doc["scenes"][0]["nodes"] = list(range(7))
case("valid/lights_punctual_and_sphere.gltf", "loads 1 lights=4 env=0", g)
g = tri()
g.doc["cameras"] = [{"type": "perspective", "name": "front",
                     "perspective": {"yfov": 0.7, "znear": 0.1}},
                    {"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 0, "znear": 0,
                                                              "zfar": 1}},
                    {"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}},
                    {"type": "perspective", "perspective": {"yfov": 1.2, "aspectRatio": 2,
                                                            "znear": 0.1}}]
for i in range(4):
    g.node(camera=i, translation=[0, 0, 3 + i], name="cam%d" % i)
g.doc["scenes"][0]["nodes"] = list(range(5))
case("valid/cameras_some_invalid.gltf", "loads 1 cameras=2", g)
g = tri()
g.doc["cameras"] = [{"type": "orthographic", "orthographic": {"xmag": 2, "ymag": 1, "znear": 0.1,
                                                              "zfar": 100}}]
g.node(camera=0, translation=[0, 0, 3])
g.doc["scenes"][0]["nodes"] = [0, 1]
case("valid/camera_orthographic.gltf", "loads 1 cameras=1", g)
g = tri()
g.doc["extensionsUsed"] = ["EXT_unknown_thing", "KHR_materials_unknown_future"]
case("valid/unknown_extensions_warn.gltf", "loads 1", g)
g = Gltf()
m = g.material(pbrMetallicRoughness={"baseColorFactor": [0.9, 0.9, 0.9, 1],
                                     "metallicFactor": 0.2, "roughnessFactor": 0.3},
               emissiveFactor=[1, 1, 1],
               extensions={"KHR_materials_emissive_strength": {"emissiveStrength": 5},
                           "KHR_materials_ior": {"ior": 1.33},
                           "KHR_materials_transmission": {"transmissionFactor": 0.5},
                           "KHR_materials_specular": {"specularFactor": 0.5,
                                                      "specularColorFactor": [1, 0.9, 0.8]}})
case("valid/material_extensions.gltf", "loads 2 env=0", quad(g, m, uv=False))
g = Gltf()
tex = g.texture(g.image(checker_png()))
m = g.material(extensions={
    "KHR_materials_clearcoat": {"clearcoatFactor": 0.8, "clearcoatRoughnessFactor": 0.25,
                                "clearcoatTexture": {"index": tex}},
    "KHR_materials_sheen": {"sheenColorFactor": [0.5, 0.4, 0.3], "sheenRoughnessFactor": 0.6},
    "KHR_materials_transmission": {"transmissionFactor": 1},
    "KHR_materials_volume": {"thicknessFactor": 0.2, "attenuationColor": [0.5, 0.25, 1],
                             "attenuationDistance": 2},
    "KHR_materials_specular": {"specularFactor": 0.9, "specularTexture": {"index": tex},
                               "specularColorTexture": {"index": tex}}})
case("valid/material_layers.gltf", "loads 2 images=1", quad(g, m))
g = Gltf()
tex = g.texture(g.image(checker_png()))
m = g.material(extensions={
    "KHR_materials_iridescence": {
        "iridescenceFactor": 0.7, "iridescenceIor": 1.8, "iridescenceThicknessMinimum": 150,
        "iridescenceThicknessMaximum": 500, "iridescenceTexture": {"index": tex},
        "iridescenceThicknessTexture": {"index": tex, "extensions": {"KHR_texture_transform": {
            "scale": [2, 2]}}}}})
case("valid/material_iridescence.gltf", "loads 2 images=1", quad(g, m))
# Every texture of the layer and volume extensions, each with a KHR_texture_transform of its own
# (scale k on the k-th one, so a test can tell which reached which field), some on TEXCOORD_1.
g = Gltf()
tex = g.texture(g.image(checker_png()))


def info(k, **more):
    return dict({"index": tex, "extensions": {"KHR_texture_transform": {"scale": [k, 1]}}}, **more)


m = g.material(normalTexture={"index": tex}, extensions={
    "KHR_materials_clearcoat": {"clearcoatFactor": 0.8, "clearcoatRoughnessFactor": 0.25,
                                "clearcoatTexture": info(2),
                                "clearcoatRoughnessTexture": info(3, texCoord=1),
                                "clearcoatNormalTexture": info(4, scale=0.5)},
    "KHR_materials_sheen": {"sheenColorFactor": [0.5, 0.4, 0.3], "sheenRoughnessFactor": 0.6,
                            "sheenColorTexture": info(5), "sheenRoughnessTexture": info(6)},
    "KHR_materials_transmission": {"transmissionFactor": 1, "transmissionTexture": info(7)},
    "KHR_materials_volume": {"thicknessFactor": 0.2, "attenuationColor": [0.5, 0.25, 1],
                             "attenuationDistance": 2, "thicknessTexture": info(8)},
    "KHR_materials_specular": {"specularTexture": info(9), "specularColorTexture": info(10)}})
case("valid/material_layer_textures.gltf", "loads 2 images=1",
     quad(g, m, normals=True, extra={"TEXCOORD_1": g.floats(QUAD_UV, "VEC2")}))
# The coat's normal map alone still gets tangents (MikkTSpace: the file has none).
g = Gltf()
tex = g.texture(g.image(normal_png()))
m = g.material(extensions={"KHR_materials_clearcoat": {
    "clearcoatFactor": 1, "clearcoatNormalTexture": {"index": tex}}})
case("valid/clearcoat_normal_map_only.gltf", "loads 2 images=1", quad(g, m, normals=True))
# KHR_texture_basisu: the core source (PNG) is the fallback, read without a warning; the KTX2
# image (its magic and nothing more) is never decoded.
KTX2 = bytes([0xab, 0x4b, 0x54, 0x58, 0x20, 0x32, 0x30, 0xbb, 0x0d, 0x0a, 0x1a, 0x0a])
g = textured(checker_png())
g.doc["textures"][0]["extensions"] = {"KHR_texture_basisu": {"source": g.image(KTX2, "image/ktx2")}}
g.doc["extensionsUsed"] = ["KHR_texture_basisu"]
case("valid/texture_basisu_fallback.gltf", "loads 2 images=1", g)
# Without a fallback (as a file that does not require the extension should not be): the
# textures are dropped, with one warning for both.
g = Gltf()
ktx = g.image(KTX2, "image/ktx2")
g.doc["textures"] = [{"extensions": {"KHR_texture_basisu": {"source": ktx}}}] * 2
m = g.material(pbrMetallicRoughness={"baseColorTexture": {"index": 0}},
               emissiveTexture={"index": 1}, emissiveFactor=[1, 1, 1])
g.doc["extensionsUsed"] = ["KHR_texture_basisu"]
case("valid/texture_basisu_without_fallback.gltf", "loads 2 images=0", quad(g, m))
# KHR_materials_anisotropy: its texture (with KHR_texture_transform) and MikkTSpace tangents for
# the primitive, which has no TANGENT and no normal map.
g = Gltf()
tex = g.texture(g.image(checker_png()))
m = g.material(pbrMetallicRoughness={"metallicFactor": 1, "roughnessFactor": 0.4},
               extensions={"KHR_materials_anisotropy": {
                   "anisotropyStrength": 0.6, "anisotropyRotation": 0.5,
                   "anisotropyTexture": {"index": tex, "extensions": {"KHR_texture_transform": {
                       "scale": [3, 3]}}}}})
case("valid/material_anisotropy.gltf", "loads 2 images=1 normals=1 tangents=1", quad(g, m))
# KHR_materials_diffuse_transmission: factor and colour, the factor's texture (A, with
# KHR_texture_transform on TEXCOORD_0) and the colour's (sRGB RGB).
g = Gltf()
tex = g.texture(g.image(checker_png()))
m = g.material(extensions={"KHR_materials_diffuse_transmission": {
    "diffuseTransmissionFactor": 0.6, "diffuseTransmissionColorFactor": [1, 0.5, 0.25],
    "diffuseTransmissionTexture": {"index": tex, "extensions": {"KHR_texture_transform": {
        "offset": [0.5, 0], "scale": [2, 2]}}},
    "diffuseTransmissionColorTexture": {"index": tex}}})
g.doc["extensionsUsed"] = ["KHR_materials_diffuse_transmission", "KHR_texture_transform"]
case("valid/material_diffuse_transmission.gltf", "loads 2 images=1", quad(g, m))
# KHR_materials_dispersion: 20 / Abbe number on glass (transmission, ior).
g = Gltf()
m = g.material(extensions={"KHR_materials_dispersion": {"dispersion": 0.5},
                           "KHR_materials_transmission": {"transmissionFactor": 1},
                           "KHR_materials_ior": {"ior": 1.6}})
g.doc["extensionsUsed"] = ["KHR_materials_dispersion", "KHR_materials_transmission",
                           "KHR_materials_ior"]
case("valid/material_dispersion.gltf", "loads 2", quad(g, m, uv=False))
g = tri()
g.doc["nodes"][0]["children"] = [1]
g.doc["nodes"].append({"mesh": 0, "translation": [0, 0, 1]})
case("valid/instanced_mesh.gltf", "loads 2", g)

case("valid/draco_quad.glb", "loads 2", draco_quad())
case("valid/draco_quad.gltf", "loads 2", draco_quad())
case("valid/meshopt_quad.glb", "loads 2", Meshopt().quad())
case("valid/meshopt_quad_khr.gltf", "loads 2", Meshopt("KHR_meshopt_compression").quad())
m = Meshopt()
m.g.doc["extensionsUsed"] = m.g.doc["extensionsRequired"] = [m.name, "KHR_mesh_quantization"]
pos = m.view(MESHOPT_U16_POSITIONS, 8, 4, "ATTRIBUTES")
nrm = m.view(MESHOPT_OCT_NORMALS, 4, 4, "ATTRIBUTES", "OCTAHEDRAL")
idx = m.view(MESHOPT_TRIANGLES, 2, 6, "TRIANGLES")
m.g.doc["accessors"] = [{"bufferView": pos, "componentType": U16, "count": 4, "type": "VEC3",
                         "normalized": True},
                        {"bufferView": nrm, "componentType": I8, "count": 4, "type": "VEC3",
                         "normalized": True},
                        {"bufferView": idx, "componentType": U16, "count": 6, "type": "SCALAR"}]
m.g.node(mesh=m.g.mesh({"POSITION": 0, "NORMAL": 1}, 2), scale=[2, 2, 2])
case("valid/meshopt_quantized_octahedral.glb", "loads 2 normals=1", m.g)


# --- Invalid files: each refused with one line naming the problem. ---
def broken(name, substring, g):
    case("invalid/" + name, "refused " + substring, g)


case("invalid/not_json.gltf", "refused is not valid JSON (a syntax error at line 1, column 4)",
     b"{ this is not json")
case("invalid/empty_file.gltf", "refused ", b"")
case("invalid/bad_magic.glb", "refused magic", b"gLTf" + bytes(40))
case("invalid/truncated.glb", "refused ", tri().glb()[:40])
case("invalid/text_pretending_glb.glb", "refused magic", b'{"asset":{"version":"2.0"}}')
case("invalid/deep_nesting.gltf", "refused nested",
     b'{"asset":{"version":"2.0"},"extras":' + b"[" * 5000 + b"]" * 5000 + b"}")
g = tri()
g.doc["extensionsRequired"] = g.doc["extensionsUsed"] = ["EXT_lights_image_based"]
broken("required_unknown_extension.gltf", "EXT_lights_image_based", g)
g = tri()
g.doc["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": {
    "TRANSLATION": g.floats([0, 0, 0, 2, 0, 0], "VEC3"), "SCALE": g.floats([1, 1, 1], "VEC3")}}}
broken("gpu_instancing_counts_differ.gltf", "attributes differ in count", g)
g = tri()
g.doc["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": {
    "ROTATION": g.accessor(struct.pack("<4B", 0, 0, 0, 255), U8, 1, "VEC4", normalized=True)}}}
broken("gpu_instancing_unsigned_rotation.gltf", "must be VEC4 of FLOAT, or of normalized BYTE", g)
# tinygltf alone would refuse this one first, for its indices accessor without bufferView.
g = draco_quad()
g.doc["extensionsRequired"] = g.doc["extensionsUsed"] = ["KHR_texture_basisu"]
broken("required_unknown_before_tinygltf.gltf", "requires glTF extension KHR_texture_basisu", g)
g = tri()
g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 7
broken("accessor_index_out_of_range.gltf", "accessor 7", g)
g = tri()
g.doc["accessors"][0]["byteOffset"] = 4
broken("accessor_past_bufferview.gltf", "extend past the end of bufferView", g)
g = tri()
g.doc["bufferViews"][0]["byteOffset"] = 8
broken("bufferview_past_buffer.gltf", "bufferView 0", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats(QUAD, "VEC3")}, g.indices([0, 1, 9])))
broken("index_past_vertices.gltf", "is 9, but there are only 4 vertices", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats([0, 0, 0, 1, float("nan"), 0, 0, 1, 0], "VEC3")}))
broken("nan_position.gltf", "NaN or infinite", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats([0, 0, 0, float("inf"), 0, 0, 0, 1, 0], "VEC3")}))
broken("inf_position.gltf", "NaN or infinite", g)
g = tri()
g.doc["nodes"][0]["scale"] = [1e30, 1e30, 1e30]
g.doc["nodes"] = [{"children": [1], "scale": [1e30, 1e30, 1e30]}, g.doc["nodes"][0]]
broken("overflow_after_transform.gltf", "not finite", g)
g = tri()
g.doc["nodes"][0]["children"] = [1]
g.doc["nodes"].append({"children": [0]})
broken("node_cycle.gltf", "cycle", g)
g = tri()
g.doc["nodes"][0]["children"] = [0]
broken("node_own_child.gltf", "", g)
g = tri()
g.doc["nodes"] += [{"children": [0]}, {"children": [0]}]
g.doc["scenes"][0]["nodes"] = [1, 2]
broken("node_two_parents.gltf", "two parents", g)
g = tri()
g.doc["meshes"][0]["primitives"][0]["material"] = 3
broken("material_index_out_of_range.gltf", "material 3", g)
g = textured(checker_png())
g.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 5
broken("texture_index_out_of_range.gltf", "texture 5", g)
g = textured(checker_png())
g.doc["textures"][0]["source"] = 4
broken("image_index_out_of_range.gltf", "image 4", g)
g = textured(checker_png())
g.doc["textures"][0]["sampler"] = 2
broken("sampler_index_out_of_range.gltf", "sampler 2", g)
g = textured(JPEG, "image/jpeg", True)
g.doc["bufferViews"][-1]["byteLength"] = 100000
broken("image_bufferview_past_buffer.gltf", "extends past the end of buffer", g)
case("invalid/buffer_outside_folder.gltf", "refused '..' is not allowed",
     tri().finish(uri="../outside.bin"))
case("invalid/buffer_absolute_path.gltf", "refused only paths relative",
     tri().finish(uri="/etc/passwd"))
case("invalid/buffer_missing_file.gltf", "refused missing.bin", tri().finish(uri="missing.bin"))
g = tri()
g.doc["accessors"].append({"componentType": F32, "count": 2 ** 31, "type": "VEC3"})
g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 1
broken("huge_count_without_bufferview.gltf", "over the limit", g)
g = tri()
g.doc["bufferViews"][0]["byteStride"] = 2
broken("stride_smaller_than_element.gltf", "byteStride", g)
g = Gltf()
pos = g.floats(QUAD, "VEC3")
g.doc["accessors"][pos]["sparse"] = {
    "count": 2, "indices": {"bufferView": g.view(struct.pack("<2H", 2, 1)), "componentType": U16},
    "values": {"bufferView": g.view(struct.pack("<6f", 2, 2, 0, 3, 3, 0))}}
g.node(mesh=g.mesh({"POSITION": pos}, g.indices(QUAD_INDICES)))
broken("sparse_indices_not_increasing.gltf", "not increasing", g)
g = Gltf()
pos = g.floats(QUAD, "VEC3")
g.doc["accessors"][pos]["sparse"] = {
    "count": 1, "indices": {"bufferView": g.view(struct.pack("<H", 60)), "componentType": U16},
    "values": {"bufferView": g.view(struct.pack("<3f", 2, 2, 0))}}
g.node(mesh=g.mesh({"POSITION": pos}, g.indices(QUAD_INDICES)))
broken("sparse_index_out_of_range.gltf", "out of range", g)
g = tri()
g.doc["accessors"][0]["normalized"] = True
broken("normalized_float.gltf", "normalized", g)
g = tri()
g.doc["accessors"][0]["type"] = "VEC2"
broken("position_wrong_type.gltf", "wrong type", g)
g = tri()
g.doc["accessors"][0]["componentType"] = U32
broken("position_uint.gltf", "componentType 5125", g)
g = tri()
g.doc["meshes"][0]["primitives"][0]["mode"] = 9
broken("bad_primitive_mode.gltf", "mode 9", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats(QUAD, "VEC3")}, g.indices([0, 1, 2, 3])))
broken("not_whole_triangles.gltf", "whole triangles", g)
g = tri()
del g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"]
g.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 0
broken("no_position.gltf", "no POSITION", g)
g = Gltf()
g.node(mesh=g.mesh({"POSITION": g.floats([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3"),
                    "NORMAL": g.floats([0, 0, 1, 0, 0, 1], "VEC3")}))
broken("normal_count_mismatch.gltf", "NORMAL has 2 elements", g)
g = tri()
g.material(pbrMetallicRoughness={"baseColorFactor": [1.5, 0, 0, 1]})
g.doc["meshes"][0]["primitives"][0]["material"] = 0
broken("base_color_above_one.gltf", "baseColorFactor", g)
g = tri()
g.material(emissiveFactor=[-1, 0, 0])
g.doc["meshes"][0]["primitives"][0]["material"] = 0
broken("negative_emission.gltf", "emissiveFactor", g)
g = tri()
g.material(alphaMode="SOMETIMES")
g.doc["meshes"][0]["primitives"][0]["material"] = 0
broken("bad_alpha_mode.gltf", "alphaMode", g)
g = tri()
g.material(pbrMetallicRoughness={"roughnessFactor": 2})
g.doc["meshes"][0]["primitives"][0]["material"] = 0
broken("roughness_above_one.gltf", "roughnessFactor", g)
g = tri()
g.doc["nodes"][0]["extensions"] = {"KHR_lights_punctual": {"light": 3}}
g.doc["extensions"] = {"KHR_lights_punctual": {"lights": [{"type": "point"}]}}
broken("light_index_out_of_range.gltf", "KHR_lights_punctual light", g)
g = tri()
g.doc["nodes"][0]["camera"] = 2
broken("camera_index_out_of_range.gltf", "camera 2", g)
g = tri()
g.doc["scene"] = 4
broken("default_scene_out_of_range.gltf", "scene 4", g)
g = tri()
g.doc["nodes"][0]["rotation"] = [0, 0, 0, 0]
broken("zero_quaternion.gltf", "quaternion", g)
g = tri()
g.doc["nodes"][0]["matrix"] = [1, 0, 0]
broken("short_matrix.gltf", "16 numbers", g)
g = textured(checker_png())
g.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
    "KHR_texture_transform": {"scale": [1e39, 1]}}
broken("texture_transform_infinite.gltf", "KHR_texture_transform", g)
g = tri()
g.doc["scenes"][0]["nodes"] = [0, 0]
broken("node_listed_twice.gltf", "listed twice", g)

# Compressed data that lies, is cut short or breaks the extensions' rules.
broken("draco_truncated.glb", "does not decode", draco_quad(data=DRACO_QUAD[:40]))
broken("draco_garbage.gltf", "does not decode", draco_quad(data=b"DRACO" + bytes(range(60))))
broken("draco_more_vertices_than_accessor.gltf", "decodes to 4 vertices", draco_quad(count=3))
broken("draco_fewer_vertices_than_accessor.gltf", "decodes to 4 vertices", draco_quad(count=5))
broken("draco_index_count.gltf", "decodes to 6 indices", draco_quad(index_count=3))
broken("draco_unknown_attribute_id.gltf", "no attribute id 7", draco_quad(attribute_id=7))
broken("draco_no_indices.gltf", "needs an indices accessor", draco_quad(indices=False))
g = draco_quad()
g.doc["meshes"][0]["primitives"][0]["mode"] = 0
broken("draco_points_mode.gltf", "triangle lists", g)
g = draco_quad()
g.doc["accessors"][0]["type"] = "VEC2"
broken("draco_position_vec2.gltf", "components", g)
g = draco_quad()
g.doc["bufferViews"][0]["byteLength"] = 4096
broken("draco_bufferview_past_buffer.gltf", "extends past the end of buffer", g)
g = draco_quad()
g.doc["accessors"][0]["count"] = 2 ** 30
broken("draco_huge_count.gltf", "over the limit", g)
broken("meshopt_stride_mismatch.glb", "differs from the EXT_meshopt_compression byteStride",
       Meshopt().quad(positions={"byteStride": 16, "count": 3}))
broken("meshopt_wrong_count.glb", "is not the EXT_meshopt_compression byteStride x count",
       Meshopt().quad(positions={"count": 5}))
broken("meshopt_attribute_stride_6.glb", "byteStride 6 is invalid for mode ATTRIBUTES",
       Meshopt().quad(positions={"byteStride": 6}))
# Refused before 7 KB are allocated for it: no valid stream of 600 elements is that short.
m = Meshopt(fallback_bytes=8192)
g = m.quad()
g.doc["bufferViews"][0]["byteLength"] = 12 * 600
g.doc["bufferViews"][0]["extensions"][m.name]["count"] = 600
broken("meshopt_data_for_fewer_elements.glb", "67 bytes cannot hold 600 elements", g)
broken("meshopt_octahedral_on_float_vec3.glb", "filter OCTAHEDRAL does not apply",
       Meshopt().quad(positions={"filter": "OCTAHEDRAL"}))
broken("meshopt_filter_on_triangles.glb", "applies to ATTRIBUTES only",
       Meshopt().quad(indices={"filter": "EXPONENTIAL"}))
broken("meshopt_triangles_stride_3.glb", "byteStride 3 is invalid for mode TRIANGLES",
       Meshopt().quad(indices={"byteStride": 3}))
broken("meshopt_lying_bytelength.glb", "extend past the end of buffer 0",
       Meshopt().quad(positions={"byteLength": 100000}))
broken("meshopt_truncated.glb", "are not valid ATTRIBUTES data",
       Meshopt().quad(positions={"byteLength": 30}))
broken("meshopt_truncated_indices.gltf", "are not valid TRIANGLES data",
       Meshopt().quad(indices={"byteLength": 9}))
broken("meshopt_huge_count.glb", "over the limit",
       Meshopt().quad(positions={"count": 2 ** 36}))
broken("meshopt_unknown_mode.glb", "mode 'QUADS'", Meshopt().quad(indices={"mode": "QUADS"}))
broken("meshopt_color_filter.gltf", "filter 'COLOR' is not supported",
       Meshopt("KHR_meshopt_compression").quad(positions={"filter": "COLOR"}))
broken("meshopt_negative_offset.glb", "byteOffset must be an integer >= 0",
       Meshopt().quad(positions={"byteOffset": -4}))
broken("meshopt_fallback_too_small.glb", "extends past the end of its fallback buffer 1",
       Meshopt(fallback_bytes=20).quad())
broken("meshopt_reads_fallback.glb", "a fallback buffer without data",
       Meshopt().quad(positions={"buffer": 1}))
g = Meshopt().quad()
g.doc["bufferViews"].append({"buffer": 1, "byteOffset": 0, "byteLength": 12})
g.doc["accessors"].append({"bufferView": 2, "componentType": F32, "count": 1, "type": "VEC3"})
broken("meshopt_plain_view_on_fallback.glb", "but is not compressed", g)
g = Meshopt().quad()
g.bin[g.doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteOffset"]] = 0xa1
broken("meshopt_vertex_codec_v1.glb", "version 1 of meshopt's vertex codec", g)


g = Gltf()
m = g.material(extensions={"KHR_materials_clearcoat": {"clearcoatFactor": 1.5}})
broken("clearcoat_above_one.gltf", "clearcoatFactor", quad(g, m, uv=False))
for name, ext, key in [("clearcoat_texture_index.gltf", "KHR_materials_clearcoat", "clearcoatTexture"),
                       ("sheen_texture_index.gltf", "KHR_materials_sheen", "sheenColorTexture"),
                       ("thickness_texture_index.gltf", "KHR_materials_volume", "thicknessTexture")]:
    g = Gltf()
    g.texture(g.image(checker_png()))
    m = g.material(extensions={ext: {key: {"index": 3}}})
    broken(name, key + " refers to texture 3", quad(g, m))
g = Gltf()
tex = g.texture(g.image(checker_png()))
m = g.material(extensions={"KHR_materials_clearcoat": {"clearcoatFactor": 1,
    "clearcoatNormalTexture": {"index": tex, "scale": "strong"}}})
broken("clearcoat_normal_scale_not_a_number.gltf", "clearcoatNormalTexture.scale", quad(g, m))
g = Gltf()
m = g.material(extensions={"KHR_materials_volume": {"thicknessFactor": 1,
                                                    "attenuationDistance": 0}})
broken("attenuation_distance_zero.gltf", "attenuationDistance", quad(g, m, uv=False))
g = Gltf()
m = g.material(extensions={"KHR_materials_sheen": {"sheenColorFactor": [0.5, -1, 0.5]}})
broken("sheen_color_negative.gltf", "sheenColorFactor", quad(g, m, uv=False))
for name, key, film in [
        ("iridescence_above_one.gltf", "iridescenceFactor", {"iridescenceFactor": 1.5}),
        ("iridescence_ior_below_one.gltf", "iridescenceIor", {"iridescenceFactor": 1,
                                                              "iridescenceIor": 0.5}),
        ("iridescence_thickness_negative.gltf", "iridescenceThicknessMinimum",
         {"iridescenceFactor": 1, "iridescenceThicknessMinimum": -10})]:
    g = Gltf()
    m = g.material(extensions={"KHR_materials_iridescence": film})
    broken(name, key, quad(g, m, uv=False))
for name, key, anisotropy in [
        ("anisotropy_strength_above_one.gltf", "anisotropyStrength", {"anisotropyStrength": 1.5}),
        ("anisotropy_strength_negative.gltf", "anisotropyStrength", {"anisotropyStrength": -0.2}),
        ("anisotropy_rotation_not_a_number.gltf", "anisotropyRotation",
         {"anisotropyStrength": 0.5, "anisotropyRotation": "east"})]:
    g = Gltf()
    m = g.material(extensions={"KHR_materials_anisotropy": anisotropy})
    broken(name, key, quad(g, m, uv=False))
for name, key, dt in [
        ("diffuse_transmission_above_one.gltf", "diffuseTransmissionFactor",
         {"diffuseTransmissionFactor": 1.5}),
        ("diffuse_transmission_color_above_one.gltf", "diffuseTransmissionColorFactor",
         {"diffuseTransmissionFactor": 0.5, "diffuseTransmissionColorFactor": [1, 2, 1]}),
        ("diffuse_transmission_texture_without_index.gltf", "diffuseTransmissionTexture",
         {"diffuseTransmissionFactor": 0.5, "diffuseTransmissionTexture": {"texCoord": 0}})]:
    g = Gltf()
    m = g.material(extensions={"KHR_materials_diffuse_transmission": dt})
    broken(name, key, quad(g, m, uv=False))
for name, value in [("dispersion_negative.gltf", -0.5), ("dispersion_not_a_number.gltf", "x")]:
    g = Gltf()
    m = g.material(extensions={"KHR_materials_dispersion": {"dispersion": value}})
    broken(name, "dispersion", quad(g, m, uv=False))


# --- Time: animations, skins and morph targets (issue 35). ---
def animated(interpolation="LINEAR", output_count=None, sampler=0, path="translation",
             channel_sampler=True):
    """A triangle on a node that an animation moves over a second."""
    g = tri()
    times = g.floats([0, 1], "SCALAR")
    values = [0, 0, 0, 1, 0, 0] * (3 if interpolation == "CUBICSPLINE" else 1)
    if output_count is not None:
        values = values[:output_count * 3]
    out = g.floats(values, "VEC3")
    channel = {"target": {"node": 0, "path": path}}
    if channel_sampler:
        channel["sampler"] = sampler
    g.doc["animations"] = [{"channels": [channel], "samplers": [
        {"input": times, "output": out, "interpolation": interpolation}]}]
    return g


def skinned(joint=1):
    """A triangle on two joints (no inverse bind matrices: identity), its third corner on the
    second; a morph target lifting it, its weight animated (STEP)."""
    g = Gltf()
    pos = g.floats([0, 0, 0, 1, 0, 0, 0, 1, 0], "VEC3")
    joints = g.accessor(struct.pack("<12B", 0, 0, 0, 0, 0, 0, 0, 0, joint, 0, 0, 0), U8, 3,
                        "VEC4")
    weights = g.floats([1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0], "VEC4")
    lift = g.floats([0, 0, 1, 0, 0, 1, 0, 0, 1], "VEC3")
    g.doc["meshes"].append({"primitives": [{"attributes": {"POSITION": pos, "JOINTS_0": joints,
                                                           "WEIGHTS_0": weights},
                                            "targets": [{"POSITION": lift}]}],
                            "weights": [0.5]})
    g.doc["scenes"] = [{"nodes": [0, 2]}]
    g.node(children=[1])
    g.node(translation=[0, 1, 0])
    g.node(mesh=0, skin=0)
    g.doc["skins"] = [{"joints": [0, 1]}]
    times = g.floats([0, 1], "SCALAR")
    g.doc["animations"] = [{"channels": [
        {"sampler": 0, "target": {"node": 1, "path": "rotation"}},
        {"sampler": 1, "target": {"node": 2, "path": "weights"}}], "samplers": [
        {"input": times, "output": g.floats([0, 0, 0, 1, 0, 0, 0.7071068, 0.7071068], "VEC4")},
        {"input": times, "output": g.floats([0, 1], "SCALAR"), "interpolation": "STEP"}]}]
    return g


case("valid/animation_translation.gltf", "loads 1", animated())
case("valid/animation_cubic_spline.gltf", "loads 1", animated("CUBICSPLINE"))
case("valid/skin_and_morph_animated.gltf", "loads 1", skinned())
broken("animation_sampler_missing.gltf", "channel 0: sampler 3 does not exist",
       animated(sampler=3))
broken("animation_output_count.gltf", "output has 1 elements, but 2 keys of LINEAR",
       animated(output_count=1))
broken("animation_cubic_output_count.gltf", "keys of CUBICSPLINE need 6",
       animated("CUBICSPLINE", output_count=2))
broken("animation_bad_interpolation.gltf", "interpolation 'SMOOTH' is not LINEAR",
       animated("SMOOTH"))
broken("animation_bad_path.gltf", "target path 'color'", animated(path="color"))
broken("animation_weights_without_targets.gltf", "which has no mesh with morph targets",
       animated(path="weights"))
broken("animation_channel_without_sampler.gltf", "the required member 'sampler' is missing",
       animated(channel_sampler=False))
broken("skin_joint_out_of_range.gltf", "names joint 5 at vertex 2, but the skin has 2",
       skinned(joint=5))

# --- Refusals that once came in tinygltf's or its JSON parser's words. ---
# A buffer without uri is valid glTF (extensions may fill it): unused, it costs nothing; a
# primitive that reads it is skipped with a warning.
g = tri()
g.more_buffers = [{"byteLength": 16}]
case("valid/unused_buffer_without_uri.gltf", "loads 1", g)
g = tri()
g.more_buffers = [{"byteLength": 36}]
doc = g.finish()
doc["bufferViews"][0]["buffer"] = 1
case("valid/primitive_reads_buffer_without_uri.gltf", "loads 0", doc)
g = tri()
g.doc["nodes"][0]["translation"] = [0, 0, "HUGE"]
case("invalid/number_overflow.gltf", "refused the number 1e309, which no double can hold",
     json.dumps(g.finish()).replace('"HUGE"', "1e309").encode())
g = tri()
del g.doc["accessors"][0]["componentType"]
broken("accessor_without_component_type.gltf", "the required member 'componentType' is missing",
       g)
g = tri()
g.doc["cameras"] = [{"type": "perspective"}]
broken("camera_without_perspective.gltf", "a perspective camera has no 'perspective' object", g)
g = tri()
g.doc["accessors"][0]["type"] = "VEC7"
broken("accessor_type_unknown.gltf", "type 'VEC7' is not SCALAR", g)

# Parser-only problems of this file's own making (their refusals checked for wording too).
broken("json_syntax_error.gltf", "is not valid JSON (a syntax error at line 1", b'{"asset": {"version": "2.0"}, ]')
g = tri()
doc = g.finish()
doc["buffers"][0]["uri"] = "data:application/octet-stream;;base64,AA=="
broken("bad_data_uri.gltf", "must be 'data:<media type>;base64,<data>'", doc)
g = tri()
doc = g.finish()
doc["buffers"][0]["uri"] = "data:application/octet-stream;;base64," + "A" * 400000
broken("huge_bad_data_uri.gltf", "must be 'data:<media type>;base64,<data>'", doc)
broken("glb_too_short.glb", "shorter than its headers", b"glTF" + struct.pack("<II", 2, 16) + bytes(4))
broken("skin_without_joints.gltf", "without naming the rule", {"asset": {"version": "2.0"}, "skins": [{}]})


def main():
    lines = []
    for name, expect, doc, files in CASES:
        path = os.path.join(HERE, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        if isinstance(doc, Gltf):
            if name.endswith(".glb"):
                data = doc.glb()
            elif files and "BIN" in files.values():
                bin_name = [f for f, v in files.items() if v == "BIN"][0]
                data = json.dumps(doc.finish(uri=os.path.basename(bin_name))).encode()
                files = {bin_name: bytes(doc.bin)}
            else:
                data = json.dumps(doc.finish()).encode()
        elif isinstance(doc, dict):
            data = json.dumps(doc).encode()
        else:
            data = doc
        with open(path, "wb") as out:
            out.write(data)
        for extra, content in files.items():
            with open(os.path.join(HERE, extra), "wb") as out:
                out.write(content)
        lines.append(name + "\t" + expect)
    with open(os.path.join(HERE, "expected.tsv"), "w") as out:
        out.write("# file\texpectation (loads TRIANGLES [key=value...] | refused SUBSTRING)\n")
        out.write("\n".join(lines) + "\n")
    print("wrote %d files" % len(CASES))


if __name__ == "__main__":
    main()
