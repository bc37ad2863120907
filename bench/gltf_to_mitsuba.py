"""Reads the glTF files the project's generators write (scenes/make_cornell_box.py,
bench/make_scaling_scene.py, the peer's mirror + glass box) into a Mitsuba 3 scene dict, so
that bench/mitsuba_peer.py renders the very triangles Wavefront renders.

Only what those generators use is read, and anything else is refused rather than guessed:
one scene of top-level nodes (translation, rotation, scale or matrix), triangle primitives
with float positions and 16- or 32-bit indices in tightly packed views, one perspective camera,
and four kinds of material, each mapped to the Mitsuba BSDF that is the same function:
  - Lambert (metallic 0, roughness 1, KHR_materials_specular 0)  -> twosided diffuse
  - emissive (emissiveFactor x KHR_materials_emissive_strength)   -> area emitter on its BSDF
  - perfect mirror (metallic 1, roughness 0, base colour 1)       -> twosided conductor "none"
  - smooth glass (KHR_materials_transmission 1, roughness 0, base colour 1) -> dielectric
Triangles are merged per material into world-space OBJ files (face normals, as Wavefront
shades meshes without normals), keeping the glTF's winding.
"""
import base64
import math
import os

import numpy as np

COMPONENTS = {5126: np.float32, 5123: np.uint16, 5125: np.uint32}
WIDTH = {"SCALAR": 1, "VEC3": 3}


def _buffers(doc, folder):
    out = []
    for buffer in doc["buffers"]:
        uri = buffer["uri"]
        if uri.startswith("data:"):
            out.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            with open(os.path.join(folder, uri), "rb") as f:
                out.append(f.read())
    return out


def _accessor(doc, buffers, index):
    acc = doc["accessors"][index]
    view = doc["bufferViews"][acc["bufferView"]]
    if "byteStride" in view:
        raise ValueError("interleaved buffer views are not read")
    dtype = COMPONENTS[acc["componentType"]]
    width = WIDTH[acc["type"]]
    start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
    data = np.frombuffer(buffers[view["buffer"]], dtype=dtype, count=acc["count"] * width,
                         offset=start)
    return data.reshape(-1, width) if width > 1 else data


def _node_matrix(node):
    if "matrix" in node:
        return np.array(node["matrix"], dtype=np.float64).reshape(4, 4).T  # column-major
    x, y, z, w = node.get("rotation", [0.0, 0.0, 0.0, 1.0])
    rotation = np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])
    m = np.eye(4)
    m[:3, :3] = rotation @ np.diag(node.get("scale", [1.0, 1.0, 1.0]))
    m[:3, 3] = node.get("translation", [0.0, 0.0, 0.0])
    return m


def _bsdf(material):
    pbr = material.get("pbrMetallicRoughness", {})
    color = pbr.get("baseColorFactor", [1.0, 1.0, 1.0, 1.0])[:3]
    metallic = pbr.get("metallicFactor", 1.0)
    roughness = pbr.get("roughnessFactor", 1.0)
    ext = material.get("extensions", {})
    transmission = ext.get("KHR_materials_transmission", {}).get("transmissionFactor", 0.0)
    specular = ext.get("KHR_materials_specular", {}).get("specularFactor", 1.0)
    white = all(abs(c - 1.0) < 1e-6 for c in color)
    if transmission == 1.0 and roughness == 0.0 and metallic == 0.0 and white:
        ior = ext.get("KHR_materials_ior", {}).get("ior", 1.5)
        return {"type": "dielectric", "int_ior": ior, "ext_ior": 1.0}
    if metallic == 1.0 and roughness == 0.0 and white:
        return {"type": "twosided", "bsdf": {"type": "conductor", "material": "none"}}
    if metallic == 0.0 and roughness == 1.0 and specular == 0.0 and transmission == 0.0:
        return {"type": "twosided", "bsdf": {
            "type": "diffuse", "reflectance": {"type": "rgb", "value": list(color)}}}
    raise ValueError("material %r has no Mitsuba equivalent here" % material.get("name"))


