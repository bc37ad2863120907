// The scene of tests/unit/test_bidir_reference.cpp: a closed box of axis-aligned Lambertian
// quads (a block inside it for shadows, one wall with a tilted shading normal so the adjoint
// factor is not 1), an area light on the ceiling that emits from its front face, and a pinhole
// camera inside the box that sees the light's edge. Ray casting is brute force over the quads:
// the point is the estimators, which run the shared headers on it exactly as a GPU pass would.
#ifndef WF_TESTS_BIDIR_REFERENCE_SCENE_H
#define WF_TESTS_BIDIR_REFERENCE_SCENE_H

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shaders/bidir/camera_importance.h"
#include "shaders/bsdf/bsdf.h"

namespace wf::test::bidir {

using glm::vec2;
using glm::vec3;
using gpu_types::BsdfParams;
using gpu_types::CameraGeometry;

// corner + a e1 + b e2 for a, b in [0, 1]; e1 and e2 orthogonal. The geometric normal
// cross(e1, e2) is the emitting side of a light; the surfaces themselves are two-sided.
struct Quad {
    vec3 corner, e1, e2;
    vec3 albedo;
    vec3 emitted;        // radiance leaving the front face; 0 for every quad but the light
    vec3 shadingTilt{0}; // added to the geometric normal to make the shading normal

