// Top-down binned SAH (Wald 2007): per node, centroids are binned on all three axes and the
// cheapest bin boundary wins; large nodes are binned over a sample of their triangles, and
// subtrees run on all cores. Triangles are moved as 32-byte boxes (PrimRef) rather than
// through an index array, so every pass streams memory; the triangles are permuted once at
// the end. Nodes are emitted depth-first, which gives "left child = next node" for free.
// The boxes, bins and ranges it works on are bvh_build_boxes.h's; the Builder class below is
// one recursive procedure (bin, choose, partition, recurse) and reads best whole.
#include "scene/bvh/bvh_builder.h"

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <memory>
#include <thread>

#include <atomic>

#include "errors.h"
#include "scene/bvh/bvh_build_boxes.h"
#include "shaders/traversal/bvh_traverse.h"

namespace wf {
namespace {

static_assert(BVH_MAX_DEPTH + 1 <= WF_BVH_STACK_SIZE, "traversal stack too small for the tree");

using glm::vec3;
using bvh_build::Bins;
using bvh_build::Bounds; // not wf::Bounds (scene.h): 4-float vectors
using bvh_build::maxExtent;
using bvh_build::medianLevels;
using bvh_build::parallelChunks;
using bvh_build::PrimRef;
using bvh_build::Range;
using bvh_build::Split;
using bvh_build::SubtreeStats;
using bvh_build::toV4;
using bvh_build::toVec3;
using bvh_build::unitHalfArea;
using bvh_build::v4;
using bvh_build::v4i;
using bvh_build::vmax;
using bvh_build::vmin;

// The tree is built top-down; a node's two subtrees go to two threads while spare threads
// remain (each into its own node array, appended in depth-first order afterwards, so the tree
// is the same whatever the thread count). A node costs two passes over its refs: binning,
// which also gives the children's boxes, and the partition, which also gives their centroid
// bounds; a large node is binned over a sample, so its partition gathers the boxes too.
class Builder {
public:
    Builder(PrimRef* refs, const BvhBuildOptions& opts, std::uint32_t threads)
        : refs_(refs), opts_(opts), spareThreads_(int(threads) - 1) {}

    void build(const Range& range, std::uint32_t depth, std::vector<BvhNode>& out,
               SubtreeStats& stats) {
        const auto nodeIndex = std::uint32_t(out.size());
        out.push_back(BvhNode{toVec3(range.box.lo), range.begin, toVec3(range.box.hi), range.size()});
        stats.maxDepth = std::max(stats.maxDepth, depth);
        Range left, right;
        if (!chooseSplit(range, depth, left, right)) {
            ++stats.leafCount;
            return;
        }
        std::uint32_t rightIndex;
        if (range.size() >= kSpawnMin && takeThread()) {
            // The worker builds the right subtree into an array of its own, appended after the
            // left one, which this thread builds in place: only the right half is copied. The
            // worker hands its thread back as soon as it is done, so that a thread still busy
            // with a larger subtree can give a part of it away.
            std::vector<BvhNode> rightNodes;
            rightNodes.reserve(2 * std::size_t(right.size()) / opts_.maxLeafSize + 1);
            SubtreeStats rightStats;
            std::thread worker([&] {
                build(right, depth + 1, rightNodes, rightStats);
                spareThreads_.fetch_add(1);
            });
            build(left, depth + 1, out, stats);
            worker.join();
            rightIndex = std::uint32_t(out.size());
            append(out, rightNodes);
            stats.leafCount += rightStats.leafCount;
            stats.maxDepth = std::max(stats.maxDepth, rightStats.maxDepth);
        } else {
            build(left, depth + 1, out, stats);
            rightIndex = std::uint32_t(out.size());
            build(right, depth + 1, out, stats);
        }
        out[nodeIndex].rightOrFirst = rightIndex;
        out[nodeIndex].count = 0;
    }