def _write_obj(path, points):
    """points: (3n, 3) world-space corners, three per triangle."""
    n = len(points) // 3
    faces = np.arange(1, 3 * n + 1).reshape(n, 3)
    with open(path, "w") as f:
        np.savetxt(f, points, fmt="v %.9g %.9g %.9g")
        np.savetxt(f, faces, fmt="f %d %d %d")


def scene_dict(mi, gltf_path, folder, width, height, spp, max_depth, rr_depth,
               integrator="path"):
    import json
    with open(gltf_path) as f:
        doc = json.load(f)
    buffers = _buffers(doc, os.path.dirname(gltf_path))
    corners = {}  # material index -> list of (3n, 3) arrays
    camera = None
    spheres = []  # (centre, radius, radiance): KHR_lights_punctual lights with extras.radius
    lights = doc.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    for index in doc["scenes"][doc.get("scene", 0)]["nodes"]:
        node = doc["nodes"][index]
        if node.get("children"):
            raise ValueError("node hierarchies are not read")
        m = _node_matrix(node)
        if "camera" in node:
            camera = (doc["cameras"][node["camera"]], m)
        light = node.get("extensions", {}).get("KHR_lights_punctual", {}).get("light")
        if light is not None:
            radius = lights[light].get("extras", {}).get("radius", 0.0)
            if lights[light].get("type") != "point" or radius <= 0.0:
                raise ValueError("only sphere lights (point lights with extras.radius) are read")
            # Wavefront's sphere light: radiance intensity / (pi R^2) over its surface.
            value = [c * lights[light].get("intensity", 1.0) / (math.pi * radius * radius)
                     for c in lights[light].get("color", [1.0, 1.0, 1.0])]
            spheres.append((m[:3, 3].tolist(), radius, value))
        if "mesh" not in node:
            continue
        for prim in doc["meshes"][node["mesh"]]["primitives"]:
            if prim.get("mode", 4) != 4:
                raise ValueError("only triangle lists are read")
            pos = _accessor(doc, buffers, prim["attributes"]["POSITION"]).astype(np.float64)
            idx = _accessor(doc, buffers, prim["indices"])
            world = pos @ m[:3, :3].T + m[:3, 3]
            corners.setdefault(prim["material"], []).append(world[idx])
    if camera is None:
        raise ValueError("the scene has no camera")
    cam, m = camera
    origin = m[:3, 3]
    forward = m[:3, :3] @ np.array([0.0, 0.0, -1.0])
    up = m[:3, :3] @ np.array([0.0, 1.0, 0.0])
    scene = {
        "type": "scene",
        # path, or ptracer (Mitsuba's light tracer, which also sees emitters directly).
        "integrator": {"type": integrator, "max_depth": max_depth, "rr_depth": rr_depth},
        "sensor": {
            "type": "perspective", "fov": math.degrees(cam["perspective"]["yfov"]),
            "fov_axis": "y",
            "to_world": mi.ScalarTransform4f().look_at(
                origin=origin.tolist(), target=(origin + forward).tolist(), up=up.tolist()),
            "sampler": {"type": "independent", "sample_count": spp},
            "film": {"type": "hdrfilm", "width": width, "height": height,
                     "rfilter": {"type": "box"}, "pixel_format": "rgb"},
        },
    }
    for material_index, parts in corners.items():
        material = doc["materials"][material_index]
        path = os.path.join(folder, "material_%d.obj" % material_index)
        _write_obj(path, np.concatenate(parts))
        shape = {"type": "obj", "filename": path, "face_normals": True,
                 "bsdf": _bsdf(material)}
        emission = material.get("emissiveFactor", [0.0, 0.0, 0.0])
        strength = material.get("extensions", {}).get(
            "KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
        if max(emission) > 0.0:
            shape["emitter"] = {"type": "area", "radiance": {
                "type": "rgb", "value": [e * strength for e in emission]}}
        scene["material_%d" % material_index] = shape
    for k, (centre, radius, value) in enumerate(spheres):
        scene["sphere_light_%d" % k] = {
            "type": "sphere", "center": centre, "radius": radius,
            "emitter": {"type": "area", "radiance": {"type": "rgb", "value": value}}}
    return scene
