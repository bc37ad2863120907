// The light tree (Conty Estevez and Kulla 2018, as pbrt-v4's BVHLightSampler): a binary BVH
// over the emitters that have a place (emissive triangles, sphere, point and spot lights),
// each node bounding its lights' positions, power and emission directions. Next-event
// estimation walks it from the root, choosing a child in proportion to an importance that
// bounds power x cos(at the light) / distance^2 from the shading point, so the lights near and
// facing a point are chosen most. The pmf of a given light at a point is the product of the
// choices on its path, which its trail (bit d: second child at depth d) replays, so a BSDF ray
// that hits a light gets the same pmf its sampling would have had.
// Shared by the shade pass (GLSL) and the CPU tests and builder (src/scene/lights/light_tree.cpp).
//
// GLSL includers define WF_LIGHT_TREE_NODE(i), an expression yielding LightTreeNode i; in C++
// the traversal functions are members of LightTreeTraversal, which reads a vector.
#ifndef WF_LIGHT_TREE_H
#define WF_LIGHT_TREE_H

#include "types/glsl_cpp.h"
#include "types/light_types.h"

#ifdef __cplusplus
#include <vector>
namespace wf::gpu_types {
using namespace glm;
#endif

WF_INLINE float lightTreeSafeSqrt(float x) { return sqrt(max(x, 0.0f)); }

// The receiver's normal as one float that any store keeps exactly: 0 for none, else 1 + two
// 12-bit octahedral coordinates (below 2^24). Sampling and the pmf of a BSDF hit both use the
// decoded normal, so they agree bit for bit.
WF_INLINE float encodeReceiverNormal(vec3 n) {
    vec2 o = vec2(n.x, n.y) / (abs(n.x) + abs(n.y) + abs(n.z));
    if (n.z < 0.0f)
        o = (vec2(1.0f) - abs(vec2(o.y, o.x))) *
            vec2(o.x >= 0.0f ? 1.0f : -1.0f, o.y >= 0.0f ? 1.0f : -1.0f);
    vec2 q = clamp(floor((o * 0.5f + vec2(0.5f)) * 4095.0f + vec2(0.5f)), vec2(0.0f),
                   vec2(4095.0f));
    return 1.0f + q.x * 4096.0f + q.y;
}

WF_INLINE vec3 decodeReceiverNormal(float encoded) {
    if (!(encoded > 0.0f))
        return vec3(0.0f);
    uint i = uint(encoded) - 1u;
    vec2 o = vec2(float(i >> 12u), float(i & 4095u)) * (2.0f / 4095.0f) - vec2(1.0f);
    vec3 n = vec3(o.x, o.y, 1.0f - abs(o.x) - abs(o.y));
    float t = max(-n.z, 0.0f);
    n.x += n.x >= 0.0f ? -t : t;
    n.y += n.y >= 0.0f ? -t : t;
    return normalize(n);
}

// cos(max(0, thetaA - thetaB)) from the cosines and sines of both angles.
WF_INLINE float lightTreeCosDifference(float cosA, float sinA, float cosB, float sinB) {
    return cosA >= cosB ? 1.0f : cosA * cosB + sinA * sinB;
}

// An upper bound of power x cos(at the light) x cos(at the receiver) / distance^2 over the
// node's lights seen from p, whose light comes only from the side n faces (n = 0: from both,
// as for a transmissive surface). Zero only where no light of the node can send p anything:
// the walk stays unbiased.
WF_INLINE float lightTreeImportance(LightTreeNode node, vec3 p, vec3 n) {
    if (!(node.power > 0.0f))
        return 0.0f;
    vec3 center = 0.5f * (node.lo + node.hi);
    vec3 toPoint = p - center;
    float distance2 = dot(toPoint, toPoint);
    float radius2 = 0.25f * dot(node.hi - node.lo, node.hi - node.lo);
    // Inside the box's bounding sphere every direction is possible; the distance is taken as
    // the sphere's radius there, so a point on a light does not get an infinite weight.
    if (distance2 <= radius2)
        return node.power / max(radius2, 1e-30f);
    float cosThetaW = dot(node.axis, toPoint * inversesqrt(distance2));
    if (node.twoSided != 0u)
        cosThetaW = abs(cosThetaW);
    float sinThetaW = lightTreeSafeSqrt(1.0f - cosThetaW * cosThetaW);
    // The angle between p and the cone, less the cone's half-angle and the half-angle the box
    // subtends from p, clamped at zero: cos(max(0, thetaW - thetaO - thetaB)).
    float sinThetaO = lightTreeSafeSqrt(1.0f - node.cosThetaO * node.cosThetaO);
    float cosThetaX = 1.0f, sinThetaX = 0.0f;
    if (cosThetaW < node.cosThetaO) {
        cosThetaX = cosThetaW * node.cosThetaO + sinThetaW * sinThetaO;
        sinThetaX = sinThetaW * node.cosThetaO - cosThetaW * sinThetaO;
    }
    float sin2ThetaB = radius2 / distance2;
    float cosThetaB = lightTreeSafeSqrt(1.0f - sin2ThetaB);
    float sinThetaB = sqrt(sin2ThetaB);
    float cosThetaP = lightTreeCosDifference(cosThetaX, sinThetaX, cosThetaB, sinThetaB);
    if (cosThetaP < node.cosThetaE)
        return 0.0f;
    float importance = node.power * max(cosThetaP, 0.0f) / distance2;
    if (dot(n, n) > 0.0f) { // the receiver's cosine, at best over the box
        float cosThetaI = -dot(n, toPoint) * inversesqrt(distance2);
        float sinThetaI = lightTreeSafeSqrt(1.0f - cosThetaI * cosThetaI);
        importance *= max(lightTreeCosDifference(cosThetaI, sinThetaI, cosThetaB, sinThetaB),
                          0.0f);
    }
    return importance;
}

// Probability of the first child at a node. By importance at p; where both children's bounds
// rule p out (each is tighter than their parent's, which did not), by power, so that every
// walk ends at a light and the pmf over the lights sums to 1.
WF_INLINE float lightTreeFirstChild(LightTreeNode first, LightTreeNode second, vec3 p, vec3 n) {
    float i0 = lightTreeImportance(first, p, n);
    float i1 = lightTreeImportance(second, p, n);
    if (i0 + i1 > 0.0f)
        return i0 / (i0 + i1);
    return first.power / (first.power + second.power);
}

#ifdef __cplusplus
struct LightTreeTraversal {
    const std::vector<LightTreeNode>* nodes = nullptr;
#define WF_LIGHT_TREE_NODE(i) (*nodes)[i]
#endif

// Walks from the root to a leaf for the shading point p with normal n (as in
// lightTreeImportance), reusing u after each choice. Returns
// the leaf's emitter and its pmf (WF_LIGHT_TREE_LEAF with pmf 0 only past the depth limit,
// which the builder keeps every leaf within).
WF_INLINE uint lightTreeSample(vec3 p, vec3 n, float u, WF_OUT(float) pmf) {
    pmf = 1.0f;
    uint node = 0u;
    for (uint depth = 0u; depth < WF_LIGHT_TREE_MAX_DEPTH; ++depth) {
        uint child = WF_LIGHT_TREE_NODE(node).child;
        if ((child & WF_LIGHT_TREE_LEAF) != 0u)
            return child & ~WF_LIGHT_TREE_LEAF;
        float first = lightTreeFirstChild(WF_LIGHT_TREE_NODE(node + 1u),
                                          WF_LIGHT_TREE_NODE(child), p, n);
        if (u < first) {
            pmf *= first;
            u = min(u / first, 0.99999994f);
            node = node + 1u;
        } else {
            float second = 1.0f - first;
            if (!(second > 0.0f))
                break;
            pmf *= second;
            u = min((u - first) / second, 0.99999994f);
            node = child;
        }
    }
    pmf = 0.0f;
    return WF_LIGHT_TREE_LEAF;
}

// The pmf lightTreeSample gives the light whose trail is `trail` (x: depths 0-31, y: 32-63).
WF_INLINE float lightTreePmf(vec3 p, vec3 n, uvec2 trail) {
    float pmf = 1.0f;
    uint node = 0u;
    for (uint depth = 0u; depth < WF_LIGHT_TREE_MAX_DEPTH; ++depth) {
        uint child = WF_LIGHT_TREE_NODE(node).child;
        if ((child & WF_LIGHT_TREE_LEAF) != 0u)
            return pmf;
        float first = lightTreeFirstChild(WF_LIGHT_TREE_NODE(node + 1u),
                                          WF_LIGHT_TREE_NODE(child), p, n);
        uint bits = depth < 32u ? trail.x : trail.y;
        bool second = ((bits >> (depth & 31u)) & 1u) != 0u;
        pmf *= second ? 1.0f - first : first;
        node = second ? child : node + 1u;
    }
    return 0.0f;
}

#ifdef __cplusplus
#undef WF_LIGHT_TREE_NODE
}; // struct LightTreeTraversal
} // namespace wf::gpu_types
#endif

#endif