    vec3 normal() const { return glm::normalize(glm::cross(e1, e2)); }
    vec3 shadingNormal() const { return glm::normalize(normal() + shadingTilt); }
    float area() const { return glm::length(glm::cross(e1, e2)); }
    bool isLight() const { return emitted != vec3(0.0f); }
};

// Pure Lambert through the general glTF BSDF (specular 0 leaves baseColor / pi exactly): the
// path the shade pass runs for it, not the WF_BSDF_DIFFUSE_ONLY shortcut.
inline BsdfParams lambert(vec3 albedo) {
    return BsdfParams{albedo, 0.0f, 0.5f, 1.5f, 0.0f, 0.0f, vec3(1.0f)};
}

struct Scene {
    std::vector<Quad> quads;
    int light = -1;
    CameraGeometry camera{};
};

inline Quad axisQuad(vec3 corner, vec3 e1, vec3 e2, vec3 albedo) {
    return Quad{corner, e1, e2, albedo, vec3(0.0f)};
}

// Box [-1, 1] x [0, 2] x [-1, 1]; the camera at z = 0.95 looks down -z, 8x6 pixels, and sees
// the light (y just under 2, z in [-0.6, 0]) in part of its top row.
inline Scene boxScene() {
    Scene s;
    const vec3 white(0.75f), red(0.75f, 0.2f, 0.15f), green(0.2f, 0.7f, 0.25f);
    auto& q = s.quads;
    q.push_back(axisQuad(vec3(-1, 0, -1), vec3(0, 0, 2), vec3(2, 0, 0), white)); // floor
    q.push_back(axisQuad(vec3(-1, 2, -1), vec3(2, 0, 0), vec3(0, 0, 2), white)); // ceiling
    q.push_back(axisQuad(vec3(-1, 0, -1), vec3(2, 0, 0), vec3(0, 2, 0), vec3(0.6f))); // back
    q.back().shadingTilt = vec3(0.35f, 0.2f, 0.0f);
    q.push_back(axisQuad(vec3(-1, 0, 1), vec3(0, 2, 0), vec3(2, 0, 0), vec3(0.5f))); // front
    q.push_back(axisQuad(vec3(-1, 0, -1), vec3(0, 2, 0), vec3(0, 0, 2), red));       // left
    q.push_back(axisQuad(vec3(1, 0, -1), vec3(0, 0, 2), vec3(0, 2, 0), green));      // right
    // The block under one side of the light: top and four sides, its shadow on the floor.
    const vec3 grey(0.6f, 0.6f, 0.5f), lo(-0.6f, 0.0f, -0.6f), hi(-0.1f, 0.9f, -0.1f);
    const vec3 dx(hi.x - lo.x, 0, 0), dy(0, hi.y, 0), dz(0, 0, hi.z - lo.z);
    q.push_back(axisQuad(vec3(lo.x, hi.y, lo.z), dz, dx, grey));
    q.push_back(axisQuad(lo, dx, dy, grey));
    q.push_back(axisQuad(vec3(lo.x, 0, hi.z), dy, dx, grey));
    q.push_back(axisQuad(lo, dy, dz, grey));
    q.push_back(axisQuad(vec3(hi.x, 0, lo.z), dz, dy, grey));
    // The light faces down (cross(e1, e2) = -y), black: what reaches it is absorbed.
    s.light = int(q.size());
    q.push_back(Quad{vec3(-0.3f, 1.999f, -0.6f), vec3(0.6f, 0, 0), vec3(0, 0, 0.6f), vec3(0.0f),
                     vec3(6.0f, 5.5f, 4.5f)});

    CameraGeometry& c = s.camera;
    c.position = vec3(0.0f, 1.1f, 0.95f);
    c.forward = vec3(0, 0, -1);
    c.right = vec3(1, 0, 0);
    c.up = vec3(0, 1, 0);
    c.tanHalfFovY = 0.75f;
    c.width = 8u;
    c.height = 6u;
    c.aspect = 8.0f / 6.0f;
    c.lensRadius = 0.0f;
    c.focusDistance = 1.0f;
    c.orthoHalfHeight = 0.0f;
    return s;
}

struct Hit {
    int quad = -1;
    float t = 0.0f;
    vec3 p{0.0f};
};

// Nearest quad along the ray, skipping `from` (the quad the ray leaves: planar, it cannot be
// hit again, so no epsilon is needed).
inline Hit intersect(const Scene& s, vec3 o, vec3 d, int from) {
    Hit best;
    best.t = 1e30f;
    for (int i = 0; i < int(s.quads.size()); ++i) {
        const Quad& q = s.quads[i];
        vec3 n = glm::cross(q.e1, q.e2);
        float dn = glm::dot(d, n);
        if (i == from || dn == 0.0f) {
            continue;
        }
        float t = glm::dot(q.corner - o, n) / dn;
        if (!(t > 0.0f) || t >= best.t) {
            continue;
        }
        vec3 p = o + t * d, r = p - q.corner;
        float a = glm::dot(r, q.e1) / glm::dot(q.e1, q.e1);
        float b = glm::dot(r, q.e2) / glm::dot(q.e2, q.e2);
        if (a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f) {
            best = Hit{i, t, p};
        }
    }
    if (best.quad < 0) {
        best.t = 0.0f;
    }
    return best;
}

// Whether the segment between a point on quad qa and one on quad qb (-1: the camera) is clear.
// The end quads are skipped: a segment ending on a plane cannot cross it before its end.
inline bool visible(const Scene& s, vec3 a, int qa, vec3 b, int qb) {
    vec3 d = b - a;
    float len = glm::length(d);
    Hit h = intersect(s, a, d / len, qa);
    return !(h.quad >= 0 && h.quad != qb && h.t < len * (1.0f - 1e-5f));
}

// The local shading frame of a quad (+z the shading normal), as path_vertex.glsl builds it.
struct Frame {
    vec3 t, b, ns, ng;
    vec3 toLocal(vec3 v) const { return vec3(glm::dot(v, t), glm::dot(v, b), glm::dot(v, ns)); }
    vec3 toWorld(vec3 v) const { return t * v.x + b * v.y + ns * v.z; }
};

inline Frame frameOf(const Quad& q) {
    Frame f;
    f.ns = q.shadingNormal();
    f.ng = q.normal();
    gpu_types::buildOrthonormalBasis(f.ns, f.t, f.b);
    return f;
}

// camera_ray.glsl's pinhole ray through raster point pixel + jitter (unit length).
inline vec3 cameraRayDirection(const CameraGeometry& c, glm::uvec2 pixel, vec2 jitter) {
    vec2 ndc = (vec2(pixel) + jitter) / vec2(c.width, c.height) * 2.0f - 1.0f;
    vec3 d = c.forward + c.right * (ndc.x * c.tanHalfFovY * c.aspect) -
             c.up * (ndc.y * c.tanHalfFovY);
    return glm::normalize(d);
}

// A small fast generator (PCG32) for the millions of samples; uniform floats in [0, 1).
struct Rng {
    uint64_t state;
    explicit Rng(uint64_t seed) : state(seed * 6364136223846793005ull + 1442695040888963407ull) {}
    uint32_t next() {
        uint64_t old = state;
        state = old * 6364136223846793005ull + 1442695040888963407ull;
        uint32_t x = uint32_t(((old >> 18u) ^ old) >> 27u), r = uint32_t(old >> 59u);
        return (x >> r) | (x << ((32u - r) & 31u));
    }
    float uniform() { return float(next() >> 8) * 0x1p-24f; }
    vec2 uniform2() {
        float a = uniform();
        return vec2(a, uniform());
    }
};

} // namespace wf::test::bidir

#endif
