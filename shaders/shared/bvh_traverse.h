// BVH traversal shared by the intersect/shadow passes (GLSL) and the CPU (src/scene/bvh_cpu.h),
// so tests compare the GPU's own traversal against brute force.
//
// Layout: BvhPair entries (scene_types.h, made by pairBvhNodes in src/scene/bvh_builder.cpp).
// Traversal holds one child reference (scene_types.h): a leaf's triangle range, or a pair entry
// whose two child boxes are tested together. The walk starts at entry 0.
//
// GLSL includers define, before including:
//   WF_BVH_PAIR(i)      an expression yielding BvhPair i (e.g. a texel-buffer fetch)
//   WF_BVH_TRIANGLE(i)  an expression yielding Triangle i
//   WF_BVH_STACK_SIZE   optional, default 64; the builder keeps depth <= WF_BVH_STACK_SIZE - 1
// With WF_HAS_ALPHA_MASK (GLSL only), every candidate hit must also pass
//   bool wfAlphaPasses(uint triangle, float b1, float b2, vec3 o, vec3 d)
// so cut-outs stop no ray, closest-hit or shadow; the includer may define it (and
// WF_ALPHA_PASSES_DEFINED), else alpha_mask.glsl's, reading the includer's scene buffers, is used.
// In C++ the functions become members of BvhTraversal, whose two pointers the default
// accessors read; use it through src/scene/bvh_cpu.h and leave the macros undefined (a second
// definition in another translation unit would break the one-definition rule).
#ifndef WF_BVH_TRAVERSE_H
#define WF_BVH_TRAVERSE_H

#include "geometry.h"
#include "scene_types.h"

#ifndef WF_BVH_STACK_SIZE
#define WF_BVH_STACK_SIZE 64
#endif

#if !defined(__cplusplus) && WF_HAS_ALPHA_MASK && !defined(WF_ALPHA_PASSES_DEFINED)
#include "alpha_mask.glsl"
#endif

#define WF_NO_TRIANGLE 0xffffffffu

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

struct HitRecord {
    float t; // tMax on a miss
    float b1; // barycentric weight of p1
    float b2; // barycentric weight of p2
    uint triangle; // WF_NO_TRIANGLE on a miss
};

