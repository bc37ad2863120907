// Top-down binned SAH (Wald 2007): per node, centroids are binned on all three axes and the
// cheapest bin boundary wins. Triangles are moved as 32-byte boxes (PrimRef) rather than
// through an index array, so every pass streams memory; the triangles are permuted once at
// the end. Nodes are emitted depth-first, which gives "left child = next node" for free.
#include "scene/bvh_builder.h"

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "errors.h"
#include "shaders/shared/bvh_traverse.h"

namespace wf {
namespace {

static_assert(BVH_MAX_DEPTH + 1 <= WF_BVH_STACK_SIZE, "traversal stack too small for the tree");

using glm::vec3;

struct Bounds {
    vec3 lo{FLT_MAX};
    vec3 hi{-FLT_MAX};

    void grow(vec3 p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Bounds& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    // Half the surface area: SAH only ever uses ratios. In double, as float products overflow
    // for extents past ~1e19 and drop the small terms that separate candidate splits.
    double halfArea() const {
        if (lo.x > hi.x) {
            return 0.0;
        }
        double x = double(hi.x) - lo.x, y = double(hi.y) - lo.y, z = double(hi.z) - lo.z;
        return x * y + y * z + z * x;
    }
};

struct PrimRef {
    vec3 lo;
    std::uint32_t index; // into the caller's triangle array
    vec3 hi;
    std::uint32_t pad;

    vec3 centroid() const { return 0.5f * (lo + hi); }
};

struct Split {
    int axis = -1;
    std::uint32_t bin = 0; // first bin on the right side
    double cost = std::numeric_limits<double>::infinity();
};

// Median splits needed to get n triangles down to leaves of `leafSize`: smallest k with
// n <= leafSize * 2^k. Used to keep every subtree finishable within the depth limit.
std::uint32_t medianLevels(std::uint32_t n, std::uint32_t leafSize) {
    std::uint32_t levels = 0;
    for (std::uint64_t cap = leafSize; cap < n; cap *= 2) {
        ++levels;
    }
    return levels;
}

class Builder {
public:
    static constexpr std::uint32_t MAX_BINS = 64;

    Builder(std::vector<PrimRef>& refs, std::vector<BvhNode>& nodes, const BvhBuildOptions& opts,
            BvhBuildStats& stats)
        : refs_(refs), nodes_(nodes), opts_(opts), stats_(stats) {}

    std::uint32_t build(std::uint32_t begin, std::uint32_t end, std::uint32_t depth) {
        Bounds box, centroids;
        for (std::uint32_t i = begin; i < end; ++i) {
            box.grow(refs_[i].lo);
            box.grow(refs_[i].hi);
            centroids.grow(refs_[i].centroid());
        }
        auto nodeIndex = std::uint32_t(nodes_.size());
        nodes_.push_back(BvhNode{box.lo, begin, box.hi, end - begin});
        stats_.maxDepth = std::max(stats_.maxDepth, depth);

        std::uint32_t mid = chooseSplit(begin, end, depth, box, centroids);
        if (mid == begin) {
            ++stats_.leafCount;
            return nodeIndex;
        }
        [[maybe_unused]] std::uint32_t left = build(begin, mid, depth + 1);
        assert(left == nodeIndex + 1);
        std::uint32_t right = build(mid, end, depth + 1);
        nodes_[nodeIndex].rightOrFirst = right;
        nodes_[nodeIndex].count = 0;
        return nodeIndex;
    }

private:
    // Partitions [begin, end) and returns the boundary, or `begin` for "make a leaf".
    std::uint32_t chooseSplit(std::uint32_t begin, std::uint32_t end, std::uint32_t depth,
                              const Bounds& box, const Bounds& centroids) {
        std::uint32_t n = end - begin;
        // Past maxDepth only when maxDepth is too small for the scene (medianLevels keeps every
        // subtree finishable otherwise); an oversized leaf is then the only choice.
        if (n <= opts_.maxLeafSize || depth >= opts_.maxDepth) {
            return begin;
        }
        vec3 extent = centroids.hi - centroids.lo;
        if (extent.x <= 0.0f && extent.y <= 0.0f && extent.z <= 0.0f) {
            // All centroids coincide (duplicates, or degenerate triangles at one point): no
            // plane separates them, so halve by index to keep the tree balanced.
            return n <= opts_.maxSahLeafSize ? begin : begin + n / 2;
        }
        int axis = extent.x >= extent.y && extent.x >= extent.z ? 0
                   : extent.y >= extent.z                        ? 1
                                                                 : 2;
        double area = box.halfArea();
        if (area <= 0.0) {
            return medianSplit(begin, end, axis); // a line of triangles: SAH costs are all 0
        }
        Split split = findSahSplit(begin, end, centroids, area);
        if (split.axis < 0) {
            return medianSplit(begin, end, axis); // no axis could be binned
        }
        double leafCost = double(opts_.intersectionCost) * n * area;
        if (split.cost >= leafCost && n <= opts_.maxSahLeafSize) {
            return begin;
        }
        std::uint32_t mid = partitionAt(begin, end, centroids, split);
        // A lopsided split near the depth limit could leave a child that median splits can
        // no longer finish in time; fall back to the median while there is room.
        std::uint32_t childRoom = opts_.maxDepth - depth - 1;
        if (medianLevels(mid - begin, opts_.maxLeafSize) > childRoom ||
            medianLevels(end - mid, opts_.maxLeafSize) > childRoom) {
            return medianSplit(begin, end, axis);
        }
        return mid;
    }

