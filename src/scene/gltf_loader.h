// glTF 2.0 (.gltf or .glb) to the renderer's flat scene: world-space triangles of the default
// scene's node tree, Lambert materials and the first perspective camera.
#pragma once
#include <string>

#include "scene/scene.h"

namespace wf {

// Loads triangle-list primitives (other modes are skipped with one warning on stderr) with
// float VEC3 POSITION and u8/u16/u32 or no indices. Front faces are counter-clockwise in world
// space: a node whose world matrix mirrors space has its triangles' winding swapped back.
// Degenerate triangles (zero area in float after the transform) are dropped.
// Only regular files inside the scene file's folder are read (no "..", no absolute URIs, at
// most 1 GiB each); images are not decoded.
// Throws InputError("<path>: <problem>", one line) for unreadable, malformed or unsupported
// input: every index, offset, stride and count is checked before use.
Scene loadGltf(const std::string& path);

} // namespace wf
