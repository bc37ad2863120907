// The adjoint BSDF (issue 46): the two factors that turn what bsdf.h returns for radiance into
// what a light subpath must carry, so that light tracing and BDPT's light-side strategies
// estimate the very integral the path tracer does (Veach 1997, 5.2 and 5.3; pbrt-v4's
// TransportMode::Importance). tests/unit/test_adjoint_bsdf.cpp checks both against their
// definitions and the symmetry they restore.
//
// Convention (bsdf.h, wave/path_vertex.glsl): bsdfEval(m, wo, wi) takes wo towards the camera's
// side and wi towards the light's, in the shading frame (+z = ns); the path tracer multiplies
// its throughput by f(wo, wi) |wi.ns| / pdf, the shading cosine on the direction it samples (wi,
// towards the light). Geometric cosines enter only through the area densities of the vertices
// its rays reach. Below, toLight and toCamera are a vertex's two unit directions, pointing away
// from it: a light subpath arrives from toLight and samples toCamera, calling
// bsdfSample(m, toLight, ...) (wo := toLight), whose weight is f(toLight, toCamera)
// |toCamera.ns| / pdf; a connection evaluates f(toLight, toCamera) |toCamera.ns| the same way.
//
// 1. Shading normals. Counting the cosines above, the path tracer integrates, against geometric
// cosines, the non-symmetric BSDF f_s(toLight -> toCamera) = f |toLight.ns| / |toLight.ng|.
// A light subpath needs f_s |toCamera.ng| per vertex (the geometric cosine of the segment it
// leaves by), so its throughput after sampling or evaluating is multiplied by
//   adjointShadingFactor = |toLight.ns| |toCamera.ng| / (|toLight.ng| |toCamera.ns|).
// (pbrt's f*(wo, wi) = f |wo.ns| |wi.ng| / (|wo.ng| |wi.ns|), CorrectShadingNormal, is this
// with pbrt's names, whose wo is the light side.) Identity it restores, per vertex: radiance
// throughput f |toLight.ns| times |toCamera.ng| equals importance's times |toLight.ng|, both
// f_s |toLight.ng| |toCamera.ng|, the vertex's share of the path's measurement contribution.
// Rule: directions on opposite sides of ns and ng keep the ratio of absolute cosines, because
// path_vertex.glsl neither rejects nor reweights them (it shades in the ns frame alone, and
// offsetRayOrigin picks the side from the direction); zeroing them in light subpaths alone would
// give the light strategies another integrand than the camera's, a bias MIS cannot hide. The
// factor is 0 only when its denominator is 0 or it overflows: light arriving tangent to the
// geometry (a vertex no light subpath reaches with nonzero area density) or leaving tangent to
// the shading frame (the throughput it multiplies is 0 there). It is not clamped: near
// |toLight.ng| = 0 the path tracer's f_s is as large, and a clamp must treat both modes alike.
#ifndef WF_ADJOINT_BSDF_H
#define WF_ADJOINT_BSDF_H

#include "types/glsl_cpp.h"
#include "bsdf/bsdf.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// ns, ng: unit shading and geometric normals (either orientation); toLight, toCamera as above.
WF_INLINE float adjointShadingFactor(vec3 ns, vec3 ng, vec3 toLight, vec3 toCamera) {
    float num = abs(dot(toLight, ns)) * abs(dot(toCamera, ng));
    float den = abs(dot(toLight, ng)) * abs(dot(toCamera, ns));
    float r = den > 0.0f ? num / den : 0.0f;
    return isinf(r) || isnan(r) ? 0.0f : r;
}

// 2. Refraction. bsdf.h's transmission carries 1 / eta^2 with eta = eta(wi side) / eta(wo side)
// (microTransmittance / (eta^2 pdf) in bsdfSample's Dirac branch, the same factor inside
// bsdfEvalMirrored's Walter term), the change of radiance across the interface. Importance does
// not change (Veach 5.2): the BSDF a light subpath needs is f_s(toLight -> toCamera) =
// f(toCamera, toLight), and bsdf.h's f(wi, wo) = eta^2 f(wo, wi) gives
//   f(toCamera, toLight) = eta^2 f(toLight, toCamera),
//   eta = eta(toCamera side) / eta(toLight side),
// which is exactly BsdfSample.eta of bsdfSample(m, toLight, ...) (1 for reflection). So a light
// subpath multiplies the sample's weight by eta^2, the same product a camera path keeps for
// Russian roulette (etaScale): that removes the radiance scaling, which importance never had.
// Through a slab both modes' crossings cancel (ior^2 / ior^2); inside it they differ by ior^2.
WF_INLINE float adjointRefractionFactor(float eta) {
    return eta * eta;
}

// eta for a connection, where nothing was sampled: what bsdfSample(m, toLight, ...) would report
// for toCamera (local shading frame, +z outside as bsdf.h requires). Same side: reflection, 1.
// Only needed with f(toLight, toCamera); evaluating bsdfEval(m, toCamera, toLight), the radiance
// order, already gives f_s and needs no factor.
WF_INLINE float adjointEtaOfPair(BsdfParams m, vec3 toLightLocal, vec3 toCameraLocal) {
    if (!(toLightLocal.z * toCameraLocal.z < 0.0f)) {
        return 1.0f;
    }
    float ior = bsdfRefractiveIor(bsdfSanitize(m));
    if (abs(ior - 1.0f) < 1e-3f) {
        return 1.0f; // index-matched: a straight pass-through, as bsdfSample reports it
    }
    return toLightLocal.z > 0.0f ? ior : 1.0f / ior;
}

// Both factors: what multiplies a light subpath's throughput after bsdfSample(m, toLight, ...)
// (eta = its sample's eta) or after f(toLight, toCamera) |toCamera.ns| (eta = adjointEtaOfPair).
WF_INLINE float adjointThroughputFactor(vec3 ns, vec3 ng, vec3 toLight, vec3 toCamera, float eta) {
    return adjointShadingFactor(ns, ng, toLight, toCamera) * adjointRefractionFactor(eta);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
