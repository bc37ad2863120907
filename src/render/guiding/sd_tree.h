// The path guide's SD-tree on the host (Mueller, Gross and Novak 2017, "Practical Path
// Guiding"): a spatial binary tree over the scene's bounds whose leaves each hold two
// directional quadtrees of incident radiance, one frozen for sampling and one being built from
// this iteration's splats. Between training iterations the host reads the splats back,
// propagates sums, splits busy spatial leaves, re-subdivides the quadtrees where energy
// concentrates, swaps, and flattens the result into the arrays the GPU reads
// (shaders/types/guide_types.h; sampled by shaders/guiding/guide_tree.h).
#ifndef WF_RENDER_GUIDING_SD_TREE_H
#define WF_RENDER_GUIDING_SD_TREE_H

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "types/guide_types.h"

namespace wf::guiding {

// A quadtree over the unit square of directions (see guideDirToSquare). Node 0 is the root;
// child[q] == 0 marks quadrant q as a leaf.
struct DirTree {
    struct Node {
        std::array<std::uint32_t, 4> child{};
        std::array<double, 4> sum{}; // energy splatted into each quadrant (after propagate())
    };
    std::vector<Node> nodes{Node{}};

    // Adds value to the leaf quadrant holding square point x.
    void record(glm::vec2 x, double value);
    // Sets every interior quadrant's sum to its child's total, bottom-up (splats land only in
    // leaf quadrants), so each node's sums partition what was splatted below it.
    void propagate();
    double total() const;
    std::uint32_t depth() const;
    // A tree whose quadrants holding more than `threshold` of the total energy are subdivided
    // (down to maxDepth; a quadrant that was a leaf spreads its energy evenly over its four
    // parts to decide further), the rest merged into leaves; all sums zero. Propagated sums
    // expected. keepSums: the new nodes keep their source's sums instead (a coarser copy of
    // a frozen tree, when the trees outgrow their buffers).
    DirTree refined(double threshold, std::uint32_t maxDepth, bool keepSums = false) const;
};

struct SpatialLeaf {
    DirTree sampling; // frozen: what this iteration samples from (propagated)
    DirTree building; // what this iteration's splats fill
    double samples = 0.0; // splats recorded in `building`
    // The learnt BSDF share of the mixture (0: not learnt, the renderer's default), and this
    // iteration's second moments of the records under each candidate share
    // (guideFractionCandidate; see WF_GUIDE_FRACTIONS).
    float bsdfFraction = 0.0f;
    std::array<double, WF_GUIDE_FRACTIONS> moments{};
    // The records' whole-path estimates (WF_GUIDE_STAT_TOTAL): sum of squares and sum.
    double totalSquares = 0.0, totalSum = 0.0;
    // The share learnt last cuts at least kMinVarianceCut of their variance (it pays).
    bool guidePays = false;
    // Parallax (see GuideSpatialNode): the sampling quadtree's directions are seen from
    // samplingCentre to radiance radianceDistance away (0: none); the building one's from
    // buildingCentre, whose splats this iteration sum value x distance, value and the
    // records' positions (from the tree's box corner).
    glm::vec3 samplingCentre{0.0f};
    float radianceDistance = 0.0f;
    glm::vec3 buildingCentre{0.0f};
    double distanceSum = 0.0, energySum = 0.0;
    glm::dvec3 positionSum{0.0};
};

// A leaf's share below 1 pays where it cuts the variance of the whole paths' estimates
// through the leaf by at least this much: where leaves sample the guide, a sample costs
// 1.15-1.5x an unguided one (docs/guiding.md), and 1 - 1 / 1.4 = 0.3. Measured cuts (64x64
// and 128x128, 256 spp, seed 1): the narrow gap 0.45-36, the sphere near the floor
// 0.005-0.22, the glass caustic at 128x128 0-0.8 (docs/guiding.md, "2026-12-04 17:09-18:08:
// training stops where the guide does not pay").
constexpr double kMinVarianceCut = 0.3;

// The candidate share with the least second moment, or -1 where no record carried light.
int chooseBsdfFraction(const std::array<double, WF_GUIDE_FRACTIONS>& moments);

// The flattened tree as uploaded. Leaf l's quadtrees start at samplingBase[l] and
// buildingBase[l]; the building quadtrees' splat counters are 2 uints (64-bit fixed point,
// low word first) per cell, cell = node * 4 + quadrant.
struct FlatGuide {
    std::vector<gpu_types::GuideSpatialNode> spatial;
    std::vector<gpu_types::GuideDirNode> sampling;
    std::vector<gpu_types::GuideDirNode> building;
    std::vector<std::uint32_t> samplingBase, buildingBase;

