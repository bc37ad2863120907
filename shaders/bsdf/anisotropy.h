// KHR_materials_anisotropy: anisotropic GGX for bsdf.h's microfacet lobes (metal, dielectric
// reflection and transmission; the clear coat stays isotropic, as the extension says). One
// header for the shade pass (GLSL, its code compiled only where some material is anisotropic:
// WF_HAS_ANISOTROPY) and the CPU tests (C++, tests/unit/test_anisotropy.cpp, always on).
//
// Frame: bsdf.h's local shading frame whose +x axis is the anisotropy direction (the tangent
// frame's direction from anisotropyTexture.rg rotated by anisotropyRotation; path_vertex.glsl
// builds it). With alpha = roughness^2 and s = anisotropyStrength x anisotropyTexture.b:
//   alpha_t = mix(alpha, 1, s^2) along x,  alpha_b = alpha along y,
//   D(h)    = 1 / (pi alpha_t alpha_b (h.x^2 / alpha_t^2 + h.y^2 / alpha_b^2 + h.z^2)^2),
//   Lambda(w) = (sqrt(1 + (alpha_t^2 w.x^2 + alpha_b^2 w.y^2) / w.z^2) - 1) / 2,
//   G2 = 1 / (1 + Lambda(wo) + Lambda(wi)) (height-correlated Smith), sampled by visible
// normals in the stretched space where the lobe is the unit hemisphere (Heitz 2018, here by
// Dupuy & Benyoub's spherical caps as microfacet.h does it). These are microfacet.h's functions
// overloaded for alpha = (alpha_t, alpha_b), written so that alpha_t == alpha_b evaluates the
// isotropic ones' arithmetic operation for operation (ratios of 1 are exact): strength 0 is the
// isotropic lobe bit for bit.
//
// Diffuse coupling: bsdf.h bounds the dielectric layer's directional albedo by
// E(mu) = F0 + (1 - F0) kappa(r) (1 - mu)^n(r), fitted over isotropic roughness r. An anisotropic
// layer reflects more at grazing angles than the isotropic one of its smaller roughness (by up to
// 0.09 at r = 0.4, s = 1, mu = 0.005), so the bound is taken at the coupling roughness
// r (1 - s^2 / 4) (anisotropyCouplingRoughness): over r, s in [0, 1], every mu and azimuth its
// excess is at most ~0.0009, the isotropic fit's own (at s = 0; scripts/
// anisotropy_coupling_bound.py measures both rules; tests/unit/test_anisotropy.cpp checks the
// white furnace).
#ifndef WF_ANISOTROPY_H
#define WF_ANISOTROPY_H

#ifndef WF_HAS_ANISOTROPY
#ifdef __cplusplus
#define WF_HAS_ANISOTROPY 1
#else
#define WF_HAS_ANISOTROPY 0
#endif
#endif

#if WF_HAS_ANISOTROPY
#include "bsdf/microfacet.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// (alpha_t, alpha_b) for perceptual roughness r and strength s, each >= WF_GGX_MIN_ALPHA.
WF_INLINE vec2 anisotropicAlpha(float roughness, float strength) {
    float alpha = roughness * roughness;
    return max(vec2(mix(alpha, 1.0f, strength * strength), alpha), vec2(WF_GGX_MIN_ALPHA));
}

// The roughness at which bsdf.h's diffuse coupling takes its albedo bound (see above).
WF_INLINE float anisotropyCouplingRoughness(float roughness, float strength) {
    return roughness * (1.0f - 0.25f * strength * strength);
}

// x^2 / ax^2 + y^2 / ay^2 = (x^2 (ay / ax) + y^2 (ax / ay)) / (ax ay): the isotropic form's
// (x^2 + y^2) / a^2 when ax == ay, and no overflow for ratios up to 1 / WF_GGX_MIN_ALPHA.
WF_INLINE float ggxD(vec3 h, vec2 alpha) {
    if (h.z <= 0.0f) {
        return 0.0f;
    }
    float axy = alpha.x * alpha.y;
    float d = (h.x * h.x * (alpha.y / alpha.x) + h.y * h.y * (alpha.x / alpha.y)) / axy +
              h.z * h.z;
    return 1.0f / (WF_PI * axy * d * d);
}

// sqrt(cos^2 + ax^2 x^2 + ay^2 y^2) = |cos| (1 + 2 Lambda(w)).
WF_INLINE float ggxStretchedLength(vec3 w, vec2 alpha) {
    float xy = w.x * w.x * (alpha.x / alpha.y) + w.y * w.y * (alpha.y / alpha.x);
    return sqrt(w.z * w.z + alpha.x * alpha.y * xy);
}

// Smith's Lambda for the anisotropic GGX (for the tests; the lobes use the stretched length).
WF_INLINE float ggxLambda(vec3 w, vec2 alpha) {
    return w.z == 0.0f ? 1e30f : 0.5f * (ggxStretchedLength(w, alpha) / abs(w.z) - 1.0f);
}

WF_INLINE float ggxG2OverCosines(vec3 wo, vec3 wi, vec2 alpha) {
    float denom =
        ggxStretchedLength(wo, alpha) * abs(wi.z) + ggxStretchedLength(wi, alpha) * abs(wo.z);
    return denom > 0.0f ? 2.0f / denom : 0.0f;
}

WF_INLINE float ggxVisibleNormalPdf(vec3 wo, vec3 h, vec2 alpha) {
    float denom = wo.z + ggxStretchedLength(wo, alpha);
    float c = dot(wo, h);
    return denom > 0.0f && c > 0.0f ? 2.0f * c * ggxD(h, alpha) / denom : 0.0f;
}

// microfacet.h's spherical caps in the space stretched by (alpha_t, alpha_b).
WF_INLINE vec3 ggxSampleVisibleNormal(vec3 wo, vec2 alpha, vec2 u) {
    vec3 wStd = normalize(vec3(wo.x * alpha.x, wo.y * alpha.y, wo.z));
    float phi = 2.0f * WF_PI * u.x;
    float z = (1.0f - u.y) * (1.0f + wStd.z) - wStd.z;
    float sinTheta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
    vec3 hStd = vec3(sinTheta * cos(phi), sinTheta * sin(phi), z) + wStd;
    vec3 h = vec3(hStd.x * alpha.x, hStd.y * alpha.y, max(hStd.z, 0.0f));
    float len2 = dot(h, h);
    return len2 > 1e-30f ? h * inversesqrt(len2) : vec3(0.0f, 0.0f, 1.0f);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif // WF_HAS_ANISOTROPY
#endif
