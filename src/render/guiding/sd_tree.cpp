// The host side of the SD-tree: splats, propagation, the spatial split and the directional
// re-subdivision between training iterations, and flattening for the GPU.
#include "render/guiding/sd_tree.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "guiding/guide_tree.h"

namespace wf::guiding {

using gpu_types::GuideDirNode;
using gpu_types::GuideSpatialNode;

void DirTree::record(glm::vec2 x, double value) {
    std::uint32_t node = 0;
    for (std::uint32_t depth = 0; depth < WF_GUIDE_MAX_DIR_DEPTH; ++depth) {
        std::uint32_t xh = x.x >= 0.5f ? 1u : 0u, yh = x.y >= 0.5f ? 1u : 0u;
        std::uint32_t q = xh | (yh << 1);
        x = glm::min(2.0f * x - glm::vec2(float(xh), float(yh)), glm::vec2(WF_GUIDE_ONE_MINUS_EPS));
        std::uint32_t child = nodes[node].child[q];
        if (child == 0 || depth + 1 == WF_GUIDE_MAX_DIR_DEPTH) {
            nodes[node].sum[q] += value;
            return;
        }
        node = child;
    }
}

void DirTree::propagate() {
    // Children always sit after their parent (refined() and the root-only tree append in
    // depth-first order), so a reverse sweep sees every child's total before its parent.
    for (std::size_t i = nodes.size(); i-- > 0;) {
        for (int q = 0; q < 4; ++q) {
            std::uint32_t c = nodes[i].child[q];
            if (c != 0) {
                const auto& s = nodes[c].sum;
                nodes[i].sum[q] = s[0] + s[1] + s[2] + s[3];
            }
        }
    }
}

double DirTree::total() const {
    const auto& s = nodes[0].sum;
    return s[0] + s[1] + s[2] + s[3];
}

std::uint32_t DirTree::depth() const {
    std::vector<std::uint32_t> depthOf(nodes.size(), 1);
    std::uint32_t deepest = 1;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        deepest = std::max(deepest, depthOf[i]);
        for (std::uint32_t c : nodes[i].child)
            if (c != 0)
                depthOf[c] = depthOf[i] + 1;
    }
    return deepest;
}

DirTree DirTree::refined(double threshold, std::uint32_t maxDepth, bool keepSums) const {
    DirTree out;
    const double whole = total();
    if (!(whole > 0.0))
        return out; // nothing learnt: one uniform node
    if (keepSums)
        out.nodes[0].sum = nodes[0].sum;
    // Each entry: a node of `out`, the source sums for its quadrants, the source node (or -1
    // when the sums were spread evenly from a source leaf quadrant), and its depth.
    struct Item {
        std::uint32_t outNode;
        std::array<double, 4> sums;
        std::int64_t source;
        std::uint32_t depth;
    };
    std::vector<Item> stack{{0, nodes[0].sum, 0, 1}};
    while (!stack.empty()) {
        Item item = stack.back();
        stack.pop_back();
        for (int q = 0; q < 4; ++q) {
            if (item.depth >= maxDepth || !(item.sums[q] / whole > threshold))
                continue;
            std::uint32_t created = std::uint32_t(out.nodes.size());
            out.nodes.emplace_back();
            out.nodes[item.outNode].child[q] = created;
            if (keepSums) {
                double quarter = 0.25 * item.sums[q];
                std::int64_t c = item.source >= 0 ? nodes[size_t(item.source)].child[q] : 0;
                out.nodes[created].sum = c != 0 ? nodes[size_t(c)].sum
                                                : std::array<double, 4>{quarter, quarter,
                                                                        quarter, quarter};
            }
            std::int64_t child = item.source >= 0 ? nodes[size_t(item.source)].child[q] : 0;
            if (child != 0) {
                stack.push_back({created, nodes[size_t(child)].sum, child, item.depth + 1});
            } else {
                double quarter = 0.25 * item.sums[q];
                stack.push_back({created, {quarter, quarter, quarter, quarter}, -1,
                                 item.depth + 1});
            }
        }
    }
    return out;
}

