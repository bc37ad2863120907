// Ray queries on the CPU through the very traversal the GPU runs (shaders/shared/
// bvh_traverse.h), for tests and tools. Borrows the node and triangle arrays; they must
// outlive it and come from buildBvh (at least one node, triangles in leaf order).
#pragma once
#include <cassert>
#include <vector>

#include "scene/scene.h"
#include "shaders/shared/bvh_traverse.h"

namespace wf {

using gpu_types::HitRecord;

class CpuBvh {
public:
    CpuBvh(const std::vector<BvhNode>& nodes, const std::vector<Triangle>& triangles) {
        assert(!nodes.empty() && "buildBvh always emits a root, even for an empty scene");
        traversal_.nodes = nodes.data();
        traversal_.triangles = triangles.data();
    }

    // Closest hit with t in (0, tMax); hit.triangle indexes the reordered triangle array.
    bool traceClosest(glm::vec3 o, glm::vec3 d, float tMax, HitRecord& hit) const {
        gpu_types::BvhTraversal traversal = traversal_; // the shared code is not const-qualified
        return traversal.traceClosest(o, d, tMax, hit);
    }

    // Whether anything is hit with t in (0, tMax).
    bool traceAny(glm::vec3 o, glm::vec3 d, float tMax) const {
        gpu_types::BvhTraversal traversal = traversal_;
        return traversal.traceAny(o, d, tMax);
    }

private:
    gpu_types::BvhTraversal traversal_;
};

} // namespace wf
