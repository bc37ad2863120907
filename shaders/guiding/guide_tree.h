// Looking up, sampling and evaluating the path guide's SD-tree (types/guide_types.h): shared by
// the shade pass and the megakernel (GLSL) and by the host builder and CPU tests (C++), so the
// chi-square tests check exactly the pdf the GPU divides by.
//
// GLSL includers define WF_GUIDE_SPATIAL(i), WF_GUIDE_SAMPLING(i) and WF_GUIDE_BUILDING(i),
// expressions yielding node i of the three arrays; in C++ the tree walks are members of
// GuideTreeView, which reads vectors.
#ifndef WF_GUIDE_TREE_H
#define WF_GUIDE_TREE_H

#include "types/glsl_cpp.h"
#include "types/guide_types.h"

#ifdef __cplusplus
#include <vector>
namespace wf::gpu_types {
using namespace glm;
#endif

#define WF_GUIDE_INV_4PI 0.07957747154594767f
#define WF_GUIDE_ONE_MINUS_EPS 0.99999994f

// World direction -> the unit square ((cos theta + 1) / 2, phi / 2 pi): equal areas map to
// equal solid angles (4 pi per unit area).
WF_INLINE vec2 guideDirToSquare(vec3 w) {
    float cosTheta = clamp(w.z, -1.0f, 1.0f);
    float phi = atan(w.y, w.x);
    if (phi < 0.0f)
        phi += 2.0f * 3.14159265358979323846f;
    vec2 x = vec2(0.5f * (cosTheta + 1.0f), phi * 0.15915494309189535f);
    return clamp(x, vec2(0.0f), vec2(WF_GUIDE_ONE_MINUS_EPS));
}

WF_INLINE vec3 guideSquareToDir(vec2 x) {
    float cosTheta = 2.0f * x.x - 1.0f;
    float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * 3.14159265358979323846f * x.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

// The mixture of BSDF sampling (share bsdfFraction) and the guide: its pdf is what both sides
// of multiple importance sampling against next-event estimation weigh. Positive wherever the
// BSDF's is, as long as bsdfFraction > 0.
WF_INLINE float guideMixturePdf(float bsdfPdf, float guidePdf, float bsdfFraction) {
    return bsdfFraction * bsdfPdf + (1.0f - bsdfFraction) * guidePdf;
}

// The BSDF shares a leaf may learn (WF_GUIDE_FRACTIONS of them): all above 0, so the mixture
// stays positive wherever the BSDF is; up to BSDF sampling alone (1: where a leaf's guide
// does not match its integrand, a diffuse room's smooth indirect light, its vertices skip
// the guide's walks outside training). None below 0.5: a sharp guide's records rarely show
// the BSDF sample that its gaps leave to 1 / share, so a lower share learnt from them lost
// (docs/guiding.md, "The learnt BSDF share").
WF_INLINE float guideFractionCandidate(uint j) {
    return j == 0u ? 0.5f : j == 1u ? 0.6f : j == 2u ? 0.7f : j == 3u ? 0.8f
         : j == 4u ? 0.9f : 1.0f;
}

// One training record's second moment had its vertex sampled with share `candidate`:
// (f |cos| L / p_used)^2 x p_used / p_candidate, whose mean over records drawn with the share
// used estimates the integral of (f |cos| L)^2 / p_candidate. estimate: f |cos| L / p_used.
WF_INLINE float guideCandidateMoment(float estimate, float bsdfPdf, float guidePdf,
                                     float usedFraction, float candidate) {
    float used = guideMixturePdf(bsdfPdf, guidePdf, usedFraction);
    float other = guideMixturePdf(bsdfPdf, guidePdf, candidate);
    return other > 0.0f ? estimate * estimate * (used / other) : 0.0f;
}

// Parallax (Ruppert et al. 2020 reproject their mixtures the same way): a leaf's quadtree
// holds directions seen from a centre c to radiance placed on the sphere of radius R around c,
// so a vertex at x = c + offset reaches the same point through another direction. A leaf's
// few records spread over its whole box; without this, a bright patch 2 m away looks blurred
// over every direction it takes from anywhere in the box. R is the learnt distance, at least
// 1.5 |offset| so that x lies inside the sphere: every direction from x meets it once, the map
// is a bijection and its Jacobian stays within [0.11, 3.8].
WF_INLINE float guideParallaxRadius(vec3 offset, float radianceDistance) {
    return radianceDistance > 0.0f ? max(radianceDistance, 1.5f * length(offset)) : 0.0f;
}

// Direction w seen from the centre -> the direction from x to the same point of the sphere of
// radius `radius` (0: w itself). jacobian: d(solid angle at c) / d(solid angle at x), so a
// density at c times it is the density at x.
WF_INLINE vec3 guideParallaxFromCentre(vec3 offset, float radius, vec3 w, WF_OUT(float) jacobian) {
    jacobian = 1.0f;
    if (!(radius > 0.0f))
        return w;
    vec3 toPoint = radius * w - offset;
    float t = length(toPoint);
    vec3 wx = toPoint / t;
    jacobian = t * t / (radius * radius * max(dot(wx, w), 1e-6f));
    return wx;
}

// The inverse: direction wx from x -> the direction from the centre to the point where it meets
// the sphere, with the same jacobian.
WF_INLINE vec3 guideParallaxToCentre(vec3 offset, float radius, vec3 wx, WF_OUT(float) jacobian) {
    jacobian = 1.0f;
    if (!(radius > 0.0f))
        return wx;
    float b = dot(offset, wx);
    float c = dot(offset, offset) - radius * radius; // < 0: x is inside
    float t = -b + sqrt(max(b * b - c, 0.0f));
    vec3 w = normalize(offset + t * wx);
    jacobian = t * t / (radius * radius * max(dot(wx, w), 1e-6f));
    return w;
}

// One quadrant choice: x-half by u.x, then y-half within it by u.y, each u rescaled to [0, 1)
// for the next level. Returns the quadrant (x-half | y-half << 1).
WF_INLINE uint guideChooseQuadrant(vec4 prob, WF_INOUT(vec2) u) {
    float left = prob.x + prob.z;
    uint xh = 0u;
    if (u.x < left) {
        u.x = min(u.x / left, WF_GUIDE_ONE_MINUS_EPS);
    } else {
        xh = 1u;
        u.x = min((u.x - left) / max(1.0f - left, 1e-30f), WF_GUIDE_ONE_MINUS_EPS);
    }
    float lower = xh == 0u ? prob.x : prob.y;
    float upper = xh == 0u ? prob.z : prob.w;
    float bottom = lower / max(lower + upper, 1e-30f);
    uint yh = 0u;
    if (u.y < bottom) {
        u.y = min(u.y / bottom, WF_GUIDE_ONE_MINUS_EPS);
    } else {
        yh = 1u;
        u.y = min((u.y - bottom) / max(1.0f - bottom, 1e-30f), WF_GUIDE_ONE_MINUS_EPS);
    }
    return xh | (yh << 1u);
}

WF_INLINE float guideQuadrantProb(vec4 prob, uint q) {
    return q == 0u ? prob.x : (q == 1u ? prob.y : (q == 2u ? prob.z : prob.w));
}

WF_INLINE uint guideQuadrantChild(uvec4 child, uint q) {
    return q == 0u ? child.x : (q == 1u ? child.y : (q == 2u ? child.z : child.w));
}

#ifdef __cplusplus
struct GuideTreeView {
    const std::vector<GuideSpatialNode>* spatial = nullptr;
    const std::vector<GuideDirNode>* sampling = nullptr;
    const std::vector<GuideDirNode>* building = nullptr;
#define WF_GUIDE_SPATIAL(i) (*spatial)[i]
#define WF_GUIDE_SAMPLING(i) (*sampling)[i]
#define WF_GUIDE_BUILDING(i) (*building)[i]
#endif

// The spatial leaf (its node index) holding the point whose position in the tree's box is
// p01 (each coordinate in [0, 1]).
WF_INLINE uint guideSpatialLeaf(vec3 p01) {
    vec3 p = clamp(p01, vec3(0.0f), vec3(WF_GUIDE_ONE_MINUS_EPS));
    uint node = 0u;
    for (uint depth = 0u; depth < WF_GUIDE_MAX_SPATIAL_DEPTH; ++depth) {
        uint child = WF_GUIDE_SPATIAL(node).child;
        if ((child & WF_GUIDE_LEAF) != 0u)
            return node;
        uint axis = depth % 3u;
        float c = axis == 0u ? p.x : (axis == 1u ? p.y : p.z);
        bool second = c >= 0.5f;
        c = second ? 2.0f * c - 1.0f : 2.0f * c;
        c = min(c, WF_GUIDE_ONE_MINUS_EPS);
        if (axis == 0u)
            p.x = c;
        else if (axis == 1u)
            p.y = c;
        else
            p.z = c;
        node = second ? child + 1u : child;
    }
    return node;
}

// Draws a point of the unit square from the frozen quadtree at `root`; squarePdf is its
// density on the square (4 pi times the density on the sphere).
WF_INLINE vec2 guideSampleSquare(uint root, vec2 u, WF_OUT(float) squarePdf) {
    squarePdf = 1.0f;
    vec2 origin = vec2(0.0f);
    float size = 1.0f;
    uint node = root;
    for (uint depth = 0u; depth < WF_GUIDE_MAX_DIR_DEPTH; ++depth) {
        GuideDirNode n = WF_GUIDE_SAMPLING(node);
        uint q = guideChooseQuadrant(n.prob, u);
        squarePdf *= 4.0f * guideQuadrantProb(n.prob, q);
        size *= 0.5f;
        origin += size * vec2(float(q & 1u), float(q >> 1u));
        node = guideQuadrantChild(n.child, q);
        if (node == 0u)
            break;
    }
    return origin + size * u;
}

// The density on the square of guideSampleSquare at the point x.
WF_INLINE float guidePdfSquare(uint root, vec2 x) {
    float pdf = 1.0f;
    uint node = root;
    for (uint depth = 0u; depth < WF_GUIDE_MAX_DIR_DEPTH; ++depth) {
        GuideDirNode n = WF_GUIDE_SAMPLING(node);
        uint xh = x.x >= 0.5f ? 1u : 0u;
        uint yh = x.y >= 0.5f ? 1u : 0u;
        uint q = xh | (yh << 1u);
        pdf *= 4.0f * guideQuadrantProb(n.prob, q);
        x = min(2.0f * x - vec2(float(xh), float(yh)), vec2(WF_GUIDE_ONE_MINUS_EPS));
        node = guideQuadrantChild(n.child, q);
        if (node == 0u)
            break;
    }
    return pdf;
}

// One walk down the frozen quadtree at `root` for the one-sample mixture's continuation, which
// needs per lane either a guide sample or the guide's density at a BSDF-sampled point: with
// `draw`, quadrants are chosen by u (guideSampleSquare) and the point drawn is returned; else
// by the point x (guidePdfSquare), which is returned. squarePdf: the density on the square at
// the returned point. One loop for both keeps SIMD lanes of either kind walking together
// (a GPU or lavapipe runs both branches of a divergent one), where a sample and then its pdf
// took two walks.
WF_INLINE vec2 guideSampleOrPdfSquare(uint root, bool draw, vec2 u, vec2 x,
                                      WF_OUT(float) squarePdf) {
    squarePdf = 1.0f;
    vec2 origin = vec2(0.0f);
    float size = 1.0f;
    vec2 r = draw ? u : x; // rescaled to the current node's square as the walk descends
    uint node = root;
    for (uint depth = 0u; depth < WF_GUIDE_MAX_DIR_DEPTH; ++depth) {
        GuideDirNode n = WF_GUIDE_SAMPLING(node);
        uint q;
        if (draw) {
            q = guideChooseQuadrant(n.prob, r);
        } else {
            uint xh = r.x >= 0.5f ? 1u : 0u;
            uint yh = r.y >= 0.5f ? 1u : 0u;
            q = xh | (yh << 1u);
            r = min(2.0f * r - vec2(float(xh), float(yh)), vec2(WF_GUIDE_ONE_MINUS_EPS));
        }
        squarePdf *= 4.0f * guideQuadrantProb(n.prob, q);
        size *= 0.5f;
        origin += size * vec2(float(q & 1u), float(q >> 1u));
        node = guideQuadrantChild(n.child, q);
        if (node == 0u)
            break;
    }
    return draw ? origin + size * r : x;
}

// A world direction from the frozen quadtree at `root`, with its solid-angle pdf.
WF_INLINE vec3 guideSample(uint root, vec2 u, WF_OUT(float) pdf) {
    float squarePdf;
    vec2 x = guideSampleSquare(root, u, squarePdf);
    pdf = squarePdf * WF_GUIDE_INV_4PI;
    return guideSquareToDir(x);
}

WF_INLINE float guidePdf(uint root, vec3 w) {
    return guidePdfSquare(root, guideDirToSquare(w)) * WF_GUIDE_INV_4PI;
}

// The guide's solid-angle density of direction w at a vertex `offset` from the leaf's sampling
// centre, with parallax radius `radius` (guideParallaxRadius; 0: none).
WF_INLINE float guidePdfAt(uint root, vec3 offset, float radius, vec3 w) {
    float jacobian;
    vec3 fromCentre = guideParallaxToCentre(offset, radius, w, jacobian);
    return guidePdf(root, fromCentre) * jacobian;
}

// The building quadtree's cell (node * 4 + quadrant, a leaf quadrant) holding square point x:
// where a splat for that direction lands.
WF_INLINE uint guideBuildingCell(uint root, vec2 x) {
    uint node = root;
    for (uint depth = 0u; depth < WF_GUIDE_MAX_DIR_DEPTH; ++depth) {
        uint xh = x.x >= 0.5f ? 1u : 0u;
        uint yh = x.y >= 0.5f ? 1u : 0u;
        uint q = xh | (yh << 1u);
        x = min(2.0f * x - vec2(float(xh), float(yh)), vec2(WF_GUIDE_ONE_MINUS_EPS));
        uint child = guideQuadrantChild(WF_GUIDE_BUILDING(node).child, q);
        if (child == 0u || depth + 1u == WF_GUIDE_MAX_DIR_DEPTH)
            return node * 4u + q;
        node = child;
    }
    return node * 4u;
}

#ifdef __cplusplus
#undef WF_GUIDE_SPATIAL
#undef WF_GUIDE_SAMPLING
#undef WF_GUIDE_BUILDING
}; // struct GuideTreeView
} // namespace wf::gpu_types
#endif

#endif
