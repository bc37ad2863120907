// Sampling the directions a light subtends, shared by the shade pass and the CPU tests:
// spherical triangles (Arvo 1995), spherical caps for sphere lights, uniform spheres, and the
// equirectangular environment's direction <-> texel mapping.
#ifndef WF_LIGHT_SAMPLING_H
#define WF_LIGHT_SAMPLING_H

#include "types/glsl_cpp.h"
#include "sampling/sampling.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// Below this solid angle Arvo's construction loses its digits to cancellation, above it the
// triangle nearly covers a hemisphere: both ends fall back to area sampling (as pbrt-v4 does).
// The rule depends only on the triangle and the shading point, so the pdf seen by a BSDF ray
// that hits the triangle takes the same branch.
#define WF_MIN_SPHERICAL_SAMPLE_AREA 3e-4f
#define WF_MAX_SPHERICAL_SAMPLE_AREA 6.22f

WF_INLINE float safeSqrt(float x) { return sqrt(max(x, 0.0f)); }

WF_INLINE float safeAcos(float x) { return acos(clamp(x, -1.0f, 1.0f)); }

// Solid angle of the triangle abc seen from p (Van Oosterom and Strackee 1983).
WF_INLINE float triangleSolidAngle(vec3 p, vec3 p0, vec3 p1, vec3 p2) {
    vec3 a = normalize(p0 - p);
    vec3 b = normalize(p1 - p);
    vec3 c = normalize(p2 - p);
    float numerator = abs(dot(a, cross(b, c)));
    float denominator = 1.0f + dot(a, b) + dot(b, c) + dot(c, a);
    return 2.0f * atan(numerator, denominator);
}

WF_INLINE bool useSphericalTriangleSampling(float solidAngle) {
    return solidAngle >= WF_MIN_SPHERICAL_SAMPLE_AREA && solidAngle <= WF_MAX_SPHERICAL_SAMPLE_AREA;
}

WF_INLINE vec3 gramSchmidt(vec3 v, vec3 w) { return v - dot(v, w) * w; }

// Arvo's area-preserving map from u to a direction inside the spherical triangle with unit
// vertices a, b, c and area solidAngle (triangleSolidAngle: more accurate for small triangles
// than pi less the sum of the interior angles, and it spares the shade pass three acos); the
// density is 1 / solidAngle. Returns (0,0,0) for a degenerate triangle.
WF_INLINE vec3 sampleSphericalTriangle(vec3 a, vec3 b, vec3 c, float solidAngle, vec2 u) {
    vec3 nab = cross(a, b);
    vec3 nbc = cross(b, c);
    vec3 nca = cross(c, a);
    if (dot(nab, nab) == 0.0f || dot(nbc, nbc) == 0.0f || dot(nca, nca) == 0.0f)
        return vec3(0.0f);
    nab = normalize(nab);
    nca = normalize(nca);
    // The interior angle at a, from the normals of the great circles meeting there.
    float cosAlpha = clamp(dot(nab, -nca), -1.0f, 1.0f);
    float sinAlpha = safeSqrt(1.0f - cosAlpha * cosAlpha);
    // Choose the sub-triangle area A' = u.x * solidAngle, then the point C' on edge ac that
    // bounds it; Arvo's formulas take sin and cos of A' + pi, which are -sin and -cos of A'
    // (exactly, where the sum would round away a small A').
    float subArea = u.x * solidAngle;
    float sinSub = -sin(subArea);
    float cosSub = -cos(subArea);
    float sinPhi = sinSub * cosAlpha - cosSub * sinAlpha;
    float cosPhi = cosSub * cosAlpha + sinSub * sinAlpha;
    float k1 = cosPhi + cosAlpha;
    float k2 = sinPhi - sinAlpha * dot(a, b);
    float denominator = (k2 * sinPhi + k1 * cosPhi) * sinAlpha;
    float cosBp = denominator != 0.0f ? (k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) /
                                            denominator
                                      : 1.0f;
    cosBp = clamp(cosBp, -1.0f, 1.0f);
    float sinBp = safeSqrt(1.0f - cosBp * cosBp);
    vec3 cToA = gramSchmidt(c, a);
    if (dot(cToA, cToA) == 0.0f)
        return vec3(0.0f);
    vec3 cp = cosBp * a + sinBp * normalize(cToA);
    // Then a point on the arc from b to C'.
    float cosTheta = 1.0f - u.y * (1.0f - dot(cp, b));
    float sinTheta = safeSqrt(1.0f - cosTheta * cosTheta);
    vec3 cpToB = gramSchmidt(cp, b);
    if (dot(cpToB, cpToB) == 0.0f)
        return b;
    return normalize(cosTheta * b + sinTheta * normalize(cpToB));
}