    std::size_t splatCounterCount() const { return building.size() * 8; }
    std::size_t bytes() const;
};

struct SDTreeStats {
    std::size_t spatialLeaves = 0;
    std::size_t samplingNodes = 0; // directional nodes, over all leaves
    std::uint32_t maxDirDepth = 0;
    // The leaves' BSDF shares (defaultFraction where not learnt), weighted by the splats each
    // recorded in the iteration that ended last.
    double meanBsdfFraction = 0.0;
    // Leaves whose share (defaultFraction where not learnt) is below 1: where the guide samples.
    std::size_t guidedLeaves = 0;
    // Leaves whose learnt share pays (SpatialLeaf::guidePays).
    std::size_t payingLeaves = 0;
};

class SDTree {
public:
    // The box is made cubic around its centre (so halving along x, y, z in turn keeps cells
    // near-cubic) and padded a little so surfaces on its faces fall inside.
    SDTree(glm::vec3 lo, glm::vec3 hi);

    glm::vec3 boxLo() const { return lo_; }
    glm::vec3 boxSize() const { return size_; }
    // The point's position in the box, each coordinate in [0, 1].
    glm::vec3 unitPosition(glm::vec3 p) const;
    std::uint32_t leafIndexAt(glm::vec3 p) const;
    const std::vector<SpatialLeaf>& leaves() const { return leaves_; }
    SpatialLeaf& leaf(std::uint32_t i) { return leaves_[i]; }

    // One splat on the CPU (tests; the GPU splats into the flat counters instead).
    void record(glm::vec3 p, glm::vec3 direction, double value);
    // Adds the GPU's splats (counters laid out as `flat`, which must be this tree's last
    // flatten()) and per-leaf statistics (WF_GUIDE_LEAF_STATS words per leaf: the splat
    // count, then the candidate shares' 64-bit moments) into the building quadtrees.
    void addSplats(const FlatGuide& flat, const std::vector<std::uint32_t>& counters,
                   const std::vector<std::uint32_t>& leafStats);
    // Every leaf with at least minRecords splats this iteration takes the candidate BSDF
    // share whose second moment was least (share 1 where no record carried light: its
    // quadtree is then empty), and notes whether that share pays: whether it removes at
    // least kMinVarianceCut of the variance of the records' whole-path estimates (a leaf
    // with fewer records does not pay); the moments restart. Before endIteration: split
    // leaves then inherit their parent's share.
    void learnFractions(double minRecords);
    // Every leaf takes this BSDF share (1: the BSDF alone).
    void setBsdfFractions(float fraction);
    // Ends a training iteration: each leaf's frozen quadtree will be seen from the centre its
    // splats were seen from, at the energy-weighted mean distance they came from (kept where
    // none did), and the mean position of its records becomes its next building centre;
    // splits spatial leaves with more than splitThreshold splats (children copy their
    // parent's quadtrees, centres, distance and half its count, recursively; the building
    // centre moved into each child's box), then in every
    // leaf propagates the building quadtree, freezes it for sampling and starts a refined,
    // empty one (energyThreshold: the share of a leaf's energy past which a quadrant
    // subdivides).
    // No split makes more than maxLeaves leaves.
    void endIteration(double splitThreshold, double energyThreshold, std::uint32_t maxDirDepth,
                      std::size_t maxLeaves = std::size_t(1) << 14);
    // Coarsens every leaf's quadtrees (frozen ones keeping their sums) with a higher energy
    // threshold, for trees that outgrew their buffers.
    void coarsen(double energyThreshold, std::uint32_t maxDirDepth);

    FlatGuide flatten() const;
    SDTreeStats stats(float defaultFraction = 0.5f) const;
    // Whether an iteration ended (before, every leaf's guide is uniform).
    bool hasLearnt() const { return !lastSamples_.empty(); }

private:
    struct Node {
        std::uint32_t child = 0; // interior: first child (second = child + 1)
        std::uint32_t leaf = 0;  // leaf: index into leaves_
        bool isLeaf = true;
        glm::vec3 lo{0.0f}, size{0.0f}; // its box, in world units
    };
    void split(std::uint32_t node, std::uint32_t depth, double threshold, std::size_t maxLeaves);

    glm::vec3 lo_, size_;
    std::vector<Node> nodes_;
    std::vector<SpatialLeaf> leaves_;
    std::vector<double> lastSamples_; // per leaf, the splats of the iteration that ended last
};

// The paper's spatial split threshold c * sqrt(2^k) at iteration k (0-based: after the
// iteration that rendered 2^k spp), with the paper's c = 12000 records whatever the image's
// size: a leaf's quadtree needs that many records to resolve a caustic's directions
// (docs/guiding.md, "Levers, one at a time", "Spatial threshold c = 12000": c scaled down
// with the pixel count, 1000 at 64x64 and 128x128, gave smaller leaves whose guides missed
// them).
double spatialSplitThreshold(std::uint32_t iteration);

} // namespace wf::guiding

#endif
