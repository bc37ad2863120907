// Compressed meshes: KHR_draco_mesh_compression (libdraco) and EXT_/KHR_meshopt_compression
// (meshoptimizer). tinygltf 2.7.0 decodes neither, and refuses such files before the loader
// sees them (a Draco primitive's indices accessor has no bufferView; a meshopt fallback buffer
// has no uri), so decompression takes two steps around tinygltf's parse:
//  1. planDecompression reads the JSON itself first: it refuses extensionsRequired that the
//     loader lacks (naming them, where tinygltf's own error would not), takes every compressed
//     bufferView's and primitive's parameters, and rewrites the two things tinygltf refuses.
//  2. decompress decodes into new buffers appended to the parsed model and points bufferViews
//     and accessors at them; everything after reads plain accessors with all their checks.
#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace wf::gltf {

// One bufferView's EXT_meshopt_compression or KHR_meshopt_compression object.
struct MeshoptView {
    enum Mode { ATTRIBUTES, TRIANGLES, INDICES };
    enum Filter { NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL };
    int view = -1;
    std::string extension; // which of the two names, for messages
    int buffer = -1;       // the compressed bytes' buffer
    std::size_t byteOffset = 0, byteLength = 0, byteStride = 0, count = 0;
    Mode mode = ATTRIBUTES;
    Filter filter = NONE;
};

// One primitive's KHR_draco_mesh_compression object.
struct DracoPrimitive {
    int mesh = -1, primitive = -1;
    int bufferView = -1;                             // the Draco bitstream
    int indices = -1;                                // taken off the primitive for tinygltf
    std::vector<std::pair<std::string, int>> attributes; // glTF attribute -> Draco unique id
};

struct CompressionPlan {
    std::vector<MeshoptView> meshopt;
    std::vector<DracoPrimitive> draco;
    // Meshopt fallback buffers (no data of their own), by index: their declared byteLength.
    // tinygltf reads a 4-byte stand-in for each.
    std::map<int, std::size_t> placeholders;
};

// Reads the file's JSON (the whole .gltf, or a .glb's JSON chunk) when it mentions compression
// or required extensions, and rewrites `bytes` for tinygltf where the plan needs it. A file
// whose JSON does not parse is left alone, for tinygltf to refuse in its own words.
// Throws InputError for an unsupported required extension or malformed compression objects.
CompressionPlan planDecompression(std::vector<unsigned char>& bytes, bool binary,
                                  const std::string& file);

// Decodes every planned bufferView and primitive into new buffers of `model`. Declared sizes
// are bounded before anything is allocated and every decoded size is checked against its
// accessor or bufferView; hostile data fails with one InputError line.
void decompress(tinygltf::Model& model, const CompressionPlan& plan, const std::string& file);

} // namespace wf::gltf
