// The two decoders behind gltf_compression.h, each in its own file: meshopt bufferViews
// (gltf_meshopt.cpp) and Draco primitives (gltf_draco.cpp).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scene/gltf/compression/gltf_compression.h"

namespace tinygltf {
class Model;
}

namespace wf::gltf {

inline constexpr const char* DRACO = "KHR_draco_mesh_compression";
inline constexpr const char* MESHOPT_NAMES[] = {"EXT_meshopt_compression",
                                                "KHR_meshopt_compression"};

// Fails unless the extension object obeys the specification's rules for its mode and filter,
// and names only what meshoptimizer 0.18 decodes. Called while planning, before any data.
void checkMeshoptParameters(const MeshoptView& ext, const std::string& file);

// Decodes `ext.byteLength` compressed bytes at `source` into count x byteStride bytes, with
// the filter applied.
std::vector<unsigned char> decodeMeshopt(const MeshoptView& ext, const unsigned char* source,
                                         const std::string& file);

// Decodes one Draco primitive: its indices and each compressed attribute go into new buffers,
// which the primitive's accessors then point at (accessor.bufferView, byteOffset 0). The
// decoded vertex and index counts must equal the accessors'.
void decodeDraco(tinygltf::Model& model, const DracoPrimitive& draco, const std::string& file);

// Appends `bytes` to the model as a new buffer and a bufferView over all of it.
int appendBufferView(tinygltf::Model& model, std::vector<unsigned char> bytes);

} // namespace wf::gltf