    std::uint32_t binOf(float c, float lo, float scale) const {
        auto b = std::int64_t((c - lo) * scale);
        return std::uint32_t(std::clamp<std::int64_t>(b, 0, opts_.binCount - 1));
    }

    // Bins per unit of centroid extent on axis a, or 0 where the axis cannot be binned (no
    // extent, or one so tiny that bins / extent overflows).
    float binScale(const Bounds& centroids, int a) const {
        float extent = centroids.hi[a] - centroids.lo[a];
        float scale = extent > 0.0f ? float(opts_.binCount) / extent : 0.0f;
        return std::isfinite(scale) ? scale : 0.0f;
    }

    Split findSahSplit(std::uint32_t begin, std::uint32_t end, const Bounds& centroids,
                       double nodeArea) {
        const std::uint32_t bins = opts_.binCount;
        const vec3 scale(binScale(centroids, 0), binScale(centroids, 1), binScale(centroids, 2));
        Bounds binBox[3][MAX_BINS];
        std::uint32_t binCount[3][MAX_BINS] = {};
        for (std::uint32_t i = begin; i < end; ++i) {
            vec3 c = refs_[i].centroid();
            for (int a = 0; a < 3; ++a) {
                if (scale[a] > 0.0f) {
                    std::uint32_t b = binOf(c[a], centroids.lo[a], scale[a]);
                    binBox[a][b].grow(refs_[i].lo);
                    binBox[a][b].grow(refs_[i].hi);
                    ++binCount[a][b];
                }
            }
        }
        // Costs stay multiplied by the node's area, so a zero-area node never divides by it.
        const double ct = opts_.traversalCost, ci = opts_.intersectionCost;
        Split best;
        for (int a = 0; a < 3; ++a) {
            if (!(scale[a] > 0.0f)) {
                continue;
            }
            double rightCost[MAX_BINS] = {}; // area * count over bins [b, bins)
            std::uint32_t rightN[MAX_BINS] = {};
            Bounds acc;
            std::uint32_t count = 0;
            for (std::uint32_t b = bins - 1; b > 0; --b) {
                acc.grow(binBox[a][b]);
                count += binCount[a][b];
                rightCost[b] = acc.halfArea() * count;
                rightN[b] = count;
            }
            acc = Bounds{};
            count = 0;
            for (std::uint32_t b = 1; b < bins; ++b) {
                acc.grow(binBox[a][b - 1]);
                count += binCount[a][b - 1];
                if (count == 0 || rightN[b] == 0) {
                    continue;
                }
                double cost = ct * nodeArea + ci * (acc.halfArea() * count + rightCost[b]);
                if (cost < best.cost) {
                    best = Split{a, b, cost};
                }
            }
        }
        return best;
    }

    std::uint32_t partitionAt(std::uint32_t begin, std::uint32_t end, const Bounds& centroids,
                              const Split& split) {
        int a = split.axis;
        float lo = centroids.lo[a];
        float scale = binScale(centroids, a);
        // Same binOf as the binning pass, so both sides are exactly the counted ones.
        auto it = std::partition(refs_.begin() + begin, refs_.begin() + end,
                                 [&](const PrimRef& r) {
                                     return binOf(r.centroid()[a], lo, scale) < split.bin;
                                 });
        return std::uint32_t(it - refs_.begin());
    }

