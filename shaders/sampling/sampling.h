// Sample warps and MIS weights shared by the shade pass (GLSL) and the CPU tests (C++), so the
// chi-square tests in tests/unit/test_sampling.cpp check exactly what the GPU draws.
// Every warp maps a point u in [0,1)^2 to its domain; local frames are z-up.
#ifndef WF_SAMPLING_H
#define WF_SAMPLING_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

#define WF_PI 3.14159265358979323846f
#define WF_INV_PI 0.31830988618379067154f
#define WF_PI_OVER_2 1.57079632679489661923f
#define WF_PI_OVER_4 0.78539816339744830962f

// Shirley-Chiu concentric mapping: keeps strata adjacent and areas proportional, unlike the
// polar r = sqrt(u) mapping, which squeezes the cells near the centre.
WF_INLINE vec2 sampleConcentricDisk(vec2 u) {
    vec2 uo = 2.0f * u - vec2(1.0f);
    if (uo.x == 0.0f && uo.y == 0.0f) {
        return vec2(0.0f);
    }
    float r;
    float theta;
    if (abs(uo.x) > abs(uo.y)) {
        r = uo.x;
        theta = WF_PI_OVER_4 * (uo.y / uo.x);
    } else {
        r = uo.y;
        theta = WF_PI_OVER_2 - WF_PI_OVER_4 * (uo.x / uo.y);
    }
    return r * vec2(cos(theta), sin(theta));
}

// Malley's method: project a uniform disk sample up onto the hemisphere. Density cos(theta)/pi.
WF_INLINE vec3 sampleCosineHemisphere(vec2 u) {
    vec2 d = sampleConcentricDisk(u);
    // max() because rounding can push x^2 + y^2 a hair above 1 at the disk's rim.
    float z = sqrt(max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
    return vec3(d.x, d.y, z);
}

// Solid-angle density of sampleCosineHemisphere; zero below the horizon.
WF_INLINE float cosineHemispherePdf(float cosTheta) {
    return max(cosTheta, 0.0f) * WF_INV_PI;
}

// Uniform barycentrics (b1, b2) weighting p1 and p2 (b0 = 1 - b1 - b2). Heitz 2019's
// low-distortion fold: no sqrt, and neighbouring u stay neighbours on the triangle.
WF_INLINE vec2 sampleUniformTriangle(vec2 u) {
    float b1;
    float b2;
    if (u.x < u.y) {
        b1 = u.x * 0.5f;
        b2 = u.y - b1;
    } else {
        b2 = u.y * 0.5f;
        b1 = u.x - b2;
    }
    return vec2(b1, b2);
}

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited": branchless apart from the sign,
// and continuous everywhere except where n.z changes sign. n must be unit length.
WF_INLINE void buildOrthonormalBasis(vec3 n, WF_OUT(vec3) t, WF_OUT(vec3) b) {
    // GLSL's sign() returns 0 at 0, which would divide by zero below; this maps -0 and +0 to 1.
    float sgn = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (sgn + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0f + sgn * n.x * n.x * a, sgn * c, -sgn * n.x);
    b = vec3(c, sgn + n.y * n.y * a, -n.y);
}

// Veach's power heuristic (beta = 2): the MIS weight of a sample drawn with density pdfA
// when pdfB could also have produced it. Never NaN for pdfs in [0, inf].
WF_INLINE float powerHeuristic(float pdfA, float pdfB) {
    if (pdfB == 0.0f) {
        return 1.0f; // the other strategy cannot produce this sample: all weight here
    }
    if (pdfA == 0.0f) {
        return 0.0f;
    }
    // Delta distributions arrive as inf; inf/inf would be NaN.
    if (isinf(pdfA)) {
        return isinf(pdfB) ? 0.5f : 1.0f;
    }
    if (isinf(pdfB)) {
        return 0.0f;
    }
    // Divide before squaring: a^2 / (a^2 + b^2) overflows for pdfs above ~1e19.
    float r = min(pdfB / pdfA, 1e18f);
    return 1.0f / (1.0f + r * r);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
