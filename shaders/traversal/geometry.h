// Ray-primitive intersection and robust ray spawning, shared by the intersect/shadow passes
// (GLSL) and the CPU BVH and its tests (C++). Error bounds follow pbrt-v4 (section 6.8): no
// fixed epsilons, so scenes behave the same at any scale and distance from the origin.
#ifndef WF_GEOMETRY_H
#define WF_GEOMETRY_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// Half the float ulp at 1 (pbrt's MachineEpsilon); gamma(n) bounds n chained roundings.
#define WF_MACHINE_EPSILON 5.96046448e-8f
#define WF_GAMMA(n) ((n) * WF_MACHINE_EPSILON / (1.0f - (n) * WF_MACHINE_EPSILON))

// Möller-Trumbore, either face. A hit needs t in (0, tMax); (b1, b2) weight p1 and p2.
// Comparisons are written so NaN (from a near-zero det) fails them.
WF_INLINE bool intersectTriangle(vec3 o, vec3 d, vec3 p0, vec3 p1, vec3 p2, float tMax,
                                 WF_OUT(float) t, WF_OUT(float) b1, WF_OUT(float) b2) {
    t = 0.0f;
    b1 = 0.0f;
    b2 = 0.0f;
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    vec3 pv = cross(d, e2);
    float det = dot(e1, pv);
    if (det == 0.0f) {
        return false; // ray parallel to the plane, or a degenerate triangle
    }
    float invDet = 1.0f / det;
    vec3 s = o - p0;
    b1 = dot(s, pv) * invDet;
    if (!(b1 >= 0.0f && b1 <= 1.0f)) {
        return false;
    }
    vec3 q = cross(s, e1);
    b2 = dot(d, q) * invDet;
    if (!(b2 >= 0.0f && b1 + b2 <= 1.0f)) {
        return false;
    }
    t = dot(e2, q) * invDet;
    return t > 0.0f && t < tMax;
}

// Narrows [tEntry, tExit] to one axis' slab. The near plane is chosen by the direction's sign,
// not by min/max of the two plane distances, so an inverted box (lo > hi, the empty scene's
// root) stays empty. invDir is +-inf on a zero component (its sign follows the zero's), and a
// ray lying in a slab plane would give 0 * inf = NaN: that plane is skipped, which only widens.
WF_INLINE void clipSlab(float o, float invDir, float lo, float hi, WF_INOUT(float) tEntry,
                        WF_INOUT(float) tExit) {
    float dNear = (invDir >= 0.0f ? lo : hi) - o;
    float dFar = (invDir >= 0.0f ? hi : lo) - o;
    if (dNear != 0.0f) {
        tEntry = max(tEntry, dNear * invDir);
    }
    if (dFar != 0.0f) {
        // pbrt's 1 + 2 gamma(3): covers the roundings of the subtraction, the product and
        // 1/d, so a ray that truly touches the box is never rejected.
        tExit = min(tExit, dFar * invDir * (1.0f + 2.0f * WF_GAMMA(3.0f)));
    }
}

// Slab test against [lo, hi] for t in [0, tMax]; tEntry is where the ray enters (0 if inside).
WF_INLINE bool intersectBox(vec3 o, vec3 invDir, vec3 lo, vec3 hi, float tMax,
                            WF_OUT(float) tEntry) {
    float tIn = 0.0f;
    float tOut = tMax;
    clipSlab(o.x, invDir.x, lo.x, hi.x, tIn, tOut);
    clipSlab(o.y, invDir.y, lo.y, hi.y, tIn, tOut);
    clipSlab(o.z, invDir.z, lo.z, hi.z, tIn, tOut);
    tEntry = tIn;
    return tIn <= tOut;
}

// The hit point from barycentrics rather than o + t*d: its error depends only on the vertices,
// not on how far the ray travelled, which is what makes the bound below tight.
WF_INLINE vec3 triangleHitPoint(vec3 p0, vec3 p1, vec3 p2, float b1, float b2) {
    return (1.0f - b1 - b2) * p0 + b1 * p1 + b2 * p2;
}

// Absolute error bound of triangleHitPoint, per component (pbrt-v4's triangle interaction).
WF_INLINE vec3 triangleHitPointError(vec3 p0, vec3 p1, vec3 p2, float b1, float b2) {
    float b0 = 1.0f - b1 - b2;
    return WF_GAMMA(7.0f) * (abs(b0 * p0) + abs(b1 * p1) + abs(b2 * p2));
}