    Range rootRange(std::uint32_t n, std::uint32_t threads) const {
        std::vector<Range> parts(threads);
        parallelChunks(n, threads, [&](std::uint32_t chunk, std::uint32_t begin,
                                       std::uint32_t end) { parts[chunk] = boundsOf(begin, end); });
        Range root{0, n, {}, {}};
        for (const Range& part : parts) {
            root.box.grow(part.box);
            root.centroids.grow(part.centroids);
        }
        return root;
    }

private:
    // Subtrees this large or larger may go to another thread; binning passes this large or
    // larger are split over spare threads.
    static constexpr std::uint32_t kSpawnMin = 16384;
    // Nodes this large or larger are binned over a sample of kSampleBlocks blocks of
    // kSampleBlock refs: the top levels cost one pass over their refs, not two. With 8192 refs
    // the SAH cost and the traversal model's cost (bvh_tuning.h) of the scaling scenes' trees
    // stayed within 0.3% of exact binning; 4096 gave -5% to +3.4%, by chance.
    static constexpr std::uint32_t kSampledBinMin = 1u << 14;
    static constexpr std::uint32_t kSampleBlock = 16;
    static constexpr std::uint32_t kSampleBlocks = 512;
    static constexpr std::uint32_t kRefsPerExtraBin = 4;
    static constexpr std::uint32_t kTwoBinSetsMin = 256; // below, a second set costs more

    bool takeThread() {
        int spare = spareThreads_.load();
        while (spare > 0)
            if (spareThreads_.compare_exchange_weak(spare, spare - 1))
                return true;
        return false;
    }

    // Appends a subtree built with indices from 0, moving its interior references along.
    static void append(std::vector<BvhNode>& out, const std::vector<BvhNode>& subtree) {
        const auto base = std::uint32_t(out.size());
        out.reserve(out.size() + subtree.size());
        for (BvhNode node : subtree) {
            if (node.count == 0)
                node.rightOrFirst += base;
            out.push_back(node);
        }
    }

    Range boundsOf(std::uint32_t begin, std::uint32_t end) const {
        Range r{begin, end, {}, {}};
        for (std::uint32_t i = begin; i < end; ++i) {
            r.box.grow(refs_[i].box0());
            r.box.grow(refs_[i].hi);
            r.centroids.grow(refs_[i].centroid());
        }
        return r;
    }

    // At `mid`, both sides' bounds by a pass over each (the rare splits SAH did not choose).
    bool splitAt(const Range& range, std::uint32_t mid, Range& left, Range& right) const {
        left = boundsOf(range.begin, mid);
        right = boundsOf(mid, range.end);
        return true;
    }

    // Splits `range` into `left` and `right` (false: make it a leaf).
    bool chooseSplit(const Range& range, std::uint32_t depth, Range& left, Range& right) {
        const std::uint32_t begin = range.begin, end = range.end, n = range.size();
        // Past maxDepth only when maxDepth is too small for the scene (medianLevels keeps every
        // subtree finishable otherwise); an oversized leaf is then the only choice.
        if (n <= opts_.maxLeafSize || depth >= opts_.maxDepth)
            return false;
        const Bounds& centroids = range.centroids;
        const v4 extent = centroids.hi - centroids.lo;
        if (extent[0] <= 0.0f && extent[1] <= 0.0f && extent[2] <= 0.0f) {
            // All centroids coincide (duplicates, or degenerate triangles at one point): no
            // plane separates them, so halve by index to keep the tree balanced.
            return n > opts_.maxSahLeafSize && splitAt(range, begin + n / 2, left, right);
        }
        int axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0
                   : extent[1] >= extent[2]                         ? 1
                                                                    : 2;
        double area = range.box.halfArea();
        if (area <= 0.0) // a line of triangles: SAH costs are all 0
            return splitAt(range, medianSplit(begin, end, axis), left, right);
        Bounds leftBox, rightBox;
        Split split = findSahSplit(range, leftBox, rightBox);
        if (split.axis < 0) // no axis could be binned
            return splitAt(range, medianSplit(begin, end, axis), left, right);
        if (split.cost >= double(opts_.intersectionCost) * n && n <= opts_.maxSahLeafSize)
            return false;
        const std::uint32_t mid = split.sampled ? partitionAt<true>(range, split, left, right)
                                                : partitionAt<false>(range, split, left, right);
        // A lopsided split near the depth limit could leave a child that median splits can
        // no longer finish in time; fall back to the median while there is room.
        std::uint32_t childRoom = opts_.maxDepth - depth - 1;
        if (medianLevels(mid - begin, opts_.maxLeafSize) > childRoom ||
            medianLevels(end - mid, opts_.maxLeafSize) > childRoom)
            return splitAt(range, medianSplit(begin, end, axis), left, right);
        left.begin = begin;
        left.end = mid;
        right.begin = mid;
        right.end = end;
        if (!split.sampled) {
            left.box = leftBox;
            right.box = rightBox;
        }
        return true;
    }

