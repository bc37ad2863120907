// Which meshes the loader keeps once and places by instances (a two-level BVH) rather than
// flattening every placement into world space.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "scene/gltf/gltf_materials.h"

namespace tinygltf {
class Model;
struct Primitive;
} // namespace tinygltf

namespace wf {

// --instancing: auto instances a mesh where its copies would cost kAutoInstancingCopies
// triangles or more (below that one flat BVH traces as fast or faster); on, every mesh that
// two or more nodes place; off, none (the scene as one flat BVH, as before instancing).
enum class Instancing { Auto, On, Off };
constexpr std::size_t kAutoInstancingCopies = std::size_t(1) << 20;

Instancing parseInstancing(const std::string& name); // UsageError if unknown
const char* instancingName(Instancing mode);

namespace gltf {

// Triangles a primitive makes by its accessors' counts alone, before any is read; 0 where an
// accessor, its buffer view or the view's buffer is out of range (the loader's checks name
// those).
std::size_t estimatedTriangles(const tinygltf::Model& model, const tinygltf::Primitive& primitive);

// Whether a primitive of the mesh has an emissive material.
bool meshEmits(const tinygltf::Model& model, std::size_t mesh, const MaterialTables& materials);

// Per mesh, whether to instance it. Emissive meshes never are: each copy is a light of its
// own, and the light table lists world-space triangles. `placements` counts each mesh's nodes
// among those the roots reach (the caller has checked the tree has no cycles).
std::vector<bool> meshesToInstance(const tinygltf::Model& model,
                                   const std::vector<std::size_t>& placements,
                                   const MaterialTables& materials, Instancing mode);

} // namespace gltf
} // namespace wf
