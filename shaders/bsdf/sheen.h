// KHR_materials_sheen's lobe: the "Charlie" distribution with its fitted masking term
// (Estevez & Kulla 2017, "Production Friendly Microfacet Sheen BRDF"), as the glTF spec and its
// sample viewer define them, and an upper bound of the lobe's directional albedo for the spec's
// albedo scaling of the layer beneath (bsdf_layers.h). Local frame, normal +z, cosines > 0.
//
//   f_sheen = sheenColor D(h) V(mu_o, mu_i),  D = (2 + 1/a) sin(theta_h)^(1/a) / (2 pi),
//   V = 1 / ((1 + Lambda(mu_o) + Lambda(mu_i)) 4 mu_o mu_i), clamped to [0, 1] as the viewer does,
// with a = sheenRoughness^2. The roughness is clamped to WF_SHEEN_MIN_ROUGHNESS: below it the
// grazing albedo of the lobe climbs past 1 and the tabulated bound stops resolving it.
#ifndef WF_SHEEN_H
#define WF_SHEEN_H

#include "sampling/sampling.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

#define WF_SHEEN_MIN_ROUGHNESS 0.1f

WF_INLINE float sheenAlpha(float roughness) {
    float r = clamp(roughness, WF_SHEEN_MIN_ROUGHNESS, 1.0f);
    return r * r;
}

WF_INLINE float sheenD(float alpha, float cosH) {
    float invAlpha = 1.0f / alpha;
    float sin2 = max(1.0f - cosH * cosH, 0.0f);
    return (2.0f + invAlpha) * pow(sin2, 0.5f * invAlpha) * (0.5f * WF_INV_PI);
}

// The paper's fit of ln Lambda, interpolated between its r = 0 and r = 1 coefficients.
WF_INLINE float sheenLambdaFit(float x, float alpha) {
    float t = (1.0f - alpha) * (1.0f - alpha);
    float a = mix(21.5473f, 25.3245f, t);
    float b = mix(3.82987f, 3.32435f, t);
    float c = mix(0.19823f, 0.16801f, t);
    float d = mix(-1.97760f, -1.27393f, t);
    float e = mix(-4.32054f, -4.85967f, t);
    return a / (1.0f + b * pow(x, c)) + d * x + e;
}

WF_INLINE float sheenLambda(float cosTheta, float alpha) {
    return cosTheta < 0.5f
               ? exp(sheenLambdaFit(cosTheta, alpha))
               : exp(2.0f * sheenLambdaFit(0.5f, alpha) - sheenLambdaFit(1.0f - cosTheta, alpha));
}

// D V for unit wo, wi in the upper hemisphere: the lobe without its colour. Symmetric in wo, wi.
WF_INLINE float sheenLobe(float alpha, vec3 wo, vec3 wi) {
    vec3 h = wo + wi;
    float len2 = dot(h, h);
    if (!(wo.z > 0.0f && wi.z > 0.0f && len2 > 1e-12f)) {
        return 0.0f;
    }
    float cosH = h.z * inversesqrt(len2);
    float v = 1.0f / ((1.0f + sheenLambda(wo.z, alpha) + sheenLambda(wi.z, alpha)) *
                      (4.0f * wo.z * wi.z));
    return sheenD(alpha, cosH) * clamp(v, 0.0f, 1.0f);
}

#ifndef WF_SHEEN_NO_TABLE
#include "bsdf/sheen_albedo_table.h"

#ifdef __cplusplus
WF_INLINE float sheenAlbedoNode(int k) { return WF_SHEEN_ALBEDO[k]; }
#endif // GLSL: scene_tables.glsl reads the nodes from the material table

// An upper bound of the directional albedo of sheenLobe (colour 1) at cosine mu: the table's
// bilinear interpolation over (sqrt(mu), roughness), whose every node holds the largest albedo
// of the cells around it (scripts/sheen_albedo_table.cpp), so the interpolant never dips under
// the albedo (tests/unit/test_bsdf_layers.cpp checks it against quadrature).
WF_INLINE float sheenAlbedoBound(float roughness, float mu) {
    float x = sqrt(clamp(mu, 0.0f, 1.0f)) * float(WF_SHEEN_TABLE_MU - 1);
    float y = (clamp(roughness, WF_SHEEN_MIN_ROUGHNESS, 1.0f) - WF_SHEEN_MIN_ROUGHNESS) /
              (1.0f - WF_SHEEN_MIN_ROUGHNESS) * float(WF_SHEEN_TABLE_ROUGHNESS - 1);
    int i = min(int(x), WF_SHEEN_TABLE_MU - 2);
    int j = min(int(y), WF_SHEEN_TABLE_ROUGHNESS - 2);
    float fx = x - float(i);
    float fy = y - float(j);
    int row0 = j * WF_SHEEN_TABLE_MU + i;
    int row1 = row0 + WF_SHEEN_TABLE_MU;
    float low = mix(sheenAlbedoNode(row0), sheenAlbedoNode(row0 + 1), fx);
    float high = mix(sheenAlbedoNode(row1), sheenAlbedoNode(row1 + 1), fx);
    return mix(low, high, fy);
}
#endif

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