// 1 - cos(thetaMax) of the cone a sphere of radius r subtends from distance d > r, computed
// without cancellation for small spheres.
WF_INLINE float sphereConeOneMinusCos(float r, float d) {
    float sin2 = (r * r) / (d * d);
    return sin2 / (1.0f + safeSqrt(1.0f - sin2));
}

// Uniform direction in the cone around unit `axis` with 1 - cos(thetaMax) = oneMinusCosMax;
// the density is 1 / (2 pi oneMinusCosMax).
WF_INLINE vec3 sampleCone(vec3 axis, float oneMinusCosMax, vec2 u) {
    float oneMinusCos = u.x * oneMinusCosMax;
    float cosTheta = 1.0f - oneMinusCos;
    float sinTheta = safeSqrt(oneMinusCos * (2.0f - oneMinusCos));
    float phi = 2.0f * WF_PI * u.y;
    vec3 t, b;
    buildOrthonormalBasis(axis, t, b);
    return normalize(cosTheta * axis + sinTheta * (cos(phi) * t + sin(phi) * b));
}

WF_INLINE vec3 sampleUniformSphere(vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = safeSqrt(1.0f - z * z);
    float phi = 2.0f * WF_PI * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

// Distance along unit d from o to the near side of the sphere, or -1 on a miss. The
// discriminant is clamped so a direction sampled inside the cone never misses by rounding.
WF_INLINE float raySphereNear(vec3 o, vec3 d, vec3 center, float radius, bool clampGrazing) {
    vec3 oc = o - center;
    float b = dot(oc, d);
    // (|oc|^2 - b^2) is the squared distance of the line from the centre: stable form.
    vec3 perpendicular = oc - b * d;
    float discriminant = radius * radius - dot(perpendicular, perpendicular);
    if (discriminant < 0.0f) {
        if (!clampGrazing)
            return -1.0f;
        discriminant = 0.0f;
    }
    float root = sqrt(discriminant);
    float t0 = -b - root;
    float t1 = -b + root;
    return t0 > 0.0f ? t0 : (t1 > 0.0f ? t1 : -1.0f);
}

// Equirectangular mapping: +Y is up (v = 0 at the zenith), longitude phi = atan2(z, x) along u.
WF_INLINE vec2 directionToEquirect(vec3 d) {
    float phi = atan(d.z, d.x);
    float u = phi * (0.5f * WF_INV_PI);
    u = u < 0.0f ? u + 1.0f : u;
    return vec2(min(u, 0.99999994f), min(safeAcos(d.y) * WF_INV_PI, 0.99999994f));
}

WF_INLINE vec3 equirectToDirection(vec2 uv) {
    float phi = uv.x * 2.0f * WF_PI;
    float theta = uv.y * WF_PI;
    float sinTheta = sin(theta);
    return vec3(sinTheta * cos(phi), cos(theta), sinTheta * sin(phi));
}

// Solid-angle density of a direction whose (u, v) has density pdfUV over [0,1)^2.
WF_INLINE float equirectSolidAnglePdf(float pdfUV, vec3 d) {
    float sinTheta = safeSqrt(1.0f - d.y * d.y);
    return sinTheta > 0.0f ? pdfUV / (2.0f * WF_PI * WF_PI * sinTheta) : 0.0f;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
