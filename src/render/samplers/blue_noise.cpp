#include "render/samplers/blue_noise.h"

#include <cmath>
#include <cstdint>

#include "errors.h"

namespace wf {
namespace {

// Binary pattern on a torus with the Gaussian-filtered "energy" of its minority pixels kept up
// to date: the tightest cluster is the set pixel of highest energy, the largest void the empty
// pixel of lowest. Energies are fixed-point integers so that the mask is the same everywhere.
// Each row remembers its extremes, so a step rescans only the rows the filter touched (ties go
// to the lowest index, as a full scan would give).
class Pattern {
public:
    Pattern(uint32_t size, double sigma)
        : size_(size), set_(size * size, 0), energy_(size * size, 0), rowCluster_(size),
          rowVoid_(size) {
        radius_ = std::min<int>(static_cast<int>(std::ceil(4.0 * sigma)), int(size) / 2);
        for (int dy = -radius_; dy <= radius_; ++dy)
            for (int dx = -radius_; dx <= radius_; ++dx)
                kernel_.push_back(std::llround(
                    std::exp(-(dx * dx + dy * dy) / (2.0 * sigma * sigma)) * double(1 << 24)));
        for (uint32_t y = 0; y < size_; ++y)
            rescanRow(y);
    }

    bool isSet(uint32_t p) const { return set_[p] != 0; }

    void toggle(uint32_t p) {
        const int64_t sign = set_[p] ? -1 : 1;
        set_[p] ^= 1;
        const int n = static_cast<int>(size_), px = int(p % size_), py = int(p / size_);
        size_t k = 0;
        for (int dy = -radius_; dy <= radius_; ++dy) {
            const int y = (py + dy + n) % n;
            for (int dx = -radius_; dx <= radius_; ++dx, ++k)
                energy_[size_t(y) * size_ + size_t((px + dx + n) % n)] += sign * kernel_[k];
        }
        for (int dy = -radius_; dy <= radius_; ++dy)
            rescanRow(uint32_t((py + dy + n) % n));
    }

    uint32_t tightestCluster() const { return extreme(rowCluster_, true); }
    uint32_t largestVoid() const { return extreme(rowVoid_, false); }

private:
    static constexpr uint32_t kNone = UINT32_MAX;

    bool better(uint32_t candidate, uint32_t best, bool highest) const {
        return best == kNone || (highest ? energy_[candidate] > energy_[best]
                                         : energy_[candidate] < energy_[best]);
    }

    void rescanRow(uint32_t y) {
        uint32_t cluster = kNone, hole = kNone;
        for (uint32_t p = y * size_; p < (y + 1) * size_; ++p) {
            if (set_[p] && better(p, cluster, true))
                cluster = p;
            if (!set_[p] && better(p, hole, false))
                hole = p;
        }
        rowCluster_[y] = cluster;
        rowVoid_[y] = hole;
    }

    uint32_t extreme(const std::vector<uint32_t>& rows, bool highest) const {
        uint32_t best = kNone;
        for (uint32_t candidate : rows)
            if (candidate != kNone && better(candidate, best, highest))
                best = candidate;
        return best;
    }

    uint32_t size_;
    int radius_;
    std::vector<uint8_t> set_;
    std::vector<int64_t> energy_;
    std::vector<int64_t> kernel_;
    std::vector<uint32_t> rowCluster_; // per row: the set pixel of highest energy, or kNone
    std::vector<uint32_t> rowVoid_;    // per row: the empty pixel of lowest energy, or kNone
};

uint64_t splitMix64(uint64_t& state) {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

} // namespace

std::vector<uint32_t> voidAndClusterMask(uint32_t size, double sigma, uint32_t seed) {
    if (size < 4 || size > 1024 || !(sigma > 0.0))
        throw InternalError("void-and-cluster: size must be 4..1024 and sigma positive");
    const uint32_t texels = size * size;
    const uint32_t initialCount = texels / 10;

    // Initial binary pattern: random minority pixels, then the tightest cluster moves into the
    // largest void until the move would undo itself.
    Pattern initial(size, sigma);
    uint64_t state = seed;
    for (uint32_t placed = 0; placed < initialCount;) {
        const uint32_t p = static_cast<uint32_t>(splitMix64(state) % texels);
        if (!initial.isSet(p)) {
            initial.toggle(p);
            ++placed;
        }
    }
    for (uint32_t step = 0; step < 16 * texels; ++step) {
        const uint32_t cluster = initial.tightestCluster();
        initial.toggle(cluster);
        const uint32_t hole = initial.largestVoid();
        initial.toggle(hole);
        if (hole == cluster)
            break;
    }

    std::vector<uint32_t> rank(texels, 0);
    // Phase 1: ranks below the initial count, removing tightest clusters from a copy.
    Pattern shrinking = initial;
    for (uint32_t r = initialCount; r-- > 0;) {
        const uint32_t cluster = shrinking.tightestCluster();
        shrinking.toggle(cluster);
        rank[cluster] = r;
    }
    // Phases 2 and 3: the rest, filling largest voids. (Ulichney's phase 3 takes the tightest
    // cluster of the inverted pattern; with a filter of constant sum that is the same pixel.)
    Pattern growing = initial;
    for (uint32_t r = initialCount; r < texels; ++r) {
        const uint32_t hole = growing.largestVoid();
        growing.toggle(hole);
        rank[hole] = r;
    }
    return rank;
}

} // namespace wf
