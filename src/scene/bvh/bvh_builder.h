// Binned-SAH BVH over the scene's triangles, flattened depth-first, then paired into the layout
// that shaders/traversal/bvh_traverse.h walks on the GPU and on the CPU.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace wf {

// Traversal keeps one stack slot per level below the root; WF_BVH_STACK_SIZE (64) - 1.
constexpr std::uint32_t BVH_MAX_DEPTH = 63;

struct BvhBuildOptions {
    std::uint32_t maxLeafSize = 4;     // at or below this count a node is always a leaf
    std::uint32_t maxSahLeafSize = 16; // SAH may stop splitting early only up to this count
    std::uint32_t binCount = 32;       // SAH candidate planes per axis, over centroid bounds
    // Nodes of n < 4 (binCount - 4) triangles get 4 + n / 4 bins: 30% faster builds, SAH within
    // 0.2%. Off: binCount everywhere (buildTunedBvh, for scenes small enough to tune).
    bool fewerBinsForSmallNodes = true;
    float traversalCost = 1.0f;        // cost of visiting an interior node ...
    float intersectionCost = 1.0f;     // ... relative to one ray-triangle test
    std::uint32_t maxDepth = BVH_MAX_DEPTH; // root is depth 0; must be <= BVH_MAX_DEPTH
    std::uint32_t threads = 0;         // 0: every core; the tree is the same for any count
};

struct BvhBuildStats {
    double sahCost = 0.0;      // expected cost per ray hitting the root box, same units as above
    double buildSeconds = 0.0;
    std::uint32_t nodeCount = 0;
    std::uint32_t leafCount = 0;
    std::uint32_t maxDepth = 0; // deepest node; the root is depth 0
    std::uint32_t stackNeed = 0; // bvhStackNeed of the paired tree (filled in by its caller)
    float traversalCost = 1.0f;  // the SAH traversal cost built with (buildTunedBvh's choice)
    std::uint32_t threads = 1;   // threads the build ran on
};

// Builds `nodes` (cleared first) and reorders `triangles` in place so every leaf indexes a
// contiguous range. Always emits at least one node: for no triangles, a root with count 0 and
// an inverted box, which traversal treats as empty. Degenerate triangles are kept and binned
// like any other; vertex coordinates must be finite.
BvhBuildStats buildBvh(std::vector<Triangle>& triangles, std::vector<BvhNode>& nodes,
                       const BvhBuildOptions& opts = {});
// The same over `count` triangles in place (a range of a larger array).
BvhBuildStats buildBvh(Triangle* triangles, std::size_t count, std::vector<BvhNode>& nodes,
                       const BvhBuildOptions& opts = {});

// The layout traversal walks (BvhPair in scene_types.h): one entry per interior node of
// `nodes` (from buildBvh), or a single entry for a leaf root or an empty scene.
std::vector<BvhPair> pairBvhNodes(const std::vector<BvhNode>& nodes);
// The same appended to `pairs` (a table of several trees), child references offset by its
// size and triangle references by `triangleBase`; returns the tree's root entry.
std::uint32_t appendBvhPairs(const std::vector<BvhNode>& nodes, std::vector<BvhPair>& pairs,
                             std::uint32_t triangleBase);

// The most entries traversal (bvh_traverse.h) can hold on its stack for these pairs, whatever
// the ray: an entry whose children are both interior pushes one and descends into the other.
std::uint32_t bvhStackNeed(const std::vector<BvhPair>& pairs);
// The same for the tree at entries [first, end) of a table of several (appendBvhPairs).
std::uint32_t bvhStackNeed(const std::vector<BvhPair>& table, std::size_t first,
                           std::size_t end);

} // namespace wf
