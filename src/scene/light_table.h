// The emitter table for next-event estimation: every emissive triangle of positive area and
// finite emission, chosen with probability proportional to its power through a Walker alias
// table (O(1) per sample). Run after the BVH builder has reordered the triangles.
#pragma once
#include <vector>

#include "scene/scene.h"

namespace wf {

struct LightTable {
    std::vector<Emitter> emitters;
    double totalPower = 0.0; // sum of (mean emitted radiance x area x pi x sides)
};

// Fills in each triangle's `emitter` field (WF_NO_EMITTER for non-emitters).
LightTable buildLightTable(std::vector<Triangle>& triangles,
                           const std::vector<Material>& materials);

// Walker/Vose alias table over non-negative weights with a positive sum: pmf, threshold and
// alias per slot (Emitter.triangle is left for the caller).
std::vector<Emitter> buildAliasTable(const std::vector<double>& weights);

} // namespace wf
