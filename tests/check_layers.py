#!/usr/bin/env python3
"""The include rule of docs/architecture.md: a layer includes only layers below it,
    app -> viewer -> render -> passes -> gpu -> scene, image -> shaders
(scene and image side by side, neither including the other), and inside scene/ the model
(scene/*.h, *.cpp) includes none of gltf/, bvh/ or lights/. Prints every include that breaks
it and exits 1. Usage: check_layers.py SOURCE_ROOT"""
import os
import re
import sys

ORDER = ["app", "viewer", "render", "passes", "gpu", "scene", "image", "shaders"]
RANK = {name: i for i, name in enumerate(ORDER)}
RANK["image"] = RANK["scene"]  # side by side
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)

root = sys.argv[1]
broken = []
checked = 0
for top in ("src", "shaders"):
    for folder, _, names in os.walk(os.path.join(root, top)):
        for name in names:
            if not name.endswith((".h", ".cpp", ".glsl", ".comp")):
                continue
            path = os.path.relpath(os.path.join(folder, name), root)
            parts = path.split(os.sep)
            layer = "shaders" if top == "shaders" else (parts[1] if len(parts) > 2 else None)
            with open(os.path.join(root, path), encoding="utf-8") as f:
                includes = INCLUDE.findall(f.read())
            for inc in includes:
                checked += 1
                if top == "shaders":
                    # GLSL and shared headers see only the shader folder
                    if os.path.exists(os.path.join(root, "src", inc)) and "/" in inc and \
                            inc.split("/")[0] in RANK and inc.split("/")[0] != "shaders":
                        broken.append(f"{path}: includes {inc} (shaders -> src)")
                    continue
                target = "shaders" if inc.startswith("shaders/") else inc.split("/")[0]
                if layer is None or target not in RANK or layer not in RANK:
                    continue
                if RANK[target] < RANK[layer] or (RANK[target] == RANK[layer] and target != layer):
                    broken.append(f"{path}: includes {inc} ({layer} -> {target})")
                if layer == "scene" and len(parts) == 3 and \
                        re.match(r"scene/(gltf|bvh|lights)/", inc):
                    broken.append(f"{path}: includes {inc} (the scene model -> a reader or builder)")
for line in broken:
    print(line)
print(f"check_layers: {checked} includes checked, {len(broken)} against the layer order")
sys.exit(1 if broken or checked == 0 else 0)