    // Bins for a node of n refs: fewer for small nodes, whose fixed cost (clearing the bins,
    // sweeping them) would otherwise outweigh binning their refs (Embree does the same). One
    // bin per 4 refs keeps the SAH cost within 0.2% of 32 bins everywhere; one per 20 cost
    // 1.3% on a triangle soup for no measurable speed.
    std::uint32_t binsFor(std::uint32_t n) const {
        return opts_.fewerBinsForSmallNodes ? std::min(opts_.binCount, 4u + n / kRefsPerExtraBin)
                                            : opts_.binCount;
    }

    static std::uint32_t binOf(float c, float lo, float scale, std::uint32_t bins) {
        return std::uint32_t(std::min(std::max((c - lo) * scale, 0.0f), float(bins - 1)));
    }

    // Bins per unit of centroid extent on axis a, or 0 where the axis cannot be binned (no
    // extent, or one so tiny that bins / extent overflows).
    static float binScale(const Bounds& centroids, int a, std::uint32_t bins) {
        float extent = centroids.hi[a] - centroids.lo[a];
        float scale = extent > 0.0f ? float(bins) / extent : 0.0f;
        return std::isfinite(scale) ? scale : 0.0f;
    }

    // All three axes' bins of a ref at once: (centroid - lo) x scale, clamped to the bins and
    // truncated, lane by lane as binOf does it (so the partition agrees bit for bit). An axis
    // that cannot be binned has scale 0, so all its refs land in bin 0 and are never read.
    // Consecutive refs of a mesh mostly fall in the same bins, so even and odd refs go to two
    // sets of bins: one set's load-min-store chains would wait on each other.
    void binRefs(std::uint32_t begin, std::uint32_t end, const Bounds& centroids, v4 scale,
                 std::uint32_t binCount, Bins& bins) const {
        const v4 last = v4{1.0f, 1.0f, 1.0f, 0.0f} * float(binCount - 1);
        auto binOfRef = [&](const PrimRef& r) {
            return __builtin_convertvector(
                vmin(vmax((r.centroid() - centroids.lo) * scale, v4{}), last), v4i);
        };
        auto add = [](Bins& to, v4i b, const PrimRef& r) {
            const v4 lo = r.box0();
            to.add(0, b[0], lo, r.hi);
            to.add(1, b[1], lo, r.hi);
            to.add(2, b[2], lo, r.hi);
        };
        std::uint32_t i = begin;
        if (end - begin >= kTwoBinSetsMin) {
            Bins odd(binCount);
            for (; i + 1 < end; i += 2) {
                const v4i b0 = binOfRef(refs_[i]), b1 = binOfRef(refs_[i + 1]);
                add(bins, b0, refs_[i]);
                add(odd, b1, refs_[i + 1]);
            }
            bins.merge(odd, binCount);
        }
        for (; i < end; ++i)
            add(bins, binOfRef(refs_[i]), refs_[i]);
    }

