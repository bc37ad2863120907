// glTF animations at one time: every animation of the file is checked (a broken one refuses the
// file in one line naming the animation, channel or sampler, and the rule), then the chosen
// ones (all, as viewers play them, or one by name or index) are sampled at `time` seconds into
// per-node overrides of translation, rotation, scale and morph target weights.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "scene/gltf/gltf_accessors.h"

namespace tinygltf {
class Model;
}

namespace wf::gltf {

// What the animations set on one node at the time (unset: the node's own value).
struct NodeAnimation {
    std::optional<glm::dvec3> translation, scale;
    std::optional<glm::dquat> rotation;
    std::optional<std::vector<double>> weights;
};

// The morph target count of a mesh (its primitives must agree; the loader checks).
std::size_t morphTargetCount(const tinygltf::Model& model, int mesh);

// One entry per node. `which` is "" for every animation, else an animation's name or index
// (InputError listing the file's animations when none matches). Time is clamped to each
// sampler's keys. `lastKey`, when given, receives the chosen animations' last key time (0 for
// none): how long they play. `restPoseOnBadKeys` (a render at time 0 that names no animation):
// an animation whose key times do not increase (as accessors without a bufferView give: all
// zero) is dropped with one warning instead of refused, since such a render needs none.
std::vector<NodeAnimation> sampleAnimations(const tinygltf::Model& model, const std::string& file,
                                            AccessorReader& reader, double time,
                                            const std::string& which, double* lastKey = nullptr,
                                            bool restPoseOnBadKeys = false);

} // namespace wf::gltf