// Möller-Trumbore judges which side of the plane a point lies on from rounded edge vectors
// and cross products, with an error (as a distance from the plane) of up to about
// gamma(7) * 2 * |s| |e1| |e2| / |e1 x e2|, s = origin - p0, |s| <= max(|e1|, |e2|): it grows as
// 1 / sin(angle at p0). pbrt's hit-point bound alone misses this; test_ray_offset.cpp shows
// needles self-hitting 10% of the time without it, and none with 1/16 of it. A triangle with
// no float area gets its own size, beyond which no offset is meaningful.
WF_INLINE float triangleIntersectSlack(vec3 p0, vec3 p1, vec3 p2) {
    vec3 e1 = p1 - p0;
    vec3 e2 = p2 - p0;
    float l1 = length(e1);
    float l2 = length(e2);
    float maxEdge = max(l1, l2);
    float area2 = length(cross(e1, e2));
    float slack = WF_GAMMA(7.0f) * 2.0f * maxEdge * (l1 / area2) * l2;
    return area2 > 0.0f ? min(slack, maxEdge) : maxEdge;
}

// What a triangle hit hands to offsetRayOrigin: the hit point's error plus the intersector's.
WF_INLINE vec3 triangleSpawnError(vec3 p0, vec3 p1, vec3 p2, float b1, float b2) {
    return triangleHitPointError(p0, p1, p2, b1, b2) + vec3(triangleIntersectSlack(p0, p1, p2));
}

// Affine maps as the three rows of a 3x4 matrix (Instance, scene_types.h): x' = r . (x, 1).
WF_INLINE vec3 affinePoint(vec4 r0, vec4 r1, vec4 r2, vec3 p) {
    return vec3(dot(vec3(r0), p) + r0.w, dot(vec3(r1), p) + r1.w, dot(vec3(r2), p) + r2.w);
}

WF_INLINE vec3 affineVector(vec4 r0, vec4 r1, vec4 r2, vec3 v) {
    return vec3(dot(vec3(r0), v), dot(vec3(r1), v), dot(vec3(r2), v));
}

// |M| e per component: where an error box e around a point can land under the linear part.
WF_INLINE vec3 affineErrorImage(vec4 r0, vec4 r1, vec4 r2, vec3 e) {
    return vec3(dot(abs(vec3(r0)), e), dot(abs(vec3(r1)), e), dot(abs(vec3(r2)), e));
}

// Rounding error bound of affinePoint at a point of absolute coordinates pAbs (pbrt-v4's
// Transform: gamma(3) (|M| |p| + |t|), three products and three sums per row).
WF_INLINE vec3 affinePointError(vec4 r0, vec4 r1, vec4 r2, vec3 pAbs) {
    return WF_GAMMA(3.0f) * (affineErrorImage(r0, r1, r2, pAbs) + abs(vec3(r0.w, r1.w, r2.w)));
}

// The next representable float towards +inf / -inf. Both zeros step to the smallest
// denormal of the requested sign (a plain bits +- 1 would turn -0 into a NaN pattern).
WF_INLINE float nextFloatUp(float v) {
    if (floatBitsToUint(v) == 0x7f800000u) {
        return v; // +inf
    }
    if (v == 0.0f) {
        return uintBitsToFloat(1u);
    }
    uint bits = floatBitsToUint(v);
    return uintBitsToFloat(v > 0.0f ? bits + 1u : bits - 1u);
}

WF_INLINE float nextFloatDown(float v) {
    if (floatBitsToUint(v) == 0xff800000u) {
        return v; // -inf
    }
    if (v == 0.0f) {
        return uintBitsToFloat(0x80000001u);
    }
    uint bits = floatBitsToUint(v);
    return uintBitsToFloat(v > 0.0f ? bits - 1u : bits + 1u);
}

WF_INLINE float roundAwayFrom(float v, float offset) {
    return offset > 0.0f ? nextFloatUp(v) : (offset < 0.0f ? nextFloatDown(v) : v);
}

// pbrt-v4's OffsetRayOrigin: moves a hit point p (error bound pError) along the geometric
// normal n to the side w leaves from, just past the slab the true point may lie in, then one
// ulp further so the rounding of p + offset cannot pull it back. n must be unit length.
WF_INLINE vec3 offsetRayOrigin(vec3 p, vec3 pError, vec3 n, vec3 w) {
    float d = dot(abs(n), pError);
    vec3 offset = d * n;
    if (dot(w, n) < 0.0f) {
        offset = -offset;
    }
    vec3 po = p + offset;
    return vec3(roundAwayFrom(po.x, offset.x), roundAwayFrom(po.y, offset.y),
                roundAwayFrom(po.z, offset.z));
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
