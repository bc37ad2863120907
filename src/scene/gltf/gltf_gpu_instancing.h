// EXT_mesh_gpu_instancing: a node's mesh drawn at many instance transforms, each
// TRANSLATION x ROTATION x SCALE (any subset; the rest identity) applied before the node's world
// transform. The loader turns each instance into the placement a child node with that TRS would
// make, so such a file renders as the file with one node per instance does (instanced or
// flattened by --instancing alike, emissive meshes flattened into lights).
#pragma once
#include <cstddef>
#include <string>

#include <glm/mat4x4.hpp>

#include "scene/gltf/gltf_accessors.h"

namespace tinygltf {
class Model;
}

namespace wf::gltf {

// How many instances the node's EXT_mesh_gpu_instancing places its mesh at; 0 where the node
// has none (its mesh is placed once, by the node). Checks what can be checked without reading
// data, failing with one line naming the node: the extension's shape, the accessors' indices,
// types and component types (TRANSLATION and SCALE: VEC3 FLOAT; ROTATION: VEC4 FLOAT, or BYTE
// or SHORT normalized), one count shared by every attribute, and that count at most
// kMaxInstances. Attributes named with a leading underscore are the application's and only
// counted; other unknown ones are ignored with a warning.
std::size_t gpuInstanceCount(const tinygltf::Model& model, const std::string& file,
                             int nodeIndex);

// The node's instances, read through `reader` (which must outlive this).
class GpuInstances {
public:
    // Reads and checks the instance attributes (values finite, rotations usable quaternions);
    // empty where the node has no EXT_mesh_gpu_instancing.
    GpuInstances(const tinygltf::Model& model, const std::string& file, AccessorReader& reader,
                 int nodeIndex);
    bool empty() const { return count_ == 0; }
    std::size_t size() const { return count_; }
    // Instance i's local transform, T x R (renormalised, as node rotations are) x S, computed
    // as nodeLocalTransform computes a node's.
    glm::dmat4 transform(std::size_t i) const;

private:
    const FloatArray* translation_ = nullptr;
    const FloatArray* rotation_ = nullptr;
    const FloatArray* scale_ = nullptr;
    std::size_t count_ = 0;
};

} // namespace wf::gltf
