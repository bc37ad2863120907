#include "scene/bvh/bvh_refit.h"

#include "errors.h"

namespace wf {
namespace {

struct Refit {
    std::vector<BvhPair>& pairs;
    const std::vector<Triangle>& triangles;

    // The box of a child reference, its entry's boxes rewritten on the way (recursion depth is
    // the tree's, at most BVH_MAX_DEPTH).
    Bounds box(uint32_t child) {
        Bounds b;
        if (child == WF_BVH_NO_CHILD)
            return b;
        const uint32_t count = child & WF_BVH_MAX_LEAF_COUNT;
        const uint32_t index = child >> WF_BVH_COUNT_BITS;
        if (count > 0) {
            if (uint64_t(index) + count > triangles.size())
                throw InternalError("refitBvhPairs: a leaf past the triangles");
            for (uint32_t i = index; i < index + count; ++i) {
                b.grow(triangles[i].p0);
                b.grow(triangles[i].p1);
                b.grow(triangles[i].p2);
            }
            return b;
        }
        return entry(index);
    }

    Bounds entry(uint32_t index) {
        if (index >= pairs.size())
            throw InternalError("refitBvhPairs: a child entry past the table");
        // Copies: the recursion may not grow the table, but references into it read clearer.
        const uint32_t child0 = pairs[index].child0, child1 = pairs[index].child1;
        const Bounds b0 = box(child0), b1 = box(child1);
        BvhPair& pair = pairs[index];
        if (child0 != WF_BVH_NO_CHILD) {
            pair.lo0 = b0.lo;
            pair.hi0 = b0.hi;
        }
        if (child1 != WF_BVH_NO_CHILD) {
            pair.lo1 = b1.lo;
            pair.hi1 = b1.hi;
        }
        Bounds both = b0;
        if (!b1.empty()) {
            both.grow(b1.lo);
            both.grow(b1.hi);
        }
        return both;
    }
};

double area(glm::vec3 lo, glm::vec3 hi) {
    const glm::vec3 d = glm::max(hi - lo, glm::vec3(0.0f));
    return 2.0 * (double(d.x) * d.y + double(d.y) * d.z + double(d.z) * d.x);
}

} // namespace

void refitBvhPairs(std::vector<BvhPair>& pairs, const std::vector<Triangle>& triangles) {
    if (!pairs.empty())
        Refit{pairs, triangles}.entry(0);
}

double pairTreeCost(const std::vector<BvhPair>& pairs) {
    if (pairs.empty())
        return 0.0;
    double sum = 0.0;
    Bounds root;
    const auto weight = [](uint32_t child) {
        const uint32_t count = child & WF_BVH_MAX_LEAF_COUNT;
        return count > 0 ? double(count) : 1.0;
    };
    for (size_t i = 0; i < pairs.size(); ++i) {
        const BvhPair& p = pairs[i];
        if (p.child0 != WF_BVH_NO_CHILD)
            sum += weight(p.child0) * area(p.lo0, p.hi0);
        if (p.child1 != WF_BVH_NO_CHILD)
            sum += weight(p.child1) * area(p.lo1, p.hi1);
    }
    const BvhPair& top = pairs.front();
    if (top.child0 != WF_BVH_NO_CHILD) {
        root.grow(top.lo0);
        root.grow(top.hi0);
    }
    if (top.child1 != WF_BVH_NO_CHILD) {
        root.grow(top.lo1);
        root.grow(top.hi1);
    }
    const double rootArea = root.empty() ? 0.0 : area(root.lo, root.hi);
    return rootArea > 0.0 ? sum / rootArea : 0.0;
}

} // namespace wf
