// Builds the light tree of shaders/lights/light_tree.h over the light table's emitters that
// have a place: emissive triangles, sphere, point and spot lights (directional lights and the
// environment are chosen beside it). Binned SAOH splits (pbrt-v4's: power x the orientation
// cone's measure x the box's area), one light per leaf.
#pragma once
#include <vector>

#include "scene/lights/light_table.h"
#include "shaders/lights/light_tree.h"

namespace wf {

struct LightTree {
    std::vector<gpu_types::LightTreeNode> nodes; // depth-first, root first; empty: no tree
    // Per emitter-table entry: its path from the root (x: depths 0-31, y: 32-63; bit set =
    // second child) and z = 1; zero for the emitters outside the tree.
    std::vector<glm::uvec4> trails;
    uint32_t lights = 0;    // emitters in the tree
    uint32_t depth = 0;     // of the deepest leaf
    double power = 0.0;     // their summed power
    double buildSeconds = 0.0;
};

// Whether an emitter-table entry belongs in the tree (else it is chosen beside it).
bool inLightTree(uint32_t source, const std::vector<PunctualLight>& lights);

// `motionKeys`: the table that moving lights' `motion` indexes (WF_MOTION), one position per
// key, motionSegments + 1 keys; a moving light's bounds cover every key.
LightTree buildLightTree(const LightTable& table, const std::vector<Triangle>& triangles,
                         const std::vector<Material>& materials,
                         const std::vector<PunctualLight>& lights,
                         const std::vector<glm::vec4>& motionKeys = {},
                         uint32_t motionSegments = 0);

} // namespace wf