SDTree::SDTree(glm::vec3 lo, glm::vec3 hi) {
    glm::vec3 centre = 0.5f * (lo + hi);
    float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-6f}) * 1.02f;
    lo_ = centre - glm::vec3(0.5f * extent);
    size_ = glm::vec3(extent);
    Node root;
    root.lo = lo_;
    root.size = size_;
    nodes_.push_back(root);
    leaves_.emplace_back();
    leaves_.back().buildingCentre = centre;
}

glm::vec3 SDTree::unitPosition(glm::vec3 p) const { return (p - lo_) / size_; }

std::uint32_t SDTree::leafIndexAt(glm::vec3 p) const {
    glm::vec3 u = glm::clamp(unitPosition(p), glm::vec3(0.0f), glm::vec3(WF_GUIDE_ONE_MINUS_EPS));
    std::uint32_t node = 0;
    for (std::uint32_t depth = 0; !nodes_[node].isLeaf; ++depth) {
        int axis = int(depth % 3);
        bool second = u[axis] >= 0.5f;
        u[axis] = std::min(second ? 2.0f * u[axis] - 1.0f : 2.0f * u[axis], WF_GUIDE_ONE_MINUS_EPS);
        node = nodes_[node].child + (second ? 1u : 0u);
    }
    return nodes_[node].leaf;
}

void SDTree::record(glm::vec3 p, glm::vec3 direction, double value) {
    SpatialLeaf& l = leaves_[leafIndexAt(p)];
    l.building.record(gpu_types::guideDirToSquare(direction), value);
    l.samples += 1.0;
}

void SDTree::addSplats(const FlatGuide& flat, const std::vector<std::uint32_t>& counters,
                       const std::vector<std::uint32_t>& leafStats) {
    for (std::size_t l = 0; l < leaves_.size(); ++l) {
        DirTree& tree = leaves_[l].building;
        std::uint32_t base = flat.buildingBase[l];
        for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
            for (int q = 0; q < 4; ++q) {
                std::size_t cell = (base + n) * 4 + size_t(q);
                std::uint64_t fixed = std::uint64_t(counters[2 * cell]) |
                                      (std::uint64_t(counters[2 * cell + 1]) << 32);
                tree.nodes[n].sum[q] += double(fixed) / double(WF_GUIDE_FIXED_SCALE);
            }
        }
        const std::uint32_t* stats = leafStats.data() + l * WF_GUIDE_LEAF_STATS;
        leaves_[l].samples += stats[0];
        for (std::size_t j = 0; j < WF_GUIDE_FRACTIONS; ++j) {
            std::uint64_t fixed =
                std::uint64_t(stats[1 + 2 * j]) | (std::uint64_t(stats[2 + 2 * j]) << 32);
            leaves_[l].moments[j] += double(fixed) / double(WF_GUIDE_MOMENT_SCALE);
        }
        auto sum64 = [&](std::uint32_t at) {
            return double(std::uint64_t(stats[at]) | (std::uint64_t(stats[at + 1]) << 32)) /
                   double(WF_GUIDE_MOMENT_SCALE);
        };
        leaves_[l].totalSquares += sum64(WF_GUIDE_STAT_TOTAL);
        leaves_[l].totalSum += sum64(WF_GUIDE_STAT_TOTAL_SUM);
        leaves_[l].distanceSum += sum64(WF_GUIDE_STAT_DISTANCE);
        leaves_[l].energySum += sum64(WF_GUIDE_STAT_ENERGY);
        for (std::uint32_t axis = 0; axis < 3; ++axis)
            leaves_[l].positionSum[int(axis)] += sum64(WF_GUIDE_STAT_POSITION + 2 * axis);
    }
}