    // The cheapest bin boundary on any axis, with the boxes of the two sides it makes.
    Split findSahSplit(const Range& range, Bounds& leftBox, Bounds& rightBox) {
        const std::uint32_t bins = binsFor(range.size());
        const Bounds& centroids = range.centroids;
        const v4 scale{binScale(centroids, 0, bins), binScale(centroids, 1, bins),
                       binScale(centroids, 2, bins), 0.0f};
        Bins binned(bins);
        const bool sampled = range.size() >= kSampledBinMin;
        if (sampled) {
            // Evenly spaced blocks of consecutive refs (so each block costs a few cache lines).
            const std::uint64_t span = range.size() - kSampleBlock;
            for (std::uint32_t k = 0; k < kSampleBlocks; ++k) {
                const auto first = range.begin + std::uint32_t(span * k / (kSampleBlocks - 1));
                binRefs(first, first + kSampleBlock, centroids, scale, bins, binned);
            }
        } else {
            binRefs(range.begin, range.end, centroids, scale, bins, binned);
        }
        // Areas in float, of boxes scaled to the node's largest extent (so none overflows),
        // with the three axes' sweeps interleaved: three independent chains of min and max.
        const v4 toUnit = v4{1.0f, 1.0f, 1.0f, 0.0f} / maxExtent(range.box);
        // Left and right area x count, over bins [0, b) and [b, bins); entries 1 .. bins-1 are
        // written before they are read, so they are left uninitialised (clearing them per node
        // was measurable).
        float cost[3][Bins::MAX];
        std::uint32_t rightN[3][Bins::MAX];
        Bounds acc[3];
        std::uint32_t count[3] = {0, 0, 0};
        for (std::uint32_t b = bins - 1; b > 0; --b)
            for (int a = 0; a < 3; ++a) {
                acc[a].lo = vmin(acc[a].lo, binned.lo[a][b]);
                acc[a].hi = vmax(acc[a].hi, binned.hi[a][b]);
                count[a] += binned.count[a][b];
                cost[a][b] = unitHalfArea(acc[a], toUnit) * float(count[a]);
                rightN[a][b] = count[a];
            }
        for (int a = 0; a < 3; ++a) {
            acc[a] = Bounds{};
            count[a] = 0;
        }
        for (std::uint32_t b = 1; b < bins; ++b)
            for (int a = 0; a < 3; ++a) {
                acc[a].lo = vmin(acc[a].lo, binned.lo[a][b - 1]);
                acc[a].hi = vmax(acc[a].hi, binned.hi[a][b - 1]);
                count[a] += binned.count[a][b - 1];
                cost[a][b] = count[a] == 0 || rightN[a][b] == 0
                                 ? INFINITY
                                 : cost[a][b] + unitHalfArea(acc[a], toUnit) * float(count[a]);
            }
        // Axis by axis, the first of equal costs wins: the same choice whatever the order
        // above. An axis that cannot be binned holds every ref in bin 0, so all its costs are
        // infinite.
        Split best;
        float bestCost = INFINITY;
        for (int a = 0; a < 3; ++a)
            for (std::uint32_t b = 1; b < bins; ++b)
                if (cost[a][b] < bestCost) {
                    bestCost = cost[a][b];
                    best = Split{a, b, 0.0};
                }
        if (best.axis < 0)
            return best;
        // Expected cost of a ray entering the node, in units of one triangle test.
        const float nodeArea = unitHalfArea(range.box, toUnit);
        const float countScale = sampled ? float(range.size()) / (kSampleBlocks * kSampleBlock) : 1.0f;
        best.cost = opts_.traversalCost + opts_.intersectionCost * bestCost * countScale / nodeArea;
        best.sampled = sampled;
        if (sampled)
            return best;
        for (std::uint32_t b = 0; b < best.bin; ++b)
            leftBox.grow(binned.box(best.axis, b));
        for (std::uint32_t b = best.bin; b < bins; ++b)
            rightBox.grow(binned.box(best.axis, b));
        return best;
    }

    // Moves the refs left of the split's plane to the front (with the same binOf as binning,
    // so that both sides are exactly the counted ones), gathering each side's centroid bounds
    // on the way, and their boxes where binning did not give them.
    template <bool withBoxes>
    std::uint32_t partitionAt(const Range& range, const Split& split, Range& left, Range& right) {
        const int a = split.axis;
        const float lo = range.centroids.lo[a];
        const std::uint32_t bins = binsFor(range.size());
        const float scale = binScale(range.centroids, a, bins);
        auto isLeft = [&](const PrimRef& r) {
            return binOf(r.centroid()[a], lo, scale, bins) < split.bin;
        };
        auto add = [](Range& side, const PrimRef& r) {
            side.centroids.grow(r.centroid());
            if constexpr (withBoxes) {
                side.box.grow(r.box0());
                side.box.grow(r.hi);
            }
        };
        // A two-ended partition. (Branch-free ones through a scratch array, for all nodes or
        // for small ones only, were no faster: more instructions than mispredictions saved.)
        std::uint32_t i = range.begin, j = range.end;
        for (;;) {
            while (i < j && isLeft(refs_[i]))
                add(left, refs_[i++]);
            while (i < j && !isLeft(refs_[j - 1]))
                add(right, refs_[--j]);
            if (i >= j)
                break;
            std::swap(refs_[i], refs_[j - 1]);
            add(left, refs_[i++]);
            add(right, refs_[--j]);
        }
        return i;
    }

    std::uint32_t medianSplit(std::uint32_t begin, std::uint32_t end, int axis) {
        std::uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(refs_ + begin, refs_ + mid, refs_ + end,
                         [axis](const PrimRef& x, const PrimRef& y) {
                             return x.centroid()[axis] < y.centroid()[axis];
                         });
        return mid;
    }

