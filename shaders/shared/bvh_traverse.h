// BVH traversal shared by the intersect/shadow passes (GLSL) and the CPU (src/scene/bvh_cpu.h),
// so tests compare the GPU's own traversal against brute force.
//
// Node layout (scene_types.h, built by src/scene/bvh_builder.cpp): depth-first, node 0 is the
// root, an interior node's left child is the next node and its right child `rightOrFirst`; a
// leaf holds `count` > 0 triangles from `rightOrFirst`. There is always at least one node: an
// empty scene gets a root with count 0 and an inverted box (lo > hi), which nothing hits.
//
// GLSL includers define, before including:
//   WF_BVH_NODE(i)      an expression yielding BvhNode i (e.g. a storage-buffer element)
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
    const BvhNode* nodes = nullptr;
    const Triangle* triangles = nullptr;
#ifndef WF_BVH_NODE
#define WF_BVH_NODE(i) nodes[i]
#define WF_BVH_TRIANGLE(i) triangles[i]
#define WF_BVH_DEFAULT_ACCESSORS
#endif
#endif

// An inverted root box marks the empty scene. Checked explicitly: an interior-looking root
// with no children must never be descended, even by a ray the slab test lets through.
WF_INLINE bool bvhIsEmpty() {
    return !(WF_BVH_NODE(0u).lo.x <= WF_BVH_NODE(0u).hi.x);
}

// Closest hit with t in (0, tMax). Ordered: the nearer child is visited first and the farther
// one pushed with its entry distance, so it is dropped on pop once a closer hit is known.
WF_INLINE bool traceClosest(vec3 o, vec3 d, float tMax, WF_OUT(HitRecord) hit) {
    hit.t = tMax;
    hit.b1 = 0.0f;
    hit.b2 = 0.0f;
    hit.triangle = WF_NO_TRIANGLE;
    vec3 invDir = 1.0f / d;
    float tRoot;
    if (bvhIsEmpty() ||
        !intersectBox(o, invDir, WF_BVH_NODE(0u).lo, WF_BVH_NODE(0u).hi, tMax, tRoot)) {
        return false;
    }
    uint stackNode[WF_BVH_STACK_SIZE];
    float stackEntry[WF_BVH_STACK_SIZE];
    uint stackSize = 0u;
    uint current = 0u;
    bool haveCurrent = true;
    while (haveCurrent) {
        BvhNode node = WF_BVH_NODE(current);
        haveCurrent = false;
        if (node.count > 0u) {
            for (uint i = node.rightOrFirst; i < node.rightOrFirst + node.count; ++i) {
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
            uint left = current + 1u;
            uint right = node.rightOrFirst;
            float tLeft;
            float tRight;
            bool hitLeft =
                intersectBox(o, invDir, WF_BVH_NODE(left).lo, WF_BVH_NODE(left).hi, hit.t, tLeft);
            bool hitRight = intersectBox(o, invDir, WF_BVH_NODE(right).lo, WF_BVH_NODE(right).hi,
                                         hit.t, tRight);
            if (hitLeft && hitRight) {
                bool leftFirst = tLeft <= tRight;
                current = leftFirst ? left : right;
                haveCurrent = true;
                // The builder bounds the depth, so this only guards against a foreign tree:
                // dropping a subtree is wrong but cannot write out of bounds.
                if (stackSize < uint(WF_BVH_STACK_SIZE)) {
                    stackNode[stackSize] = leftFirst ? right : left;
                    stackEntry[stackSize] = leftFirst ? tRight : tLeft;
                    ++stackSize;
                }
            } else if (hitLeft || hitRight) {
                current = hitLeft ? left : right;
                haveCurrent = true;
            }
        }
        while (!haveCurrent && stackSize > 0u) {
            --stackSize;
            if (stackEntry[stackSize] <= hit.t) {
                current = stackNode[stackSize];
                haveCurrent = true;
            }
        }
    }
    return hit.triangle != WF_NO_TRIANGLE;
}

// Any hit with t in (0, tMax), for shadow rays: order does not matter, the first hit ends it.
WF_INLINE bool traceAny(vec3 o, vec3 d, float tMax) {
    vec3 invDir = 1.0f / d;
    float tEntry;
    if (bvhIsEmpty() ||
        !intersectBox(o, invDir, WF_BVH_NODE(0u).lo, WF_BVH_NODE(0u).hi, tMax, tEntry)) {
        return false;
    }
    uint stackNode[WF_BVH_STACK_SIZE];
    uint stackSize = 0u;
    uint current = 0u;
    bool haveCurrent = true;
    while (haveCurrent) {
        BvhNode node = WF_BVH_NODE(current);
        haveCurrent = false;
        if (node.count > 0u) {
            for (uint i = node.rightOrFirst; i < node.rightOrFirst + node.count; ++i) {
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
            uint left = current + 1u;
            uint right = node.rightOrFirst;
            bool hitLeft =
                intersectBox(o, invDir, WF_BVH_NODE(left).lo, WF_BVH_NODE(left).hi, tMax, tEntry);
            bool hitRight =
                intersectBox(o, invDir, WF_BVH_NODE(right).lo, WF_BVH_NODE(right).hi, tMax, tEntry);
            if (hitLeft || hitRight) {
                current = hitLeft ? left : right;
                haveCurrent = true;
                if (hitLeft && hitRight && stackSize < uint(WF_BVH_STACK_SIZE)) {
                    stackNode[stackSize] = right;
                    ++stackSize;
                }
            }
        }
        if (!haveCurrent && stackSize > 0u) {
            --stackSize;
            current = stackNode[stackSize];
            haveCurrent = true;
        }
    }
    return false;
}

#ifdef __cplusplus
}; // struct BvhTraversal
} // namespace wf::gpu_types
#ifdef WF_BVH_DEFAULT_ACCESSORS
#undef WF_BVH_NODE
#undef WF_BVH_TRIANGLE
#undef WF_BVH_DEFAULT_ACCESSORS
#endif
#endif

#endif
