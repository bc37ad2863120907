// The first segment of a light subpath (issue 46): an emitted ray from each kind of light, with
// the origin's area density pdfA and the direction's solid-angle density pdfW kept apart, as
// BDPT's and VCM's MIS weights need them, and the emitted value that makes the subpath's
// throughput emitted cos / (pdfA pdfW) (emissionThroughput). Pure math on plain parameters, so
// tests/unit/test_light_emission.cpp checks what a light raygen pass would run. The light's
// choice (the light table's pmf) is the caller's and is in none of these densities.
//
// A Dirac part (the position of a point or spot light, the direction of a directional light)
// has density 1 and its flag set: the measurement integrates it away, and MIS must know it can
// never be hit or connected to. cos at a Dirac position is 1: the emitted value there is an
// intensity (W/sr), already per unit solid angle.
//
// Sample dimensions of a light subpath's first segment, beside the camera path's (rng.h):
//   1D  light choice
//   2D  uPoint: the point on the light (triangle, sphere; the disk for directional and
//       environment light); point and spot lights leave it unused
//   2D  uDirection: the direction of emission (triangle: its first number also picks the side
//       of a double-sided one; the environment: the point in its texel)
//   1D  uExtra: the environment's texel choice
// so every kind keeps the same numbering, as a camera path's bounce does.
#ifndef WF_LIGHT_EMISSION_H
#define WF_LIGHT_EMISSION_H

#include "types/glsl_cpp.h"
#include "sampling/sampling.h"
#include "lights/light_sampling.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

#define WF_EMISSION_DELTA_POSITION 1u
#define WF_EMISSION_DELTA_DIRECTION 2u

struct EmissionSample {
    vec3 origin;
    float pdfA;     // area density of the origin; 1 for a Dirac position
    vec3 direction; // unit, the way light travels
    float pdfW;     // solid-angle density of direction; 1 for a Dirac direction
    vec3 normal;    // the emitting side's normal (the disk's for far lights); 0 at a point
    uint flags;     // WF_EMISSION_DELTA_*
    vec3 emitted;   // radiance (surfaces, environment), intensity (point, spot), irradiance
                    // (directional)
    float pad0;
};

// emitted cos / (pdfA pdfW): what the light vertex's throughput starts from, over the light
// choice's pmf. 0 for a sample with no density (a direction grazing the surface).
WF_INLINE vec3 emissionThroughput(EmissionSample s) {
    float cosOrigin = (s.flags & WF_EMISSION_DELTA_POSITION) != 0u
                          ? 1.0f
                          : abs(dot(s.normal, s.direction));
    float density = s.pdfA * s.pdfW;
    return density > 0.0f ? s.emitted * (cosOrigin / density) : vec3(0.0f);
}

// A cosine-weighted direction about unit n and its density, cos / pi.
WF_INLINE vec3 emitCosineDirection(vec3 n, vec2 u, WF_OUT(float) pdfW) {
    vec3 t, b;
    buildOrthonormalBasis(n, t, b);
    vec3 local = sampleCosineHemisphere(u);
    pdfW = cosineHemispherePdf(local.z);
    return normalize(t * local.x + b * local.y + n * local.z);
}

// Emissive triangle, Le leaving the front face (p0, p1, p2 counter-clockwise) or both: uniform
// point (pdfA 1 / area), cosine direction (pdfW cos / pi, halved when doubleSided picks a side).
// Dimensions: uPoint (2D), uDirection (2D). Textured emission: the point's barycentrics are
// sampleUniformTriangle(uPoint), (b1, b2) weighting (p1, p2), for the caller to look Le up.
WF_INLINE EmissionSample emitTriangle(vec3 p0, vec3 p1, vec3 p2, vec3 Le, bool doubleSided,
                                      vec2 uPoint, vec2 uDirection) {
    EmissionSample s;
    vec3 cross12 = cross(p1 - p0, p2 - p0);
    float area = 0.5f * length(cross12);
    vec2 b = sampleUniformTriangle(uPoint);
    s.origin = p0 + b.x * (p1 - p0) + b.y * (p2 - p0);
    s.pdfA = area > 0.0f ? 1.0f / area : 0.0f;
    s.normal = area > 0.0f ? cross12 / (2.0f * area) : vec3(0.0f, 0.0f, 1.0f);
    float sideScale = 1.0f;
    if (doubleSided) {
        // pbrt-v4's fold: the side from the first number, rescaled so both keep a full [0, 1).
        bool back = uDirection.x >= 0.5f;
        uDirection.x = min(back ? 2.0f * uDirection.x - 1.0f : 2.0f * uDirection.x,
                           0.99999994f);
        s.normal = back ? -s.normal : s.normal;
        sideScale = 0.5f;
    }
    s.direction = emitCosineDirection(s.normal, uDirection, s.pdfW);
    s.pdfW *= sideScale;
    s.flags = 0u;
    s.emitted = Le;
    s.pad0 = 0.0f;
    return s;
}

