// glTF 2.0 (.gltf or .glb) to the renderer's flat scene: world-space triangles of the default
// scene's node tree with the vertex attributes and textures their materials use, metallic-
// roughness materials, every perspective camera and KHR_lights_punctual light.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scene/gltf/gltf_instancing.h"
#include "scene/scene.h"

namespace wf {

struct GltfOptions {
    Instancing instancing = Instancing::Auto; // which multiply placed meshes stay instanced
    // The scene at this time in seconds: its animations' node transforms and morph weights,
    // skins posed by their joints (gltf_animation.h). 0 poses animated files at their start.
    double time = 0.0;
    std::string animation; // "" plays every animation at once; else one's name or index
    // Motion blur: the shutter's interval in seconds (open < close; equal: none). Rigid node
    // motion within it (placements of meshes, cameras, lights) is keyed at motionSegments + 1
    // evenly spaced times, and `time` should be the interval's centre: what cannot be blurred
    // (skinned, morphed or emissive meshes) is posed there, with a warning.
    double shutterOpen = 0.0;
    double shutterClose = 0.0;
    uint32_t motionSegments = 8;
    // KHR_materials_variants: the variant whose materials the primitives take, by name or
    // index ("": their own materials; gltf_variants.h).
    std::string variant;
};

// Loads triangle lists, strips and fans (points and lines are skipped with one warning on
// stderr), indexed or not, dense or sparse accessors, float or (KHR_mesh_quantization)
// integer attributes. Front faces are counter-clockwise in world space: a node whose world
// matrix mirrors space has its triangles' winding swapped back (an instanced mesh keeps its
// own winding and its placement mirrors the faces back at shading). Degenerate triangles (zero
// area in float after the transform, or in the mesh's space when instanced) are dropped, and
// so are placements that flatten their mesh (a zero scale), with a warning. A scene with no emissive triangle and no
// light gets a 1x1 white environment.
// Only regular files inside the scene file's folder are read (no "..", no absolute URIs, at
// most 1 GiB each); PNG and JPEG images are decoded with their sizes checked first.
// Throws InputError("<path>: <problem>", one line) for unreadable, malformed or unsupported
// input: every index, offset, stride and count is checked before use.
// Warnings (skipped primitives, missing images, ignored extensions) go to `warnings` when
// given, else to stderr once the whole file has loaded; a refused file prints nothing.
Scene loadGltf(const std::string& path, std::vector<std::string>* warnings = nullptr,
               const GltfOptions& options = {});

// The same for a file already in memory (the fuzzer): `path` names it in messages, its
// extension says .gltf or .glb, and its folder is where URIs resolve. Warnings are dropped.
Scene loadGltfFromMemory(const unsigned char* data, std::size_t size, const std::string& path,
                         const GltfOptions& options = {});

} // namespace wf
