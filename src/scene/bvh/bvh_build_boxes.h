// The 4-float boxes the BVH builder (bvh_builder.cpp) works on: a triangle's box with its
// index (PrimRef), the bounds and areas binning and the partition compute, the bins, node
// ranges and splits, and the builder's thread fan-out. Internal to the builder.
#pragma once
#include <algorithm>
#include <bit>
#include <cfloat>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

#include <glm/glm.hpp>

namespace wf::bvh_build {

using glm::vec3;

// Four floats in one SSE/NEON register (GCC and Clang vector extensions): the builder works on
// whole boxes at a time, x, y, z and a fourth lane it keeps at zero.
using v4 = float __attribute__((vector_size(16)));
using v4i = std::int32_t __attribute__((vector_size(16)));

inline v4 vmin(v4 a, v4 b) { return a < b ? a : b; }
inline v4 vmax(v4 a, v4 b) { return a > b ? a : b; }
inline v4 toV4(vec3 v) { return v4{v.x, v.y, v.z, 0.0f}; }
inline vec3 toVec3(v4 v) { return vec3(v[0], v[1], v[2]); }

struct Bounds {
    v4 lo{FLT_MAX, FLT_MAX, FLT_MAX, 0.0f};
    v4 hi{-FLT_MAX, -FLT_MAX, -FLT_MAX, 0.0f};

    void grow(v4 p) {
        lo = vmin(lo, p);
        hi = vmax(hi, p);
    }
    void grow(vec3 p) { grow(toV4(p)); }
    void grow(const Bounds& b) {
        lo = vmin(lo, b.lo);
        hi = vmax(hi, b.hi);
    }
    // Half the surface area: SAH only ever uses ratios. In double, as float products overflow
    // for extents past ~1e19 and drop the small terms that separate candidate splits.
    double halfArea() const {
        if (lo[0] > hi[0]) {
            return 0.0;
        }
        double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
        return x * y + y * z + z * x;
    }
};

// The largest extent of a box with some area (positive, or infinite past FLT_MAX).
inline float maxExtent(const Bounds& b) {
    const v4 e = b.hi - b.lo;
    return std::max(e[0], std::max(e[1], e[2]));
}

// Half the surface area of `b` scaled by `toUnit`: in float, as the boxes are scaled to at
// most 1 on a side, so that neither overflow nor cancellation can reorder candidate splits.
inline float unitHalfArea(const Bounds& b, v4 toUnit) {
    const v4 e = (b.hi - b.lo) * toUnit; // fourth lane 0
    const v4 rotated = __builtin_shufflevector(e, e, 1, 2, 0, 3);
    const v4 products = e * rotated;
    return products[0] + products[1] + products[2];
}

// A triangle's box, 32 bytes, with its index in the caller's array in the bits of lo's fourth
// lane (masked off before any arithmetic: as a float it would be a denormal).
struct PrimRef {
    v4 lo;
    v4 hi;

    PrimRef() = default;
    PrimRef(vec3 boxLo, std::uint32_t index, vec3 boxHi)
        : lo{boxLo.x, boxLo.y, boxLo.z, std::bit_cast<float>(index)}, hi(toV4(boxHi)) {}
    std::uint32_t index() const { return std::bit_cast<std::uint32_t>(lo[3]); }
    v4 box0() const { return (v4)((v4i)lo & v4i{-1, -1, -1, 0}); } // lo, fourth lane zero
    v4 centroid() const { return 0.5f * (box0() + hi); }
};

struct Split {
    int axis = -1;
    std::uint32_t bin = 0; // first bin on the right side
    double cost = std::numeric_limits<double>::infinity();
    bool sampled = false; // binned over a sample: the sides' boxes come from the partition
};

// Median splits needed to get n triangles down to leaves of `leafSize`: smallest k with
// n <= leafSize * 2^k. Used to keep every subtree finishable within the depth limit.
inline std::uint32_t medianLevels(std::uint32_t n, std::uint32_t leafSize) {
    std::uint32_t levels = 0;
    for (std::uint64_t cap = leafSize; cap < n; cap *= 2) {
        ++levels;
    }
    return levels;
}

// Runs fn(chunk, begin, end) over [0, n) in up to `threads` contiguous chunks, one thread
// each (one chunk per 64k items at most).
template <typename Fn> void parallelChunks(std::uint32_t n, std::uint32_t threads, Fn fn) {
    const std::uint32_t chunks = std::max(1u, std::min(threads, n / 65536 + 1));
    auto start = [&](std::uint32_t k) { return std::uint32_t(std::uint64_t(n) * k / chunks); };
    std::vector<std::thread> workers;
    for (std::uint32_t k = 1; k < chunks; ++k)
        workers.emplace_back(fn, k, start(k), start(k + 1));
    fn(0u, 0u, start(1));
    for (std::thread& w : workers)
        w.join();
}

// A node's triangles: refs [begin, end), the union of their boxes and of their centroids.
struct Range {
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
    Bounds box;
    Bounds centroids;
    std::uint32_t size() const { return end - begin; }
};

struct SubtreeStats {
    std::uint32_t leafCount = 0;
    std::uint32_t maxDepth = 0;
};

// Per axis and bin: the bounds of the refs whose centroid falls in it, and their count, set up
// for the bins in use only: small nodes are most nodes, and clearing all 64 bins of each was a
// sixth of the build.
struct Bins {
    static constexpr std::uint32_t MAX = 64;
    v4 lo[3][MAX]; // v4 is trivial: only the bins in use are set up
    v4 hi[3][MAX];
    std::uint32_t count[3][MAX];

    explicit Bins(std::uint32_t bins) {
        const Bounds empty;
        for (int a = 0; a < 3; ++a)
            for (std::uint32_t b = 0; b < bins; ++b) {
                lo[a][b] = empty.lo;
                hi[a][b] = empty.hi;
                count[a][b] = 0;
            }
    }
    void add(int a, std::uint32_t b, v4 refLo, v4 refHi) {
        lo[a][b] = vmin(lo[a][b], refLo);
        hi[a][b] = vmax(hi[a][b], refHi);
        ++count[a][b];
    }
    Bounds box(int a, std::uint32_t b) const {
        Bounds bounds;
        bounds.lo = lo[a][b];
        bounds.hi = hi[a][b];
        return bounds;
    }
    void merge(const Bins& other, std::uint32_t bins) {
        for (int a = 0; a < 3; ++a)
            for (std::uint32_t b = 0; b < bins; ++b) {
                lo[a][b] = vmin(lo[a][b], other.lo[a][b]);
                hi[a][b] = vmax(hi[a][b], other.hi[a][b]);
                count[a][b] += other.count[a][b];
            }
    }
};

} // namespace wf::bvh_build