// Sphere light of uniform radiance (lights.glsl's sphereRadiance): uniform point (pdfA
// 1 / (4 pi R^2)), cosine direction about the outward normal (pdfW cos / pi).
// Dimensions: uPoint (2D), uDirection (2D).
WF_INLINE EmissionSample emitSphere(vec3 center, float radius, vec3 radiance, vec2 uPoint,
                                    vec2 uDirection) {
    EmissionSample s;
    s.normal = sampleUniformSphere(uPoint);
    s.origin = center + radius * s.normal;
    s.pdfA = radius > 0.0f ? 1.0f / (4.0f * WF_PI * radius * radius) : 0.0f;
    s.direction = emitCosineDirection(s.normal, uDirection, s.pdfW);
    s.flags = 0u;
    s.emitted = radiance;
    s.pad0 = 0.0f;
    return s;
}

// Point light of intensity I: Dirac position (pdfA 1), uniform direction (pdfW 1 / (4 pi)).
// Dimensions: uDirection (2D).
WF_INLINE EmissionSample emitPoint(vec3 position, vec3 intensity, vec2 uDirection) {
    EmissionSample s;
    s.origin = position;
    s.pdfA = 1.0f;
    s.direction = sampleUniformSphere(uDirection);
    s.pdfW = 0.25f * WF_INV_PI;
    s.normal = vec3(0.0f);
    s.flags = WF_EMISSION_DELTA_POSITION;
    s.emitted = intensity;
    s.pad0 = 0.0f;
    return s;
}

// glTF's smooth falloff between the outer and inner cone, as lights.glsl's sampleDeltaLight
// applies it (the 1e-4 keeps equal cones from dividing by zero).
WF_INLINE float spotFalloff(float cosAngle, float cosInner, float cosOuter) {
    float x = clamp((cosAngle - cosOuter) / max(cosInner - cosOuter, 1e-4f), 0.0f, 1.0f);
    return x * x;
}

// Spot light along unit `axis`: Dirac position (pdfA 1), uniform direction in the outer cone
// (pdfW 1 / (2 pi (1 - cosOuter))), emitted I x the falloff; only the cone carries power, so
// no sample is wasted outside it. Dimensions: uDirection (2D).
WF_INLINE EmissionSample emitSpot(vec3 position, vec3 axis, vec3 intensity, float cosInner,
                                  float cosOuter, vec2 uDirection) {
    EmissionSample s;
    float oneMinusCosOuter = 1.0f - cosOuter;
    s.origin = position;
    s.pdfA = 1.0f;
    s.direction = sampleCone(axis, oneMinusCosOuter, uDirection);
    s.pdfW = oneMinusCosOuter > 0.0f ? 1.0f / (2.0f * WF_PI * oneMinusCosOuter) : 0.0f;
    s.normal = vec3(0.0f);
    s.flags = WF_EMISSION_DELTA_POSITION;
    s.emitted = intensity * spotFalloff(dot(s.direction, axis), cosInner, cosOuter);
    s.pad0 = 0.0f;
    return s;
}

// A uniform point on the disk of radius sceneRadius facing unit `direction`, centred on the
// scene's axis along it and 2 sceneRadius back from the centre: wholly outside the bounding
// sphere, and its rays along `direction` cover the sphere's whole silhouette.
WF_INLINE vec3 sceneDiskPoint(vec3 direction, vec3 sceneCenter, float sceneRadius, vec2 u) {
    vec3 t, b;
    buildOrthonormalBasis(direction, t, b);
    vec2 d = sceneRadius * sampleConcentricDisk(u);
    return sceneCenter - direction * (2.0f * sceneRadius) + t * d.x + b * d.y;
}

WF_INLINE float sceneDiskPdf(float sceneRadius) {
    return sceneRadius > 0.0f ? 1.0f / (WF_PI * sceneRadius * sceneRadius) : 0.0f;
}

// Directional light of irradiance E travelling along unit `direction`: origin uniform on the
// scene disk (pdfA 1 / (pi sceneRadius^2)), Dirac direction (pdfW 1). Dimensions: uPoint (2D).
WF_INLINE EmissionSample emitDirectional(vec3 direction, vec3 irradiance, vec3 sceneCenter,
                                         float sceneRadius, vec2 uPoint) {
    EmissionSample s;
    s.origin = sceneDiskPoint(direction, sceneCenter, sceneRadius, uPoint);
    s.pdfA = sceneDiskPdf(sceneRadius);
    s.direction = direction;
    s.pdfW = 1.0f;
    s.normal = direction;
    s.flags = WF_EMISSION_DELTA_DIRECTION;
    s.emitted = irradiance;
    s.pad0 = 0.0f;
    return s;
}

// Environment light arriving from unit toEnvironment (a direction lights.glsl's
// sampleEnvironment draws, with its radiance and its solid-angle density without the light
// choice): origin on the scene disk (pdfA 1 / (pi sceneRadius^2)), light travelling along
// -toEnvironment (pdfW the environment's). Dimensions: uPoint (2D), and the environment's own
// uExtra (1D) and uDirection (2D) for toEnvironment.
WF_INLINE EmissionSample emitEnvironment(vec3 toEnvironment, vec3 radiance, float pdfW,
                                         vec3 sceneCenter, float sceneRadius, vec2 uPoint) {
    EmissionSample s;
    s.direction = -toEnvironment;
    s.origin = sceneDiskPoint(s.direction, sceneCenter, sceneRadius, uPoint);
    s.pdfA = sceneDiskPdf(sceneRadius);
    s.pdfW = pdfW;
    s.normal = s.direction;
    s.flags = 0u;
    s.emitted = radiance;
    s.pad0 = 0.0f;
    return s;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
