// How big a scene the loader accepts: triangles (the BVH's index limit, or what this machine's
// memory holds) and instances, counted from the accessors before anything is read, so a small
// file placing a big mesh at many nodes is refused at once rather than after filling memory.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace wf::gltf {

// Host bytes a triangle takes at the peak of loading and building (measured ~200: a 3.5 M
// triangle scene peaked at 710 MiB).
constexpr std::size_t kHostBytesPerTriangle = 256;
// The BVH's triangle index limit (bvh_traverse.h: 32 - WF_BVH_COUNT_BITS bits).
constexpr std::size_t kTraversalTriangleLimit = (std::size_t(1) << 27) - 1;

// The most triangles a scene may flatten to: the traversal's limit, or what this machine's
// memory holds at kHostBytesPerTriangle, whichever is less. Meshes placed by many nodes are
// flattened, so a small file can ask for far more; the loader refuses it before loading.
std::size_t maxSceneTriangles();
// Why maxSceneTriangles() is what it is, for the refusal: "this machine's 24 GiB of memory
// (256 bytes a triangle)" or "the BVH's triangle index limit".
std::string sceneTriangleLimitReason();

// Triangles a primitive of `mode` makes from `corners` vertices (list: n / 3, strip and fan:
// n - 2); 0 for points, lines and unknown modes.
std::size_t trianglesOfPrimitive(int mode, std::size_t corners);

// The most placements of instanced meshes a scene may have (112 bytes each on the GPU).
constexpr std::size_t kMaxInstances = std::size_t(1) << 24;

// The triangles the scene keeps (flattened copies, and instanced meshes once), from the
// accessors' counts alone, given each mesh's placements and whether it is instanced; refuses
// (InputError naming `file`) a scene past maxSceneTriangles() or kMaxInstances.
std::size_t checkPlacedTriangles(const tinygltf::Model& model, const std::string& file,
                                 const std::vector<std::size_t>& placements,
                                 const std::vector<bool>& instanced);

} // namespace wf::gltf
