// A primitive's morph targets and skin read and applied (scene/animation/deformation.h) to
// copies of its POSITION, NORMAL and TANGENT arrays, before the builder transforms and
// flattens them. Every target and skin accessor is checked like any other attribute.
#pragma once
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/gltf/gltf_accessors.h"

namespace tinygltf {
class Model;
struct Primitive;
} // namespace tinygltf

namespace wf::gltf {

struct Deformation {
    std::vector<double> morphWeights;      // per target (the node's, else the mesh's, animated)
    std::vector<glm::dmat4> jointMatrices; // skin: jointWorld x inverseBind; empty: no skin
    bool active() const {
        if (!jointMatrices.empty())
            return true;
        for (double w : morphWeights)
            if (w != 0.0)
                return true;
        return false;
    }
};

// Poses `points` (3 per vertex), `normals` (3, may be null) and `tangents` (4, may be null) in
// place: morph deltas first, then the skin. Fails (one line naming `where`) on a target or skin
// attribute of the wrong type or count, or a joint index outside the skin.
void deformPrimitive(AccessorReader& reader, const std::string& file,
                     const tinygltf::Primitive& primitive, const std::string& where,
                     const Deformation& deformation, FloatArray& points, FloatArray* normals,
                     FloatArray* tangents);

// A skin's joint matrices from the nodes' world transforms at the time: jointWorld[j] x
// inverseBindMatrices[j] (identity without the accessor). Fails on a joint index out of range
// or an inverseBindMatrices accessor that is not MAT4 floats with one matrix per joint.
std::vector<glm::dmat4> jointMatrices(const tinygltf::Model& model, const std::string& file,
                                      AccessorReader& reader, int skin,
                                      const std::vector<glm::dmat4>& nodeWorld);

} // namespace wf::gltf
