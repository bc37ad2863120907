// Compressed copies of whole glTF scenes for the render tests: every triangle primitive
// re-encoded by Draco's encoder or meshoptimizer's, as glTF Transform or gltfpack would, and
// the rest (materials, textures, nodes, cameras) left as it was.
#pragma once
#include <string>

#include "compressed_gltf.h"

namespace wf::test {

// A .gltf whose single buffer is a data: URI (as scenes/*.gltf are), buffer 0 of the result.
Document readGltf(const std::string& path);

enum class MeshCodec {
    // KHR_draco_mesh_compression, Edgebreaker; positions at 14 bits, normals 10, UVs 12.
    Draco,
    // KHR_meshopt_compression over KHR_mesh_quantization: float positions through the
    // exponential filter (16-bit mantissas), int8 octahedral normals, u16 UVs (when in
    // [0, 1]), triangle-coded indices, decoded into a fallback buffer.
    Meshopt,
};

// `original` with its primitives' POSITION, NORMAL, TEXCOORD_0 and indices compressed by
// `codec` (no other attributes; triangle lists only) and images in bufferViews carried over.
// What it cannot copy is a test failure.
Document compressedCopy(const Document& original, MeshCodec codec);

} // namespace wf::test