#ifdef __cplusplus
struct BvhTraversal {
    const BvhPair* pairs = nullptr;
    const Triangle* triangles = nullptr;
#ifndef WF_BVH_PAIR
#define WF_BVH_PAIR(i) pairs[i]
#define WF_BVH_TRIANGLE(i) triangles[i]
#define WF_BVH_DEFAULT_ACCESSORS
#endif
#endif

// Whether the ray meets child reference `child`'s box before tMax; entry distance in tEntry.
WF_INLINE bool bvhChildHit(uint child, vec3 o, vec3 invDir, vec3 lo, vec3 hi, float tMax,
                           WF_OUT(float) tEntry) {
    bool boxHit = intersectBox(o, invDir, lo, hi, tMax, tEntry);
    return child != WF_BVH_NO_CHILD && boxHit;
}

// Closest hit with t in (0, tMax). Ordered: the nearer child is visited first and the farther
// one pushed with its entry distance, so it is dropped on pop once a closer hit is known.
WF_INLINE bool traceClosest(vec3 o, vec3 d, float tMax, WF_OUT(HitRecord) hit) {
    hit.t = tMax;
    hit.b1 = 0.0f;
    hit.b2 = 0.0f;
    hit.triangle = WF_NO_TRIANGLE;
    vec3 invDir = 1.0f / d;
    uint stackChild[WF_BVH_STACK_SIZE];
    float stackEntry[WF_BVH_STACK_SIZE];
    uint stackSize = 0u;
    uint current = 0u; // a reference to pair entry 0: the root's children
    bool haveCurrent = true;
    while (haveCurrent) {
        haveCurrent = false;
        uint index = current >> WF_BVH_COUNT_BITS;
        uint count = current & WF_BVH_MAX_LEAF_COUNT;
        if (count > 0u) {
            for (uint i = index; i < index + count; ++i) {
                Triangle tri = WF_BVH_TRIANGLE(i);
                float t;
                float b1;
                float b2;
                if (intersectTriangle(o, d, tri.p0, tri.p1, tri.p2, hit.t, t, b1, b2)) {
#if WF_HAS_ALPHA_MASK
                    if (!wfAlphaPasses(i, b1, b2, o, d))
                        continue; // a cut-out: the ray goes on
#endif
                    hit.t = t;
                    hit.b1 = b1;
                    hit.b2 = b2;
                    hit.triangle = i;
                }
            }
        } else {
            BvhPair pair = WF_BVH_PAIR(index);
            float t0;
            float t1;
            bool hit0 = bvhChildHit(pair.child0, o, invDir, pair.lo0, pair.hi0, hit.t, t0);
            bool hit1 = bvhChildHit(pair.child1, o, invDir, pair.lo1, pair.hi1, hit.t, t1);
            if (hit0 && hit1) {
                bool firstNear = t0 <= t1;
                current = firstNear ? pair.child0 : pair.child1;
                haveCurrent = true;
                // The builder bounds the depth, so this only guards against a foreign tree:
                // dropping a subtree is wrong but cannot write out of bounds.
                if (stackSize < uint(WF_BVH_STACK_SIZE)) {
                    stackChild[stackSize] = firstNear ? pair.child1 : pair.child0;
                    stackEntry[stackSize] = firstNear ? t1 : t0;
                    ++stackSize;
                }
            } else if (hit0 || hit1) {
                current = hit0 ? pair.child0 : pair.child1;
                haveCurrent = true;
            }
        }
        while (!haveCurrent && stackSize > 0u) {
            --stackSize;
            if (stackEntry[stackSize] <= hit.t) {
                current = stackChild[stackSize];
                haveCurrent = true;
            }
        }
    }
    return hit.triangle != WF_NO_TRIANGLE;
}

// Any hit with t in (0, tMax), for shadow rays: order does not matter, the first hit ends it.
WF_INLINE bool traceAny(vec3 o, vec3 d, float tMax) {
    vec3 invDir = 1.0f / d;
    uint stackChild[WF_BVH_STACK_SIZE];
    uint stackSize = 0u;
    uint current = 0u;
    bool haveCurrent = true;
    while (haveCurrent) {
        haveCurrent = false;
        uint index = current >> WF_BVH_COUNT_BITS;
        uint count = current & WF_BVH_MAX_LEAF_COUNT;
        if (count > 0u) {
            for (uint i = index; i < index + count; ++i) {
                Triangle tri = WF_BVH_TRIANGLE(i);
                float t;
                float b1;
                float b2;
                if (intersectTriangle(o, d, tri.p0, tri.p1, tri.p2, tMax, t, b1, b2)) {
#if WF_HAS_ALPHA_MASK
                    if (!wfAlphaPasses(i, b1, b2, o, d))
                        continue;
#endif
                    return true;
                }
            }
        } else {
            BvhPair pair = WF_BVH_PAIR(index);
            float t0;
            float t1;
            bool hit0 = bvhChildHit(pair.child0, o, invDir, pair.lo0, pair.hi0, tMax, t0);
            bool hit1 = bvhChildHit(pair.child1, o, invDir, pair.lo1, pair.hi1, tMax, t1);
            if (hit0 || hit1) {
                current = hit0 ? pair.child0 : pair.child1;
                haveCurrent = true;
                if (hit0 && hit1 && stackSize < uint(WF_BVH_STACK_SIZE)) {
                    stackChild[stackSize] = pair.child1;
                    ++stackSize;
                }
            }
        }
        if (!haveCurrent && stackSize > 0u) {
            --stackSize;
            current = stackChild[stackSize];
            haveCurrent = true;
        }
    }
    return false;
}

#ifdef __cplusplus
}; // struct BvhTraversal
} // namespace wf::gpu_types
#ifdef WF_BVH_DEFAULT_ACCESSORS
#undef WF_BVH_PAIR
#undef WF_BVH_TRIANGLE
#undef WF_BVH_DEFAULT_ACCESSORS
#endif
#endif

#endif
