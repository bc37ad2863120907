// Ray queries on the CPU through the very traversal the GPU runs (shaders/traversal/
// bvh_traverse.h), for tests and tools. Pairs the nodes from buildBvh and borrows the
// triangle array, which must outlive it (in leaf order, as buildBvh leaves it).
#pragma once
#include <algorithm>
#include <cassert>
#include <vector>

#include "scene/bvh/bvh_builder.h"
#include "scene/scene.h"
#include "shaders/traversal/bvh_traverse.h"

namespace wf {

using gpu_types::HitRecord;

class CpuBvh {
public:
    CpuBvh(const std::vector<BvhNode>& nodes, const std::vector<Triangle>& triangles)
        : pairs_(pairBvhNodes(nodes)) {
        traversal_.pairs = pairs_.data();
        traversal_.triangles = triangles.data();
    }
    CpuBvh(const CpuBvh&) = delete; // traversal_ points into pairs_
    CpuBvh& operator=(const CpuBvh&) = delete;

    // Closest hit with t in (0, tMax); hit.triangle indexes the reordered triangle array.
    // With `stepTests`, each traversal step appends how many triangles it tested.
    bool traceClosest(glm::vec3 o, glm::vec3 d, float tMax, HitRecord& hit,
                      std::vector<std::uint32_t>* stepTests = nullptr) const {
        gpu_types::BvhTraversal traversal = traversal_; // the shared code is not const-qualified
        traversal.stepTests = stepTests;
        const bool found = traversal.traceClosest(o, d, tMax, hit);
        deepestStack_ = std::max(deepestStack_, traversal.deepestStack);
        return found;
    }

    // Whether anything is hit with t in (0, tMax).
    bool traceAny(glm::vec3 o, glm::vec3 d, float tMax,
                  std::vector<std::uint32_t>* stepTests = nullptr) const {
        gpu_types::BvhTraversal traversal = traversal_;
        traversal.stepTests = stepTests;
        const bool found = traversal.traceAny(o, d, tMax);
        deepestStack_ = std::max(deepestStack_, traversal.deepestStack);
        return found;
    }

    // The most entries the traversal stack has held over all queries so far.
    std::uint32_t deepestStack() const { return deepestStack_; }
    std::uint32_t stackNeed() const { return bvhStackNeed(pairs_); }

private:
    std::vector<BvhPair> pairs_;
    gpu_types::BvhTraversal traversal_;
    mutable std::uint32_t deepestStack_ = 0;
};

} // namespace wf
