// GGX (Trowbridge-Reitz) microfacets for the BSDF in bsdf.h: normal distribution, height-
// correlated Smith masking-shadowing, visible-normal sampling, Schlick Fresnel and refraction.
// Local frame, normal +z. Directions are unit vectors pointing away from the surface; wo is
// in the upper hemisphere (bsdf.h mirrors lower ones), alpha >= WF_GGX_MIN_ALPHA.
#ifndef WF_MICROFACET_H
#define WF_MICROFACET_H

#include "sampling/sampling.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// Below this alpha the float GGX lobe stops resolving (D(n) = 1 / (pi alpha^2) ~ 3e7);
// roughness exactly 0 is a Dirac lobe instead (bsdf.h).
#define WF_GGX_MIN_ALPHA 1e-4f

WF_INLINE float maxComponent(vec3 v) {
    return max(v.x, max(v.y, v.z));
}

WF_INLINE float averageComponent(vec3 v) {
    return (v.x + v.y + v.z) * (1.0f / 3.0f);
}

// D(h) = 1 / (pi alpha^2 ((x^2 + y^2) / alpha^2 + z^2)^2); for alpha <= 1 the bracket is >= 1,
// so nothing overflows even at alpha = 1e-4.
WF_INLINE float ggxD(vec3 h, float alpha) {
    if (h.z <= 0.0f) {
        return 0.0f;
    }
    float a2 = alpha * alpha;
    float d = (h.x * h.x + h.y * h.y) / a2 + h.z * h.z;
    return 1.0f / (WF_PI * a2 * d * d);
}

// sqrt(cos^2 + alpha^2 sin^2) = |cos| sqrt(1 + alpha^2 tan^2) = |cos| (1 + 2 Lambda): writing
// Smith's terms with it avoids dividing by cos(theta), so they stay finite at grazing angles.
WF_INLINE float ggxStretchedLength(vec3 w, float alpha) {
    return sqrt(w.z * w.z + alpha * alpha * (w.x * w.x + w.y * w.y));
}

// Height-correlated G2 = 1 / (1 + Lambda(wo) + Lambda(wi)), divided by |cos o| |cos i| (the
// form every lobe needs): 2 / (L(wo) |cos i| + L(wi) |cos o|). Zero only if both are grazing.
WF_INLINE float ggxG2OverCosines(vec3 wo, vec3 wi, float alpha) {
    float denom =
        ggxStretchedLength(wo, alpha) * abs(wi.z) + ggxStretchedLength(wi, alpha) * abs(wo.z);
    return denom > 0.0f ? 2.0f / denom : 0.0f;
}

// Density of ggxSampleVisibleNormal over microfacet normals: G1(wo) max(0, wo.h) D(h) / wo.z
// = 2 max(0, wo.h) D(h) / (wo.z + L(wo)), finite at wo.z = 0.
WF_INLINE float ggxVisibleNormalPdf(vec3 wo, vec3 h, float alpha) {
    float denom = wo.z + ggxStretchedLength(wo, alpha);
    float c = dot(wo, h);
    return denom > 0.0f && c > 0.0f ? 2.0f * c * ggxD(h, alpha) / denom : 0.0f;
}

// Visible-normal sampling by spherical caps (Dupuy & Benyoub 2023): in the stretched space
// where the GGX is the unit hemisphere, the visible normals of the hemisphere seen from wStd are
// wStd plus a uniform point on the cap z > -wStd.z of the unit sphere. wo.z >= 0.
WF_INLINE vec3 ggxSampleVisibleNormal(vec3 wo, float alpha, vec2 u) {
    vec3 wStd = normalize(vec3(wo.x * alpha, wo.y * alpha, wo.z));
    float phi = 2.0f * WF_PI * u.x;
    float z = (1.0f - u.y) * (1.0f + wStd.z) - wStd.z;
    float sinTheta = sqrt(clamp(1.0f - z * z, 0.0f, 1.0f));
    vec3 hStd = vec3(sinTheta * cos(phi), sinTheta * sin(phi), z) + wStd;
    vec3 h = vec3(hStd.x * alpha, hStd.y * alpha, max(hStd.z, 0.0f));
    float len2 = dot(h, h);
    // hStd = 0 needs u.y = 1 with wo grazing; h.z = 0 is then rejected by the callers.
    return len2 > 1e-30f ? h * inversesqrt(len2) : vec3(0.0f, 0.0f, 1.0f);
}

// (1 - c)^5, the Schlick interpolant.
WF_INLINE float schlickWeight(float c) {
    float m = clamp(1.0f - c, 0.0f, 1.0f);
    float m2 = m * m;
    return m2 * m2 * m;
}

WF_INLINE vec3 fresnelSchlick(vec3 f0, float c) {
    return f0 + (vec3(1.0f) - f0) * schlickWeight(c);
}

// The cosine Schlick's formula takes at a dielectric interface, seen from a direction at cosine
// cosO > 0 to the microfacet normal, with etaRel = eta(far side) / eta(near side): the cosine on
// the optically thinner side. F is then the same from both sides (reciprocal) and 1 beyond the
// critical angle. Returns -1 under total internal reflection.
WF_INLINE float interfaceCosine(float cosO, float etaRel) {
    if (etaRel >= 1.0f) {
        return cosO;
    }
    float sin2T = max(0.0f, 1.0f - cosO * cosO) / (etaRel * etaRel);
    return sin2T >= 1.0f ? -1.0f : sqrt(1.0f - sin2T);
}

// Refracts w (unit, dot(w, h) > 0) through the microfacet h into the far side; etaRel as above.
// False under total internal reflection.
WF_INLINE bool refractDirection(vec3 w, vec3 h, float etaRel, WF_OUT(vec3) wt) {
    float cosI = dot(w, h);
    float sin2T = max(0.0f, 1.0f - cosI * cosI) / (etaRel * etaRel);
    if (sin2T >= 1.0f) {
        wt = vec3(0.0f);
        return false;
    }
    float cosT = sqrt(1.0f - sin2T);
    wt = -w / etaRel + (cosI / etaRel - cosT) * h;
    return true;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
