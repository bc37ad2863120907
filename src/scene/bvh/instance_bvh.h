// The two-level acceleration structure of a scene with instanced meshes: one BVH per mesh and
// one over the world-space geometry, each in its own space, and a top-level BVH over their
// placements, all in one pair table (bvh_traverse.h's two-level traversal walks it).
#pragma once
#include <vector>

#include "scene/bvh/bvh_builder.h"
#include "scene/scene.h"

namespace wf {

struct TwoLevelBvh {
    // Entry 0 roots the top-level tree; the mesh trees follow, their child references rebased
    // onto this table and onto the whole triangle array.
    std::vector<BvhPair> pairs;
    std::vector<Instance> instances; // in the top-level tree's leaf order
    // Each instance's world-space box, in the same order (scene bounds; the top level's input).
    std::vector<Bounds> instanceBoxes;
    // Moving instances' keys (WF_INSTANCE_MOVING): 3 rows of worldFromObject per key, from
    // each such instance's motionKeys; their boxes bound every key's, so the motion between.
    std::vector<glm::vec4> motionKeys;
    BvhBuildStats stats; // summed over every tree; stackNeed is the deepest mesh tree's
};

// The affine maps and flags of an instance of a tree rooted at pair entry `blasRoot`.
Instance makeInstance(const glm::mat4& worldFromObject, uint32_t blasRoot);

// Reorders each range of `triangles` (the world geometry, then each of `meshes`) into its
// tree's leaf order. The world geometry's tree is tuned as a one-level scene's is
// (buildTunedBvh with `materials` and `camera`); it becomes an instance with the identity.
TwoLevelBvh buildTwoLevelBvh(std::vector<Triangle>& triangles, const std::vector<MeshRange>& meshes,
                             const std::vector<MeshPlacement>& placements,
                             const std::vector<Material>& materials, const Camera& camera);

} // namespace wf
