#include "scene/bvh/instance_bvh.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

#include "scene/bvh/bvh_tuning.h"

namespace wf {
namespace {

// A tree's nodes until they are paired into the shared table, and the triangle range they
// index from 0.
struct BuiltTree {
    std::vector<BvhNode> nodes;
    uint32_t firstTriangle = 0;
    Bounds box() const { return Bounds{nodes[0].lo, nodes[0].hi}; }
};

BuiltTree buildRange(std::vector<Triangle>& triangles, uint32_t first, uint32_t count, bool tuned,
                     const std::vector<Material>& materials, const Camera& camera,
                     BvhBuildStats& total) {
    BuiltTree tree;
    tree.firstTriangle = first;
    BvhBuildStats stats;
    if (tuned && count <= kMaxTunedTriangles) {
        // Tuning builds candidate trees from copies; small enough to copy this range too.
        std::vector<Triangle> part(triangles.begin() + first, triangles.begin() + first + count);
        stats = buildTunedBvh(part, tree.nodes, materials, camera);
        std::copy(part.begin(), part.end(), triangles.begin() + first);
    } else {
        // In place: a copy of millions of triangles would raise the peak of host memory.
        stats = buildBvh(triangles.data() + first, count, tree.nodes);
        stats.traversalCost = kTunedTraversalCosts[0];
    }
    total.sahCost += tuned ? stats.sahCost : 0.0;
    total.traversalCost = tuned ? stats.traversalCost : total.traversalCost;
    total.nodeCount += stats.nodeCount;
    total.leafCount += stats.leafCount;
    total.maxDepth = std::max(total.maxDepth, stats.maxDepth);
    total.threads = std::max(total.threads, stats.threads);
    return tree;
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
    if (worldCount > 0)
        trees.push_back(buildRange(triangles, 0, worldCount, true, materials, camera, out.stats));
    const uint32_t firstMeshTree = uint32_t(trees.size());
    for (const MeshRange& mesh : meshes)
        trees.push_back(buildRange(triangles, mesh.firstTriangle, mesh.triangleCount, false,
                                   materials, camera, out.stats));

    // The top level: each instance a pseudo-triangle (lo, hi, centre) whose bounds are its box
    // and whose centroid is the box's centre, so the triangle builder serves; one per leaf.
    struct Placed {
        glm::mat4 worldFromObject;
        uint32_t tree;
        const std::vector<glm::mat4>* motion;
    };
    static const std::vector<glm::mat4> still;
    std::vector<Placed> placed;
    if (worldCount > 0)
        placed.push_back({glm::mat4(1.0f), 0, &still});
    for (const MeshPlacement& placement : placements)
        placed.push_back({placement.worldFromObject, firstMeshTree + placement.mesh,
                          &placement.motion});
    std::vector<Triangle> boxes;
    boxes.reserve(placed.size());
    for (uint32_t i = 0; i < placed.size(); ++i) {
        // A moving placement's map is interpolated between keys, so each of its points stays
        // between the keys' images of it: the keys' boxes together bound the motion.
        Bounds box = transformedBounds(trees[placed[i].tree].box(), placed[i].worldFromObject);
        for (const glm::mat4& key : *placed[i].motion) {
            const Bounds moved = transformedBounds(trees[placed[i].tree].box(), key);
            box.grow(moved.lo);
            box.grow(moved.hi);
        }
        box = padded(box);
        boxes.push_back(Triangle{box.lo, 0u, box.hi, 0u, 0.5f * (box.lo + box.hi), i});
    }
    std::vector<BvhNode> topNodes;
    BvhBuildOptions topOptions;
    topOptions.maxLeafSize = 1;
    topOptions.maxSahLeafSize = 1;
    const BvhBuildStats topStats = buildBvh(boxes, topNodes, topOptions);
    // The top level first (traversal starts at entry 0), then each tree paired straight into
    // the shared table, its nodes freed as it goes.
    size_t pairCount = topNodes.size() / 2 + 1;
    for (const BuiltTree& tree : trees)
        pairCount += tree.nodes.size() / 2 + 1;
    out.pairs.reserve(pairCount);
    appendBvhPairs(topNodes, out.pairs, 0);
    out.stats.nodeCount += topStats.nodeCount;
    out.stats.leafCount += topStats.leafCount;
    out.stats.maxDepth += topStats.maxDepth + 1;

    std::vector<uint32_t> roots;
    for (BuiltTree& tree : trees) {
        roots.push_back(appendBvhPairs(tree.nodes, out.pairs, tree.firstTriangle));
        out.stats.stackNeed = std::max(
            out.stats.stackNeed, bvhStackNeed(out.pairs, roots.back(), out.pairs.size()));
        tree.nodes = {};
    }
    for (const Triangle& box : boxes) {
        const Placed& p = placed[box.pad];
        out.instances.push_back(makeInstance(p.worldFromObject, roots[p.tree]));
        if (!p.motion->empty()) {
            Instance& instance = out.instances.back();
            instance.flags |= WF_INSTANCE_MOVING;
            instance.motionKeys = uint32_t(out.motionKeys.size());
            for (const glm::mat4& key : *p.motion)
                for (int r = 0; r < 3; ++r)
                    out.motionKeys.emplace_back(key[0][r], key[1][r], key[2][r], key[3][r]);
        }
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
