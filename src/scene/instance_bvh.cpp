#include "scene/instance_bvh.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "scene/bvh_tuning.h"

namespace wf {
namespace {

struct BuiltTree {
    std::vector<BvhPair> pairs; // indices local to the tree and its triangle range
    Bounds box;
};

BuiltTree buildRange(std::vector<Triangle>& triangles, uint32_t first, uint32_t count, bool tuned,
                     const std::vector<Material>& materials, const Camera& camera,
                     BvhBuildStats& total) {
    std::vector<BvhNode> nodes;
    BvhBuildStats stats;
    if (tuned && count <= kMaxTunedTriangles) {
        // Tuning builds candidate trees from copies; small enough to copy this range too.
        std::vector<Triangle> part(triangles.begin() + first, triangles.begin() + first + count);
        stats = buildTunedBvh(part, nodes, materials, camera);
        std::copy(part.begin(), part.end(), triangles.begin() + first);
    } else {
        // In place: a copy of millions of triangles would raise the peak of host memory.
        stats = buildBvh(triangles.data() + first, count, nodes);
        stats.traversalCost = kTunedTraversalCosts[0];
    }
    BuiltTree tree;
    tree.pairs = pairBvhNodes(nodes);
    tree.box.lo = nodes[0].lo;
    tree.box.hi = nodes[0].hi;
    total.sahCost += tuned ? stats.sahCost : 0.0;
    total.traversalCost = tuned ? stats.traversalCost : total.traversalCost;
    total.nodeCount += stats.nodeCount;
    total.leafCount += stats.leafCount;
    total.maxDepth = std::max(total.maxDepth, stats.maxDepth);
    total.stackNeed = std::max(total.stackNeed, bvhStackNeed(tree.pairs));
    total.threads = std::max(total.threads, stats.threads);
    return tree;
}

// A child reference moved from a tree's own tables to the shared ones.
uint32_t rebase(uint32_t child, uint32_t pairBase, uint32_t triangleBase) {
    if (child == WF_BVH_NO_CHILD)
        return child;
    const uint32_t count = child & WF_BVH_MAX_LEAF_COUNT;
    const uint32_t index = (child >> WF_BVH_COUNT_BITS) + (count == 0 ? pairBase : triangleBase);
    return index << WF_BVH_COUNT_BITS | count;
}

void append(std::vector<BvhPair>& table, const std::vector<BvhPair>& pairs, uint32_t triangleBase) {
    const uint32_t pairBase = uint32_t(table.size());
    for (BvhPair pair : pairs) {
        pair.child0 = rebase(pair.child0, pairBase, triangleBase);
        pair.child1 = rebase(pair.child1, pairBase, triangleBase);
        table.push_back(pair);
    }
}

// A box grown by a few float ulps of its largest coordinate, so that rounding in the box's
// own transform cannot leave out a point the mesh's ray meets (the slab test has slack for
// its own rounding only).
Bounds padded(Bounds box) {
    const float scale = std::max(glm::length(box.lo), glm::length(box.hi));
    const glm::vec3 pad(scale * 4.0f * 1.1920929e-7f);
    box.lo -= pad;
    box.hi += pad;
    return box;
}

} // namespace

Instance makeInstance(const glm::mat4& worldFromObject, uint32_t blasRoot) {
    // The inverse in double: a float inverse of a badly scaled matrix loses digits the ray
    // offsets (surface.glsl) do not allow for.
    const glm::dmat4 world(worldFromObject);
    const glm::dmat4 object = glm::inverse(world);
    Instance instance{};
    glm::vec4* rowsObject[3] = {&instance.objectFromWorld0, &instance.objectFromWorld1,
                                &instance.objectFromWorld2};
    glm::vec4* rowsWorld[3] = {&instance.worldFromObject0, &instance.worldFromObject1,
                               &instance.worldFromObject2};
    for (int r = 0; r < 3; ++r) {
        *rowsObject[r] = glm::vec4(object[0][r], object[1][r], object[2][r], object[3][r]);
        *rowsWorld[r] = glm::vec4(world[0][r], world[1][r], world[2][r], world[3][r]);
    }
    instance.blasRoot = blasRoot;
    instance.flags = glm::determinant(glm::dmat3(world)) < 0.0 ? WF_INSTANCE_MIRRORED : 0u;
    return instance;
}

TwoLevelBvh buildTwoLevelBvh(std::vector<Triangle>& triangles, const std::vector<MeshRange>& meshes,
                             const std::vector<MeshPlacement>& placements,
                             const std::vector<Material>& materials, const Camera& camera) {
    const auto start = std::chrono::steady_clock::now();
    TwoLevelBvh out;
    out.stats.threads = 1;
    const uint32_t worldCount = meshes.empty() ? uint32_t(triangles.size()) : meshes[0].firstTriangle;
    std::vector<BuiltTree> trees; // the world's first where it has triangles, then the meshes'
    std::vector<uint32_t> triangleBases;
    if (worldCount > 0) {
        trees.push_back(buildRange(triangles, 0, worldCount, true, materials, camera, out.stats));
        triangleBases.push_back(0);
    }
    const uint32_t firstMeshTree = uint32_t(trees.size());
    for (const MeshRange& mesh : meshes) {
        trees.push_back(buildRange(triangles, mesh.firstTriangle, mesh.triangleCount, false,
                                   materials, camera, out.stats));
        triangleBases.push_back(mesh.firstTriangle);
    }

    // The top level: each instance a pseudo-triangle (lo, hi, centre) whose bounds are its box
    // and whose centroid is the box's centre, so the triangle builder serves; one per leaf.
    struct Placed {
        glm::mat4 worldFromObject;
        uint32_t tree;
    };
    std::vector<Placed> placed;
    if (worldCount > 0)
        placed.push_back({glm::mat4(1.0f), 0});
    for (const MeshPlacement& placement : placements)
        placed.push_back({placement.worldFromObject, firstMeshTree + placement.mesh});
    std::vector<Triangle> boxes;
    boxes.reserve(placed.size());
    for (uint32_t i = 0; i < placed.size(); ++i) {
        const Bounds box =
            padded(transformedBounds(trees[placed[i].tree].box, placed[i].worldFromObject));
        boxes.push_back(Triangle{box.lo, 0u, box.hi, 0u, 0.5f * (box.lo + box.hi), i});
    }
    std::vector<BvhNode> topNodes;
    BvhBuildOptions topOptions;
    topOptions.maxLeafSize = 1;
    topOptions.maxSahLeafSize = 1;
    const BvhBuildStats topStats = buildBvh(boxes, topNodes, topOptions);
    out.pairs = pairBvhNodes(topNodes);
    out.stats.nodeCount += topStats.nodeCount;
    out.stats.leafCount += topStats.leafCount;
    out.stats.maxDepth += topStats.maxDepth + 1;

    std::vector<uint32_t> roots;
    size_t pairCount = out.pairs.size();
    for (const BuiltTree& tree : trees)
        pairCount += tree.pairs.size();
    out.pairs.reserve(pairCount);
    for (size_t t = 0; t < trees.size(); ++t) {
        roots.push_back(uint32_t(out.pairs.size()));
        append(out.pairs, trees[t].pairs, triangleBases[t]);
        trees[t].pairs = {};
    }
    for (const Triangle& box : boxes) {
        const Placed& p = placed[box.pad];
        out.instances.push_back(makeInstance(p.worldFromObject, roots[p.tree]));
        Bounds world;
        world.lo = box.p0;
        world.hi = box.p1;
        out.instanceBoxes.push_back(world);
    }
    out.stats.buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace wf
