// Chooses the BVH's SAH traversal cost per scene by what a sample of paths costs on 8-wide SIMD
// (lavapipe's subgroups; GPU warps alike): a batch of 8 rays steps until its last ray is done,
// and each step runs the triangle loop as often as its busiest ray needs, at least once.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/bvh/bvh_builder.h"
#include "scene/scene.h"

namespace wf {

// Steps and triangle-loop iterations of 8-ray batches, summed over a sample of rays.
struct SimdTraversalWork {
    double steps = 0.0;
    double triangleIterations = 0.0;
    double cost() const; // in triangle-loop iterations, a step weighted by its relative cost
};

// The sample mimics the renderer's queues: camera rays over a side x side pixel grid, then up
// to three cosine-sampled bounces of the paths that hit, each queue in path order and cut into
// batches of 8; and from every hit a shadow segment to a point on an emissive triangle, where
// the scene has one. Deterministic for a given seed.
SimdTraversalWork simdTraversalWork(const std::vector<BvhNode>& nodes,
                                    const std::vector<Triangle>& triangles,
                                    const std::vector<Material>& materials, const Camera& camera,
                                    std::uint32_t side = 32, std::uint32_t seed = 1u);

// SAH traversal costs tried, and the scene size above which only the first is built (three
// builds of a million triangles would take seconds; the larger scaling scenes all chose it).
inline constexpr float kTunedTraversalCosts[] = {1.0f, 2.0f, 3.0f};
inline constexpr std::size_t kMaxTunedTriangles = 200000;

// buildBvh with each of kTunedTraversalCosts, keeping the tree whose simdTraversalWork costs
// least (the first of equals). `triangles` ends up in the kept tree's order; the stats say which
// cost won (traversalCost) and include the whole search in buildSeconds.
BvhBuildStats buildTunedBvh(std::vector<Triangle>& triangles, std::vector<BvhNode>& nodes,
                            const std::vector<Material>& materials, const Camera& camera);

} // namespace wf
