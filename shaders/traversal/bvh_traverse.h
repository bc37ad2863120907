// BVH traversal shared by the intersect/shadow passes (GLSL) and the CPU (src/scene/bvh/bvh_cpu.h),
// so tests compare the GPU's own traversal against brute force.
//
// Layout: BvhPair entries (scene_types.h, made by pairBvhNodes in src/scene/bvh/bvh_builder.cpp).
// Each step visits one pair entry: tests both child boxes, intersects the triangles of the
// children that are leaves there and then (nearer leaf first), and descends into an interior
// child, so the loop and its stack only ever hold pair entries. The walk starts at entry 0.
// On 8-wide SIMD (lavapipe) a step costs the same whatever each lane finds, so fewer, fuller
// steps are what pays; the CPU tests run this very code against brute force.
//
// GLSL includers define, before including:
//   WF_BVH_PAIR(i)      an expression yielding BvhPair i (e.g. a texel-buffer fetch)
//   WF_BVH_TRIANGLE(i)  an expression yielding Triangle i
//   WF_BVH_INSTANCE(i)  with WF_HAS_INSTANCES, an expression yielding Instance i
//   WF_BVH_STACK_SIZE   optional, default 64; the builder keeps depth <= WF_BVH_STACK_SIZE - 1
//   WF_BVH_REGISTER_STACK  optional, default 0; 8 or 16 where the tree never holds more
//                       entries than that on its stack (bvhStackNeed): any-hit traversal then
//                       keeps its stack in vectors, closest-hit traversal only at 8
// With WF_HAS_ALPHA_MASK (GLSL only), every candidate hit must also pass
//   bool wfAlphaPasses(uint triangle, float b1, float b2, vec3 o, vec3 d)
// so cut-outs stop no ray, closest-hit or shadow; the includer may define it (and
// WF_ALPHA_PASSES_DEFINED), else alpha_mask.glsl's, reading the includer's scene buffers, is used.
// In C++ the functions become members of BvhTraversal, whose two pointers the default
// accessors read; use it through src/scene/bvh/bvh_cpu.h and leave the macros undefined (a second
// definition in another translation unit would break the one-definition rule).
#ifndef WF_BVH_TRAVERSE_H
#define WF_BVH_TRAVERSE_H

#include "traversal/geometry.h"
#include "types/scene_types.h"

#ifndef WF_BVH_STACK_SIZE
#define WF_BVH_STACK_SIZE 64
#endif

#if !defined(__cplusplus) && WF_HAS_ALPHA_MASK && !defined(WF_ALPHA_PASSES_DEFINED)
#include "surface/alpha_mask.glsl"
#endif

#ifndef WF_BVH_REGISTER_STACK
#define WF_BVH_REGISTER_STACK 0
#endif

#define WF_NO_TRIANGLE 0xffffffffu

