// The 4-float boxes the BVH builder (bvh_builder.cpp) works on: a triangle's box with its
// index (PrimRef), and the bounds and areas binning and the partition compute. Internal to the
// builder.
#pragma once
#include <algorithm>
#include <bit>
#include <cfloat>
#include <cstdint>

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

} // namespace wf::bvh_build
