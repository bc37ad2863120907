// pairBvhNodes and bvhStackNeed (bvh_builder.h): the built tree in the layout traversal reads.
#include <algorithm>
#include <cassert>
#include <string>
#include <thread>

#include "errors.h"
#include "scene/bvh/bvh_builder.h"
#include "shaders/traversal/bvh_traverse.h"

namespace wf {

using glm::vec3;

namespace {

// Packs child references (BvhPair in scene_types.h) at the end of `pairs`, whose entries
// before are other trees' (so references are offset by the size it had), with triangle
// indices offset by `triangleBase`; leaves over WF_BVH_MAX_LEAF_COUNT become extra pair
// entries whose two children share the leaf's box and halve its range.
class BvhPairer {
public:
    BvhPairer(const std::vector<BvhNode>& nodes, std::vector<BvhPair>& pairs,
              std::uint32_t triangleBase)
        : nodes_(nodes), pairs_(pairs), triangleBase_(triangleBase),
          pairOf_(nodes.size(), WF_BVH_NO_CHILD) {}

    void pair() {
        const BvhNode& root = nodes_[0];
        const std::size_t rootEntry = pairs_.size();
        if (root.count > 0 || nodes_.size() == 1) { // a leaf root, or the empty scene
            pairs_.emplace_back(); // the root's, before any entries an oversized leaf adds
            const std::uint32_t only =
                root.count > 0 ? leafRef(root.lo, root.hi, root.rightOrFirst, root.count)
                               : WF_BVH_NO_CHILD;
            pairs_[rootEntry] = BvhPair{root.lo, only, root.hi, 0, vec3(0.0f), WF_BVH_NO_CHILD,
                                        vec3(0.0f), 0};
            return;
        }
        if (nodes_.size() >= kParallelNodes && pairInParallel())
            return;
        // Interior nodes become the first entries, in depth-first order: the root's first. (A
        // binary tree has one fewer interior node than leaves, so about half are interior:
        // reserved, as growing a table of millions by doubling copied it over and over.)
        pairs_.reserve(pairs_.size() + nodes_.size() / 2 + 1);
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
    }

private:
    // Trees this large are paired on every core: 0.09 s of a 5 M triangle two-level build
    // on one.
    static constexpr std::size_t kParallelNodes = std::size_t(1) << 16;

    // The same entries as the serial loops, in three passes over contiguous chunks of the
    // nodes: count each chunk's interior nodes (and check the limits leafRef would throw on),
    // number them from the chunk's prefix, then fill them. False, with nothing written, where
    // a leaf needs splitting or a limit is passed: the serial loops handle those.
    bool pairInParallel() {
        const std::size_t n = nodes_.size();
        const std::size_t chunks =
            std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1, 8);
        auto chunkStart = [&](std::size_t k) { return n * k / chunks; };
        struct Scan {
            std::size_t interior = 0;
            std::uint64_t leafEnd = 0; // past the last triangle any leaf holds
            bool oversized = false;
        };
        std::vector<Scan> scans(chunks);
        onChunks(chunks, [&](std::size_t k) {
            Scan scan;
            for (std::size_t i = chunkStart(k); i < chunkStart(k + 1); ++i) {
                const BvhNode& node = nodes_[i];
                if (node.count == 0) {
                    ++scan.interior;
                    continue;
                }
                scan.oversized |= node.count > WF_BVH_MAX_LEAF_COUNT;
                scan.leafEnd = std::max(scan.leafEnd, std::uint64_t(node.rightOrFirst) + node.count);
            }
            scans[k] = scan;
        });
        std::vector<std::size_t> first(chunks + 1, pairs_.size());
        std::uint64_t leafEnd = 0;
        for (std::size_t k = 0; k < chunks; ++k) {
            if (scans[k].oversized)
                return false;
            first[k + 1] = first[k] + scans[k].interior;
            leafEnd = std::max(leafEnd, scans[k].leafEnd);
        }
        if (first[chunks] >= kMaxIndex || triangleBase_ + leafEnd >= kMaxIndex)
            return false;
        pairs_.resize(first[chunks]);
        onChunks(chunks, [&](std::size_t k) {
            auto entry = std::uint32_t(first[k]);
            for (std::size_t i = chunkStart(k); i < chunkStart(k + 1); ++i)
                if (nodes_[i].count == 0)
                    pairOf_[i] = entry++;
        });
        onChunks(chunks, [&](std::size_t k) {
            for (std::size_t i = chunkStart(k); i < chunkStart(k + 1); ++i) {
                if (nodes_[i].count > 0)
                    continue;
                const std::size_t right = nodes_[i].rightOrFirst;
                pairs_[pairOf_[i]] = BvhPair{nodes_[i + 1].lo, checkedChildRef(i + 1),
                                             nodes_[i + 1].hi, 0, nodes_[right].lo,
                                             checkedChildRef(right), nodes_[right].hi, 0};
            }
        });
        return true;
    }