int chooseBsdfFraction(const std::array<double, WF_GUIDE_FRACTIONS>& moments) {
    int best = -1;
    for (std::size_t j = 0; j < moments.size(); ++j)
        if (moments[j] > 0.0 && (best < 0 || moments[j] < moments[std::size_t(best)]))
            best = int(j);
    return best;
}

void SDTree::learnFractions(double minRecords) {
    for (SpatialLeaf& l : leaves_) {
        l.guidePays = false;
        if (l.samples >= minRecords) {
            const std::uint32_t alone = WF_GUIDE_FRACTIONS - 1u; // share 1
            const int best = chooseBsdfFraction(l.moments);
            l.bsdfFraction =
                gpu_types::guideFractionCandidate(best >= 0 ? std::uint32_t(best) : alone);
            // Sampling the guide costs its walks and its rays: it pays where it removes at
            // least kMinVarianceCut of the variance of the whole paths' estimates through the
            // leaf, not only a part of the vertex's own (where the leaf's light is mostly NEE's
            // direct light, the guide's cut is a sliver of it).
            const double variance = l.totalSquares - l.totalSum * l.totalSum / l.samples;
            l.guidePays = best >= 0 && std::uint32_t(best) != alone &&
                          l.moments[alone] - l.moments[std::size_t(best)] >=
                              kMinVarianceCut * variance;
        }
        l.moments = {};
        l.totalSquares = l.totalSum = 0.0;
    }
}

void SDTree::setBsdfFractions(float fraction) {
    for (SpatialLeaf& l : leaves_)
        l.bsdfFraction = fraction;
}

void SDTree::split(std::uint32_t node, std::uint32_t depth, double threshold,
                   std::size_t maxLeaves) {
    if (nodes_[node].isLeaf) {
        if (!(leaves_[nodes_[node].leaf].samples > threshold) ||
            depth + 1 >= WF_GUIDE_MAX_SPATIAL_DEPTH || leaves_.size() >= maxLeaves)
            return;
        std::uint32_t leafIndex = nodes_[node].leaf;
        leaves_[leafIndex].samples *= 0.5;
        SpatialLeaf copy = leaves_[leafIndex];
        std::uint32_t first = std::uint32_t(nodes_.size());
        Node a, b;
        a.leaf = leafIndex;
        b.leaf = std::uint32_t(leaves_.size());
        int axis = int(depth % 3);
        a.lo = b.lo = nodes_[node].lo;
        a.size = b.size = nodes_[node].size;
        a.size[axis] = b.size[axis] = 0.5f * nodes_[node].size[axis];
        b.lo[axis] += a.size[axis];
        leaves_.push_back(std::move(copy));
        for (const Node& n : {a, b}) {
            glm::vec3& c = leaves_[n.leaf].buildingCentre;
            c = glm::clamp(c, n.lo, n.lo + n.size);
        }
        nodes_.push_back(a);
        nodes_.push_back(b);
        nodes_[node].isLeaf = false;
        nodes_[node].child = first;
    }
    std::uint32_t child = nodes_[node].child;
    split(child, depth + 1, threshold, maxLeaves);
    split(child + 1, depth + 1, threshold, maxLeaves);
}

void SDTree::endIteration(double splitThreshold, double energyThreshold,
                          std::uint32_t maxDirDepth, std::size_t maxLeaves) {
    for (SpatialLeaf& l : leaves_) {
        l.samplingCentre = l.buildingCentre;
        if (l.energySum > 0.0)
            l.radianceDistance = float(l.distanceSum / l.energySum);
        if (l.samples > 0.0 && l.positionSum != glm::dvec3(0.0))
            l.buildingCentre = lo_ + glm::vec3(l.positionSum / l.samples);
        l.distanceSum = l.energySum = 0.0;
        l.positionSum = glm::dvec3(0.0);
    }
    split(0, 0, splitThreshold, maxLeaves);
    lastSamples_.clear();
    for (SpatialLeaf& l : leaves_) {
        lastSamples_.push_back(l.samples);
        l.building.propagate();
        DirTree next = l.building.refined(energyThreshold, maxDirDepth);
        l.sampling = std::move(l.building);
        l.building = std::move(next);
        l.samples = 0.0;
    }
}