    std::uint32_t medianSplit(std::uint32_t begin, std::uint32_t end, int axis) {
        std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(refs_.begin() + begin, refs_.begin() + mid, refs_.begin() + end,
                         [axis](const PrimRef& x, const PrimRef& y) {
                             return x.centroid()[axis] < y.centroid()[axis];
                         });
        return mid;
    }

    std::vector<PrimRef>& refs_;
    std::vector<BvhNode>& nodes_;
    const BvhBuildOptions& opts_;
    BvhBuildStats& stats_;
};

// Expected cost of a ray that hits the root box: each node is entered with probability
// area / rootArea (a point or line scene has no area: every node then counts fully).
double sahCost(const std::vector<BvhNode>& nodes, const BvhBuildOptions& opts) {
    auto areaOf = [](const BvhNode& n) {
        Bounds b;
        b.grow(n.lo);
        b.grow(n.hi);
        return n.lo.x <= n.hi.x ? b.halfArea() : 0.0;
    };
    double rootArea = areaOf(nodes[0]);
    double cost = 0.0;
    for (const BvhNode& n : nodes) {
        double ratio = rootArea > 0.0 ? areaOf(n) / rootArea : 1.0;
        cost += ratio * (n.count > 0 ? opts.intersectionCost * n.count : opts.traversalCost);
    }
    return cost;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

BvhBuildStats buildBvh(std::vector<Triangle>& triangles, std::vector<BvhNode>& nodes,
                       const BvhBuildOptions& optsIn) {
    auto start = std::chrono::steady_clock::now();
    BvhBuildOptions opts = optsIn;
    opts.maxLeafSize = std::max(opts.maxLeafSize, 1u);
    opts.maxSahLeafSize = std::max(opts.maxSahLeafSize, opts.maxLeafSize);
    opts.binCount = std::clamp(opts.binCount, 2u, Builder::MAX_BINS);
    assert(opts.maxDepth <= BVH_MAX_DEPTH && "traversal's stack would overflow");
    opts.maxDepth = std::min(opts.maxDepth, BVH_MAX_DEPTH);
    assert(triangles.size() < WF_NO_TRIANGLE);

    BvhBuildStats stats;
    nodes.clear();
    auto n = std::uint32_t(triangles.size());
    if (n == 0) {
        // Inverted box and no triangles: pairBvhNodes gives it no children.
        nodes.push_back(BvhNode{vec3(FLT_MAX), 0, vec3(-FLT_MAX), 0});
        stats.nodeCount = 1;
        stats.buildSeconds = secondsSince(start);
        return stats;
    }
    std::vector<PrimRef> refs(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const Triangle& t = triangles[i];
        refs[i] = PrimRef{glm::min(t.p0, glm::min(t.p1, t.p2)), i,
                          glm::max(t.p0, glm::max(t.p1, t.p2)), 0};
    }
    nodes.reserve(std::size_t(n) * 2 / opts.maxLeafSize + 1);
    Builder(refs, nodes, opts, stats).build(0, n, 0);
    assert(stats.maxDepth <= BVH_MAX_DEPTH);

    std::vector<Triangle> ordered(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        ordered[i] = triangles[refs[i].index];
    }
    triangles.swap(ordered);

    stats.nodeCount = std::uint32_t(nodes.size());
    stats.sahCost = sahCost(nodes, opts);
    stats.buildSeconds = secondsSince(start);
    return stats;
}

namespace {

// Packs child references (BvhPair in scene_types.h); leaves over WF_BVH_MAX_LEAF_COUNT become
// extra pair entries whose two children share the leaf's box and halve its range.
class BvhPairer {
public:
    explicit BvhPairer(const std::vector<BvhNode>& nodes)
        : nodes_(nodes), pairOf_(nodes.size(), WF_BVH_NO_CHILD) {}

    std::vector<BvhPair> pair() {
        const BvhNode& root = nodes_[0];
        if (root.count > 0 || nodes_.size() == 1) { // a leaf root, or the empty scene
            pairs_.emplace_back(); // entry 0, before any entries an oversized leaf adds
            const std::uint32_t only =
                root.count > 0 ? leafRef(root.lo, root.hi, root.rightOrFirst, root.count)
                               : WF_BVH_NO_CHILD;
            pairs_[0] = BvhPair{root.lo, only, root.hi, 0, vec3(0.0f), WF_BVH_NO_CHILD,
                                vec3(0.0f), 0};
            return std::move(pairs_);
        }
        // Interior nodes become the first entries, in depth-first order: the root's is 0.
        for (std::size_t i = 0; i < nodes_.size(); ++i)
            if (nodes_[i].count == 0)
                pairOf_[i] = std::uint32_t(pairs_.size()), pairs_.emplace_back();
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            if (nodes_[i].count > 0)
                continue;
            const std::size_t right = nodes_[i].rightOrFirst;
            const BvhPair pair{nodes_[i + 1].lo, childRef(i + 1), nodes_[i + 1].hi, 0,
                               nodes_[right].lo, childRef(right), nodes_[right].hi, 0};
            pairs_[pairOf_[i]] = pair;
        }
        return std::move(pairs_);
    }

private:
    std::uint32_t childRef(std::size_t node) {
        const BvhNode& n = nodes_[node];
        return n.count > 0 ? leafRef(n.lo, n.hi, n.rightOrFirst, n.count)
                           : pairRef(pairOf_[node]);
    }

    static std::uint32_t pairRef(std::size_t entry) {
        if (entry >= kMaxIndex)
            throw InputError("the BVH needs " + std::to_string(entry + 1) +
                             " nodes, over the traversal's limit of " + std::to_string(kMaxIndex));
        return std::uint32_t(entry) << WF_BVH_COUNT_BITS;
    }

    std::uint32_t leafRef(vec3 lo, vec3 hi, std::uint32_t first, std::uint32_t count) {
        if (std::uint64_t(first) + count >= kMaxIndex)
            throw InputError("the scene has " + std::to_string(std::uint64_t(first) + count) +
                             " triangles, over the traversal's limit of " +
                             std::to_string(kMaxIndex - 1));
        if (count <= WF_BVH_MAX_LEAF_COUNT)
            return first << WF_BVH_COUNT_BITS | count;
        const std::size_t entry = pairs_.size();
        pairs_.emplace_back();
        const std::uint32_t half = count / 2;
        const std::uint32_t low = leafRef(lo, hi, first, half);
        const std::uint32_t high = leafRef(lo, hi, first + half, count - half);
        pairs_[entry] = BvhPair{lo, low, hi, 0, lo, high, hi, 0};
        return pairRef(entry);
    }

    // Indices stay below this, so no reference can equal WF_BVH_NO_CHILD.
    static constexpr std::uint64_t kMaxIndex = (1ull << (32 - WF_BVH_COUNT_BITS)) - 1;

    const std::vector<BvhNode>& nodes_;
    std::vector<std::uint32_t> pairOf_;
    std::vector<BvhPair> pairs_;
};

} // namespace

std::vector<BvhPair> pairBvhNodes(const std::vector<BvhNode>& nodes) {
    assert(!nodes.empty() && "buildBvh always emits a root");
    return BvhPairer(nodes).pair();
}

std::uint32_t bvhStackNeed(const std::vector<BvhPair>& pairs) {
    // Children come after their parents (BvhPairer), so one backward sweep sees them first.
    std::vector<std::uint32_t> need(pairs.size(), 0);
    auto interior = [](std::uint32_t child) {
        return child != WF_BVH_NO_CHILD && (child & WF_BVH_MAX_LEAF_COUNT) == 0;
    };
    for (std::size_t i = pairs.size(); i-- > 0;) {
        const std::uint32_t children[2] = {pairs[i].child0, pairs[i].child1};
        std::uint32_t deepest = 0;
        for (const std::uint32_t child : children) {
            if (!interior(child))
                continue;
            const std::size_t entry = child >> WF_BVH_COUNT_BITS;
            assert(entry > i && entry < pairs.size() && "pair entries follow their parents");
            deepest = std::max(deepest, need[entry]);
        }
        need[i] = deepest + (interior(children[0]) && interior(children[1]) ? 1 : 0);
    }
    return pairs.empty() ? 0 : need[0];
}

} // namespace wf