#ifdef __cplusplus
#include <vector>
namespace wf::gpu_types {
using namespace glm;
#endif

struct HitRecord {
    float t; // tMax on a miss
    float b1; // barycentric weight of p1
    float b2; // barycentric weight of p2
    uint triangle; // WF_NO_TRIANGLE on a miss
};

// A traversal stack of up to 8 or 16 entries (`capacity`, a constant at every call) held in
// vectors and shifted on push and pop. Mesa 22.3's llvmpipe runs a dynamically indexed private
// array as a loop over the lanes, a load or store at a time; a shift is a few selects per
// vector. The host picks it where the tree's stack need fits. Pair entries only: closest-hit
// traversal with it pops without the entry-distance cull. Measured: the 16-entry stack speeds
// shadow rays up by 20% but slowed closest hits (then with entry distances) by as much.
struct BvhRegisterStack {
    uvec4 pairs0; // top of the stack in .x
    uvec4 pairs1;
    uvec4 pairs2; // entries 8-15, only at capacity 16
    uvec4 pairs3;
};

WF_INLINE BvhRegisterStack bvhRegisterStack() {
    BvhRegisterStack s;
    s.pairs0 = uvec4(0u);
    s.pairs1 = uvec4(0u);
    s.pairs2 = uvec4(0u);
    s.pairs3 = uvec4(0u);
    return s;
}

// Past `capacity` entries the bottom one falls off: wrong, but the host never lets that happen.
WF_INLINE void bvhRegisterPush(WF_INOUT(BvhRegisterStack) s, uint pair, uint capacity) {
    if (capacity > 8u) {
        s.pairs3 = uvec4(s.pairs2.w, s.pairs3.x, s.pairs3.y, s.pairs3.z);
        s.pairs2 = uvec4(s.pairs1.w, s.pairs2.x, s.pairs2.y, s.pairs2.z);
    }
    s.pairs1 = uvec4(s.pairs0.w, s.pairs1.x, s.pairs1.y, s.pairs1.z);
    s.pairs0 = uvec4(pair, s.pairs0.x, s.pairs0.y, s.pairs0.z);
}

// Removes the top entry (read it from pairs0.x first).
WF_INLINE void bvhRegisterPop(WF_INOUT(BvhRegisterStack) s, uint capacity) {
    s.pairs0 = uvec4(s.pairs0.y, s.pairs0.z, s.pairs0.w, s.pairs1.x);
    s.pairs1 = uvec4(s.pairs1.y, s.pairs1.z, s.pairs1.w, capacity > 8u ? s.pairs2.x : 0u);
    if (capacity > 8u) {
        s.pairs2 = uvec4(s.pairs2.y, s.pairs2.z, s.pairs2.w, s.pairs3.x);
        s.pairs3 = uvec4(s.pairs3.y, s.pairs3.z, s.pairs3.w, 0u);
    }
}

// The end of a step on the register stack: push `far` where both children go on, and take the
// top entry where neither does. One pop a step, without an entry-distance cull: an entry
// behind the closest hit costs one step whose child boxes all start behind it too (nested
// boxes), so it tests nothing, and that is cheaper on 8-wide SIMD than a pop loop run on every
// step. The size saturates, so a foreign tree deeper than the stack loses subtrees but never
// pops the zeros below the bottom (entry 0 again: a walk without end).
WF_INLINE void bvhRegisterNext(WF_INOUT(BvhRegisterStack) s, WF_INOUT(uint) size, bool pushFar,
                               uint far, WF_INOUT(bool) haveCurrent, WF_INOUT(uint) current,
                               uint capacity) {
    if (pushFar) {
        bvhRegisterPush(s, far, capacity);
        size = min(size + 1u, capacity);
    }
    if (!haveCurrent && size > 0u) {
        --size;
        current = s.pairs0.x;
        haveCurrent = true;
        bvhRegisterPop(s, capacity);
    }
}

#ifdef __cplusplus
struct BvhTraversal {
    const BvhPair* pairs = nullptr;
    const Triangle* triangles = nullptr;
    const Instance* instances = nullptr; // two-level scenes only
    uint deepestStack = 0u; // the most entries the stack held, for the tests of bvhStackNeed
    // When set, each step appends how many triangles it tested (bvh_tuning.cpp models SIMD
    // batches from these).
    std::vector<uint>* stepTests = nullptr;
#ifndef WF_BVH_PAIR
#define WF_BVH_PAIR(i) pairs[i]
#define WF_BVH_TRIANGLE(i) triangles[i]
#define WF_BVH_INSTANCE(i) instances[i]
#define WF_BVH_DEFAULT_ACCESSORS
#endif
#endif

// Whether the ray meets child reference `child`'s box before tMax; entry distance in tEntry.
WF_INLINE bool bvhChildHit(uint child, vec3 o, vec3 invDir, vec3 lo, vec3 hi, float tMax,
                           WF_OUT(float) tEntry) {
    bool boxHit = intersectBox(o, invDir, lo, hi, tMax, tEntry);
    return child != WF_BVH_NO_CHILD && boxHit;
}

// The children of one pair entry as a step sees them: nearer hit child first.
struct BvhStep {
    uint nearChild;
    uint farChild;
    float nearEntry;
    float farEntry;
    uint nearCount; // triangles to test now: a leaf child that the ray hits, else 0
    uint farCount;
    bool nearInner; // an interior child that the ray hits
    bool farInner;
};

WF_INLINE BvhStep bvhStep(BvhPair pair, vec3 o, vec3 invDir, float tMax) {
    float t0;
    float t1;
    bool hit0 = bvhChildHit(pair.child0, o, invDir, pair.lo0, pair.hi0, tMax, t0);
    bool hit1 = bvhChildHit(pair.child1, o, invDir, pair.lo1, pair.hi1, tMax, t1);
    bool swap = hit1 && (!hit0 || t1 < t0);
    BvhStep step;
    step.nearChild = swap ? pair.child1 : pair.child0;
    step.farChild = swap ? pair.child0 : pair.child1;
    step.nearEntry = swap ? t1 : t0;
    step.farEntry = swap ? t0 : t1;
    bool nearHit = swap ? hit1 : hit0;
    bool farHit = swap ? hit0 : hit1;
    uint nearCount = step.nearChild & WF_BVH_MAX_LEAF_COUNT;
    uint farCount = step.farChild & WF_BVH_MAX_LEAF_COUNT;
    step.nearCount = nearHit ? nearCount : 0u;
    step.farCount = farHit ? farCount : 0u;
    step.nearInner = nearHit && nearCount == 0u;
    step.farInner = farHit && farCount == 0u;
    return step;
}

// Triangle k of a step's leaves: the near leaf's, then the far leaf's.
WF_INLINE uint bvhStepTriangle(BvhStep step, uint k) {
    return k < step.nearCount ? (step.nearChild >> WF_BVH_COUNT_BITS) + k
                              : (step.farChild >> WF_BVH_COUNT_BITS) + (k - step.nearCount);
}

// Closest hit with t in (0, tMax) in the tree whose root children pair entry `root` holds.
// Ordered: the nearer child first; a farther interior child is pushed with its entry distance
// and dropped on pop once a closer hit is known.
WF_INLINE bool traceClosestFrom(uint root, vec3 o, vec3 d, float tMax, WF_OUT(HitRecord) hit) {
    hit.t = tMax;
    hit.b1 = 0.0f;
    hit.b2 = 0.0f;
    hit.triangle = WF_NO_TRIANGLE;
    vec3 invDir = 1.0f / d;
#if WF_BVH_REGISTER_STACK == 8
    BvhRegisterStack stack = bvhRegisterStack();
#else
    uint stackPair[WF_BVH_STACK_SIZE];
    float stackEntry[WF_BVH_STACK_SIZE];
#endif
    uint stackSize = 0u;
    uint current = root;
    bool haveCurrent = true;
    while (haveCurrent) {
        BvhStep step = bvhStep(WF_BVH_PAIR(current), o, invDir, hit.t);
#ifdef __cplusplus
        uint tested = 0u;
#endif
        for (uint k = 0u; k < step.nearCount + step.farCount; ++k) {
            if (k == step.nearCount && step.farEntry > hit.t)
                break; // the near leaf hit something before the far leaf begins
#ifdef __cplusplus
            ++tested;
#endif
            uint i = bvhStepTriangle(step, k);
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
#ifdef __cplusplus
        if (stepTests)
            stepTests->push_back(tested);
#endif
        bool nearNext = step.nearInner && step.nearEntry <= hit.t;
        bool farNext = step.farInner && step.farEntry <= hit.t;
        haveCurrent = nearNext || farNext;
        current = (nearNext ? step.nearChild : step.farChild) >> WF_BVH_COUNT_BITS;
#if WF_BVH_REGISTER_STACK == 8
        bvhRegisterNext(stack, stackSize, nearNext && farNext,
                        step.farChild >> WF_BVH_COUNT_BITS, haveCurrent, current, 8u);
#else
        // The builder bounds the depth, so the size check only guards against a foreign tree:
        // dropping a subtree is wrong but cannot write out of bounds.
        if (nearNext && farNext && stackSize < uint(WF_BVH_STACK_SIZE)) {
            stackPair[stackSize] = step.farChild >> WF_BVH_COUNT_BITS;
            stackEntry[stackSize] = step.farEntry;
            ++stackSize;
#ifdef __cplusplus
            deepestStack = max(deepestStack, stackSize);
#endif
        }
        while (!haveCurrent && stackSize > 0u) {
            --stackSize;
            if (stackEntry[stackSize] <= hit.t) {
                current = stackPair[stackSize];
                haveCurrent = true;
            }
        }
#endif
    }
    return hit.triangle != WF_NO_TRIANGLE;
}

// Any hit with t in (0, tMax), for shadow rays: order does not matter, the first hit ends it.
WF_INLINE bool traceAnyFrom(uint root, vec3 o, vec3 d, float tMax) {
    vec3 invDir = 1.0f / d;
#if WF_BVH_REGISTER_STACK
    BvhRegisterStack stack = bvhRegisterStack();
#else
    uint stackPair[WF_BVH_STACK_SIZE];
#endif
    uint stackSize = 0u;
    uint current = root;
    bool haveCurrent = true;
    while (haveCurrent) {
        BvhStep step = bvhStep(WF_BVH_PAIR(current), o, invDir, tMax);
        for (uint k = 0u; k < step.nearCount + step.farCount; ++k) {
            uint i = bvhStepTriangle(step, k);
            Triangle tri = WF_BVH_TRIANGLE(i);
            float t;
            float b1;
            float b2;
            if (intersectTriangle(o, d, tri.p0, tri.p1, tri.p2, tMax, t, b1, b2)) {
#if WF_HAS_ALPHA_MASK
                if (!wfAlphaPasses(i, b1, b2, o, d))
                    continue;
#endif
#ifdef __cplusplus
                if (stepTests)
                    stepTests->push_back(k + 1u);
#endif
                return true;
            }
        }
#ifdef __cplusplus
        if (stepTests)
            stepTests->push_back(step.nearCount + step.farCount);
#endif
        haveCurrent = step.nearInner || step.farInner;
        current = (step.nearInner ? step.nearChild : step.farChild) >> WF_BVH_COUNT_BITS;
#if WF_BVH_REGISTER_STACK
        bvhRegisterNext(stack, stackSize, step.nearInner && step.farInner,
                        step.farChild >> WF_BVH_COUNT_BITS, haveCurrent, current,
                        uint(WF_BVH_REGISTER_STACK));
#else
        if (step.nearInner && step.farInner && stackSize < uint(WF_BVH_STACK_SIZE)) {
            stackPair[stackSize] = step.farChild >> WF_BVH_COUNT_BITS;
            ++stackSize;
#ifdef __cplusplus
            deepestStack = max(deepestStack, stackSize);
#endif
        }
        if (!haveCurrent && stackSize > 0u) {
            --stackSize;
            current = stackPair[stackSize];
            haveCurrent = true;
        }
#endif
    }
    return false;
}

// One-level scenes: the tree rooted at pair entry 0.
WF_INLINE bool traceClosest(vec3 o, vec3 d, float tMax, WF_OUT(HitRecord) hit) {
    return traceClosestFrom(0u, o, d, tMax, hit);
}

WF_INLINE bool traceAny(vec3 o, vec3 d, float tMax) { return traceAnyFrom(0u, o, d, tMax); }

#if defined(__cplusplus) || WF_HAS_INSTANCES
// Two-level scenes: pair entry 0 roots the top-level tree, whose leaves hold one instance each
// (WF_BVH_INSTANCE(i), in leaf order), and each instance's mesh tree starts at its blasRoot.
// The ray meets a mesh in the mesh's own space. Its direction is mapped but not renormalised,
// so t means the same point in both spaces and one tMax serves every level. The top-level
// stack is a plain array: its trees are shallow and its steps few.
WF_INLINE void instanceRay(Instance instance, vec3 o, vec3 d, WF_OUT(vec3) objectOrigin,
                           WF_OUT(vec3) objectDirection) {
    objectOrigin = affinePoint(instance.objectFromWorld0, instance.objectFromWorld1,
                               instance.objectFromWorld2, o);
    objectDirection = affineVector(instance.objectFromWorld0, instance.objectFromWorld1,
                                   instance.objectFromWorld2, d);
}

// Closest hit over every instance; `instance` is the one hit (undefined on a miss).
WF_INLINE bool traceClosestInstanced(vec3 o, vec3 d, float tMax, WF_OUT(HitRecord) hit,
                                     WF_OUT(uint) instance) {
    hit.t = tMax;
    hit.b1 = 0.0f;
    hit.b2 = 0.0f;
    hit.triangle = WF_NO_TRIANGLE;
    instance = 0u;
    vec3 invDir = 1.0f / d;
    uint stackPair[WF_BVH_STACK_SIZE];
    float stackEntry[WF_BVH_STACK_SIZE];
    uint stackSize = 0u;
    uint current = 0u;
    bool haveCurrent = true;
    while (haveCurrent) {
        BvhStep step = bvhStep(WF_BVH_PAIR(current), o, invDir, hit.t);
        for (uint k = 0u; k < step.nearCount + step.farCount; ++k) {
            uint i = bvhStepTriangle(step, k);
            Instance placed = WF_BVH_INSTANCE(i);
            vec3 objectOrigin;
            vec3 objectDirection;
            instanceRay(placed, o, d, objectOrigin, objectDirection);
            HitRecord found;
            if (traceClosestFrom(placed.blasRoot, objectOrigin, objectDirection, hit.t, found)) {
                hit = found;
                instance = i;
            }
        }
        bool nearNext = step.nearInner && step.nearEntry <= hit.t;
        bool farNext = step.farInner && step.farEntry <= hit.t;
        haveCurrent = nearNext || farNext;
        current = (nearNext ? step.nearChild : step.farChild) >> WF_BVH_COUNT_BITS;
        if (nearNext && farNext && stackSize < uint(WF_BVH_STACK_SIZE)) {
            stackPair[stackSize] = step.farChild >> WF_BVH_COUNT_BITS;
            stackEntry[stackSize] = step.farEntry;
            ++stackSize;
        }
        while (!haveCurrent && stackSize > 0u) {
            --stackSize;
            if (stackEntry[stackSize] <= hit.t) {
                current = stackPair[stackSize];
                haveCurrent = true;
            }
        }
    }
    return hit.triangle != WF_NO_TRIANGLE;
}

WF_INLINE bool traceAnyInstanced(vec3 o, vec3 d, float tMax) {
    vec3 invDir = 1.0f / d;
    uint stackPair[WF_BVH_STACK_SIZE];
    uint stackSize = 0u;
    uint current = 0u;
    bool haveCurrent = true;
    while (haveCurrent) {
        BvhStep step = bvhStep(WF_BVH_PAIR(current), o, invDir, tMax);
        for (uint k = 0u; k < step.nearCount + step.farCount; ++k) {
            Instance placed = WF_BVH_INSTANCE(bvhStepTriangle(step, k));
            vec3 objectOrigin;
            vec3 objectDirection;
            instanceRay(placed, o, d, objectOrigin, objectDirection);
            if (traceAnyFrom(placed.blasRoot, objectOrigin, objectDirection, tMax))
                return true;
        }
        haveCurrent = step.nearInner || step.farInner;
        current = (step.nearInner ? step.nearChild : step.farChild) >> WF_BVH_COUNT_BITS;
        if (step.nearInner && step.farInner && stackSize < uint(WF_BVH_STACK_SIZE)) {
            stackPair[stackSize] = step.farChild >> WF_BVH_COUNT_BITS;
            ++stackSize;
        }
        if (!haveCurrent && stackSize > 0u) {
            --stackSize;
            current = stackPair[stackSize];
            haveCurrent = true;
        }
    }
    return false;
}
#endif

#ifdef __cplusplus
}; // struct BvhTraversal
} // namespace wf::gpu_types
#ifdef WF_BVH_DEFAULT_ACCESSORS
#undef WF_BVH_PAIR
#undef WF_BVH_TRIANGLE
#undef WF_BVH_INSTANCE
#undef WF_BVH_DEFAULT_ACCESSORS
#endif
#endif

#endif