    // childRef for trees pairInParallel has checked: no leaf to split, every index in range.
    std::uint32_t checkedChildRef(std::size_t node) const {
        const BvhNode& n = nodes_[node];
        return n.count > 0 ? (triangleBase_ + n.rightOrFirst) << WF_BVH_COUNT_BITS | n.count
                           : pairOf_[node] << WF_BVH_COUNT_BITS;
    }

    template <typename Fn> static void onChunks(std::size_t chunks, Fn fn) {
        std::vector<std::thread> workers;
        for (std::size_t k = 1; k < chunks; ++k)
            workers.emplace_back(fn, k);
        fn(std::size_t(0));
        for (std::thread& worker : workers)
            worker.join();
    }

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
        const std::uint64_t end = std::uint64_t(triangleBase_) + first + count;
        if (end >= kMaxIndex)
            throw InputError("the scene has " + std::to_string(end) +
                             " triangles, over the traversal's limit of " +
                             std::to_string(kMaxIndex - 1));
        if (count <= WF_BVH_MAX_LEAF_COUNT)
            return (triangleBase_ + first) << WF_BVH_COUNT_BITS | count;
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
    std::vector<BvhPair>& pairs_;
    std::uint32_t triangleBase_;
    std::vector<std::uint32_t> pairOf_;
};

} // namespace

std::vector<BvhPair> pairBvhNodes(const std::vector<BvhNode>& nodes) {
    std::vector<BvhPair> pairs;
    appendBvhPairs(nodes, pairs, 0);
    return pairs;
}

std::uint32_t appendBvhPairs(const std::vector<BvhNode>& nodes, std::vector<BvhPair>& pairs,
                             std::uint32_t triangleBase) {
    assert(!nodes.empty() && "buildBvh always emits a root");
    const auto root = std::uint32_t(pairs.size());
    BvhPairer(nodes, pairs, triangleBase).pair();
    return root;
}

std::uint32_t bvhStackNeed(const std::vector<BvhPair>& pairs) {
    return bvhStackNeed(pairs, 0, pairs.size());
}

std::uint32_t bvhStackNeed(const std::vector<BvhPair>& table, std::size_t first,
                           std::size_t end) {
    // Children come after their parents (BvhPairer), so one backward sweep sees them first.
    const BvhPair* pairs = table.data() + first;
    std::vector<std::uint32_t> need(end - first, 0);
    auto interior = [](std::uint32_t child) {
        return child != WF_BVH_NO_CHILD && (child & WF_BVH_MAX_LEAF_COUNT) == 0;
    };
    for (std::size_t i = end - first; i-- > 0;) {
        const std::uint32_t children[2] = {pairs[i].child0, pairs[i].child1};
        std::uint32_t deepest = 0;
        for (const std::uint32_t child : children) {
            if (!interior(child))
                continue;
            const std::size_t entry = (child >> WF_BVH_COUNT_BITS) - first;
            assert(entry > i && entry < end - first && "pair entries follow their parents");
            deepest = std::max(deepest, need[entry]);
        }
        need[i] = deepest + (interior(children[0]) && interior(children[1]) ? 1 : 0);
    }
    return need.empty() ? 0 : need[0];
}

} // namespace wf
