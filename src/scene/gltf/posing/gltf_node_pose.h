// A node's local transform at the time the animations were sampled.
#pragma once
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/gltf/posing/gltf_animation.h"

namespace tinygltf {
class Model;
}

namespace wf::gltf {

// The rotation of the unit quaternion (x, y, z, w), as a matrix (the one node rotations use).
glm::dmat4 rotationMatrix(double x, double y, double z, double w);

// The node's matrix, or its translation x rotation (renormalised) x scale with the parts that
// `animated` (may be null) sets replaced. Fails (one line naming the node) on a matrix that is
// not 16 numbers, TRS of the wrong sizes, a rotation that is no usable quaternion or a
// transform that is not finite.
glm::dmat4 nodeLocalTransform(const tinygltf::Model& model, const std::string& file,
                              int nodeIndex, const NodeAnimation* animated);

// Every node's world transform with `animated` (one entry per node) applied, joints outside the
// scene's tree included, parents before children via `parent` (-1: a root; checked free of
// loops).
std::vector<glm::dmat4> nodeWorldTransforms(const tinygltf::Model& model, const std::string& file,
                                            const std::vector<int>& parent,
                                            const std::vector<NodeAnimation>& animated);

} // namespace wf::gltf