    PrimRef* refs_;
    const BvhBuildOptions& opts_;
    std::atomic<int> spareThreads_;
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
                       const BvhBuildOptions& opts) {
    return buildBvh(triangles.data(), triangles.size(), nodes, opts);
}

BvhBuildStats buildBvh(Triangle* triangles, std::size_t count, std::vector<BvhNode>& nodes,
                       const BvhBuildOptions& optsIn) {
    auto start = std::chrono::steady_clock::now();
    BvhBuildOptions opts = optsIn;
    opts.maxLeafSize = std::max(opts.maxLeafSize, 1u);
    opts.maxSahLeafSize = std::max(opts.maxSahLeafSize, opts.maxLeafSize);
    opts.binCount = std::clamp(opts.binCount, 2u, Bins::MAX);
    assert(opts.maxDepth <= BVH_MAX_DEPTH && "traversal's stack would overflow");
    opts.maxDepth = std::min(opts.maxDepth, BVH_MAX_DEPTH);
    assert(count < WF_NO_TRIANGLE);

    BvhBuildStats stats;
    nodes.clear();
    auto n = std::uint32_t(count);
    if (n == 0) {
        // Inverted box and no triangles: pairBvhNodes gives it no children.
        nodes.push_back(BvhNode{vec3(FLT_MAX), 0, vec3(-FLT_MAX), 0});
        stats.nodeCount = 1;
        stats.buildSeconds = secondsSince(start);
        return stats;
    }
    const std::uint32_t threads =
        opts.threads > 0 ? opts.threads : std::max(1u, std::thread::hardware_concurrency());
    // One scratch, uninitialised, serves the build's refs and then the reordering (the
    // triangles and their leaf-order sources): the first touch of a page is what costs, a
    // tenth of the build at 5 M triangles. (Asking for transparent huge pages made it slower
    // on these virtual machines: 1.4 s against 0.9 s at 5 M; the host backs each anew.)
    static_assert(sizeof(PrimRef) <= sizeof(Triangle) && alignof(PrimRef) <= alignof(std::max_align_t));
    const auto scratch = std::make_unique_for_overwrite<std::byte[]>(
        (sizeof(Triangle) + sizeof(std::uint32_t)) * std::size_t(n));
    auto* refs = reinterpret_cast<PrimRef*>(scratch.get());
    parallelChunks(n, threads, [&](std::uint32_t, std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i) {
            const Triangle& t = triangles[i];
            refs[i] = PrimRef(glm::min(t.p0, glm::min(t.p1, t.p2)), i,
                              glm::max(t.p0, glm::max(t.p1, t.p2)));
        }
    });
    // Address space only (pages are touched as nodes are written); a reallocation would copy.
    nodes.reserve(std::size_t(n) * 2);
    stats.threads = threads;
    Builder builder(refs, opts, threads);
    SubtreeStats subtree;
    builder.build(builder.rootRange(n, threads), 0, nodes, subtree);
    stats.leafCount = subtree.leafCount;
    stats.maxDepth = subtree.maxDepth;
    assert(stats.maxDepth <= BVH_MAX_DEPTH);

    // Into leaf order: the triangles go to scratch and are gathered back into their own
    // array, whose pages are in memory already. (Following the permutation's cycles in place
    // saves the scratch but, single-threaded and latency-bound, took 0.5-0.8 s longer at 5 M
    // triangles; the scratch is not at the peak of host memory, which is the load.)
    auto* source = reinterpret_cast<std::uint32_t*>(scratch.get() + sizeof(Triangle) * n);
    auto* original = reinterpret_cast<Triangle*>(scratch.get()); // over the refs, once read
    parallelChunks(n, threads, [&](std::uint32_t, std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i)
            source[i] = refs[i].index();
    });
    parallelChunks(n, threads, [&](std::uint32_t, std::uint32_t begin, std::uint32_t end) {
        std::copy(triangles + begin, triangles + end, original + begin);
    });
    parallelChunks(n, threads, [&](std::uint32_t, std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i)
            triangles[i] = original[source[i]];
    });

    stats.nodeCount = std::uint32_t(nodes.size());
    stats.sahCost = sahCost(nodes, opts);
    stats.buildSeconds = secondsSince(start);
    return stats;
}

} // namespace wf