void SDTree::coarsen(double energyThreshold, std::uint32_t maxDirDepth) {
    for (SpatialLeaf& l : leaves_) {
        l.sampling = l.sampling.refined(energyThreshold, maxDirDepth, true);
        l.building = l.sampling.refined(energyThreshold, maxDirDepth);
    }
}

FlatGuide SDTree::flatten() const {
    FlatGuide flat;
    flat.spatial.resize(nodes_.size());
    for (const SpatialLeaf& l : leaves_) {
        flat.samplingBase.push_back(std::uint32_t(flat.sampling.size()));
        flat.buildingBase.push_back(std::uint32_t(flat.building.size()));
        std::uint32_t sBase = flat.samplingBase.back(), bBase = flat.buildingBase.back();
        for (const DirTree::Node& n : l.sampling.nodes) {
            GuideDirNode g{};
            double total = n.sum[0] + n.sum[1] + n.sum[2] + n.sum[3];
            for (int q = 0; q < 4; ++q) {
                g.child[q] = n.child[q] != 0 ? sBase + n.child[q] : 0u;
                g.prob[q] = total > 0.0 ? float(n.sum[q] / total) : 0.25f;
            }
            flat.sampling.push_back(g);
        }
        for (const DirTree::Node& n : l.building.nodes) {
            GuideDirNode g{};
            for (int q = 0; q < 4; ++q)
                g.child[q] = n.child[q] != 0 ? bBase + n.child[q] : 0u;
            flat.building.push_back(g);
        }
    }
    for (std::size_t i = 0; i < nodes_.size(); ++i) {
        GuideSpatialNode& g = flat.spatial[i];
        if (nodes_[i].isLeaf) {
            g.child = WF_GUIDE_LEAF | nodes_[i].leaf;
            g.samplingRoot = flat.samplingBase[nodes_[i].leaf];
            g.buildingRoot = flat.buildingBase[nodes_[i].leaf];
            const SpatialLeaf& l = leaves_[nodes_[i].leaf];
            g.bsdfFraction = l.bsdfFraction;
            g.samplingCentre = l.samplingCentre;
            g.radianceDistance = l.radianceDistance;
            g.buildingCentre = l.buildingCentre;
        } else {
            g.child = nodes_[i].child;
        }
    }
    return flat;
}

std::size_t FlatGuide::bytes() const {
    return spatial.size() * sizeof(GuideSpatialNode) +
           (sampling.size() + building.size()) * sizeof(GuideDirNode) +
           splatCounterCount() * sizeof(std::uint32_t) + spatial.size() * sizeof(std::uint32_t);
}

SDTreeStats SDTree::stats(float defaultFraction) const {
    SDTreeStats s;
    s.spatialLeaves = leaves_.size();
    double weighted = 0.0, weights = 0.0;
    for (std::size_t i = 0; i < leaves_.size(); ++i) {
        const SpatialLeaf& l = leaves_[i];
        s.samplingNodes += l.sampling.nodes.size();
        s.maxDirDepth = std::max(s.maxDirDepth, l.sampling.depth());
        const double w = i < lastSamples_.size() ? lastSamples_[i] : 0.0;
        const float fraction = l.bsdfFraction > 0.0f ? l.bsdfFraction : defaultFraction;
        weighted += w * fraction;
        weights += w;
        if (fraction < 1.0f)
            ++s.guidedLeaves;
        if (l.guidePays)
            ++s.payingLeaves;
    }
    s.meanBsdfFraction = weights > 0.0 ? weighted / weights : defaultFraction;
    return s;
}

double spatialSplitThreshold(std::uint32_t iteration) {
    return 12000.0 * std::sqrt(std::pow(2.0, double(iteration)));
}

} // namespace wf::guiding
