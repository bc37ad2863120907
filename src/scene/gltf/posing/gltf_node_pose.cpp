// A node's local transform: its matrix, or T x R x S with any of the three replaced by what
// the animations set at the time (gltf_animation.h), every number checked.
#include "scene/gltf/posing/gltf_node_pose.h"

#include <tiny_gltf.h>

#include <cmath>

namespace wf::gltf {
namespace {

bool allFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) {
                return false;
            }
        }
    }
    return true;
}

} // namespace

// Row r, column c of the rotation, as glm's m[c][r].
glm::dmat4 rotationMatrix(double x, double y, double z, double w) {
    glm::dmat4 m(1.0);
    m[0][0] = 1 - 2 * (y * y + z * z);
    m[1][0] = 2 * (x * y - w * z);
    m[2][0] = 2 * (x * z + w * y);
    m[0][1] = 2 * (x * y + w * z);
    m[1][1] = 1 - 2 * (x * x + z * z);
    m[2][1] = 2 * (y * z - w * x);
    m[0][2] = 2 * (x * z - w * y);
    m[1][2] = 2 * (y * z + w * x);
    m[2][2] = 1 - 2 * (x * x + y * y);
    return m;
}

glm::dmat4 nodeLocalTransform(const tinygltf::Model& model, const std::string& file,
                              int nodeIndex, const NodeAnimation* animated) {
    const tinygltf::Node& node = model.nodes[nodeIndex];
    const std::string name = "node " + std::to_string(nodeIndex);
    glm::dmat4 m(1.0);
    if (animated && (animated->translation || animated->rotation || animated->scale)) {
        // The channels replace the node's own T, R or S (gltf_animation checked it has no matrix).
        const auto& t = node.translation;
        const auto& r = node.rotation;
        const auto& s = node.scale;
        if ((!t.empty() && t.size() != 3) || (!r.empty() && r.size() != 4) ||
            (!s.empty() && s.size() != 3)) {
            fail(file, name + ": translation and scale need 3 numbers, rotation 4");
        }
        glm::dvec3 tv = t.empty() ? glm::dvec3(0.0) : glm::dvec3(t[0], t[1], t[2]);
        glm::dquat rq = r.empty() ? glm::dquat(1, 0, 0, 0) : glm::dquat(r[3], r[0], r[1], r[2]);
        glm::dvec3 sv = s.empty() ? glm::dvec3(1.0) : glm::dvec3(s[0], s[1], s[2]);
        tv = animated->translation.value_or(tv);
        rq = animated->rotation.value_or(rq);
        sv = animated->scale.value_or(sv);
        const double len = glm::length(rq);
        if (!(len > 0.0) || !std::isfinite(len))
            fail(file, name + ": rotation is not a usable quaternion");
        rq /= len;
        m[3] = glm::dvec4(tv, 1.0);
        m = m * rotationMatrix(rq.x, rq.y, rq.z, rq.w) *
            glm::dmat4(glm::dvec4(sv.x, 0, 0, 0), glm::dvec4(0, sv.y, 0, 0),
                       glm::dvec4(0, 0, sv.z, 0), glm::dvec4(0, 0, 0, 1));
    } else if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) {
            fail(file, name + ": matrix needs 16 numbers");
        }
        for (int i = 0; i < 16; ++i) {
            m[i / 4][i % 4] = node.matrix[i]; // column-major in glTF and glm alike
        }
    } else {
        const auto& t = node.translation;
        const auto& r = node.rotation;
        const auto& s = node.scale;
        if ((!t.empty() && t.size() != 3) || (!r.empty() && r.size() != 4) ||
            (!s.empty() && s.size() != 3)) {
            fail(file, name + ": translation and scale need 3 numbers, rotation 4");
        }
        if (!t.empty()) {
            m[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
        }
        if (!r.empty()) {
            // Exporters write quaternions rounded to a few digits; renormalize so the
            // rotation stays a rotation.
            const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
            if (!(len > 0.0) || !std::isfinite(len)) {
                fail(file, name + ": rotation is not a usable quaternion");
            }
            m = m * rotationMatrix(r[0] / len, r[1] / len, r[2] / len, r[3] / len);
        }
        if (!s.empty()) {
            m = m * glm::dmat4(glm::dvec4(s[0], 0, 0, 0), glm::dvec4(0, s[1], 0, 0),
                               glm::dvec4(0, 0, s[2], 0), glm::dvec4(0, 0, 0, 1));
        }
    }
    if (!allFinite(m)) {
        fail(file, name + ": transform is not finite");
    }
    return m;
}

std::vector<glm::dmat4> nodeWorldTransforms(const tinygltf::Model& model, const std::string& file,
                                            const std::vector<int>& parent,
                                            const std::vector<NodeAnimation>& animated) {
    const std::size_t n = model.nodes.size();
    std::vector<glm::dmat4> world(n, glm::dmat4(1.0));
    std::vector<bool> done(n, false);
    std::vector<int> chain;
    for (std::size_t i = 0; i < n; ++i) {
        for (int node = int(i); node != -1 && !done[node]; node = parent[node])
            chain.push_back(node);
        for (auto node = chain.rbegin(); node != chain.rend(); ++node) {
            const int up = parent[*node];
            world[*node] = (up == -1 ? glm::dmat4(1.0) : world[up]) *
                           nodeLocalTransform(model, file, *node,
                                              std::size_t(*node) < animated.size()
                                                  ? &animated[*node]
                                                  : nullptr);
            done[*node] = true;
        }
        chain.clear();
    }
    return world;
}

} // namespace wf::gltf
