// KHR_materials_dispersion: the ior at a wavelength, and the RGB weight a path takes when it
// picks one. Shared by the shaders (WF_HAS_DISPERSION; wave/path_vertex.glsl) and the CPU tests
// (tests/unit/test_dispersion.cpp).
//
// Method (docs/gltf.md): a path stays RGB until it meets a transmissive material with
// dispersion > 0. There it draws one wavelength lambda, uniform over [380, 780] nm (pdf 1/400,
// sample dimension WF_DIM_WAVELENGTH of that bounce, rng.h), and multiplies its RGB throughput
// by dispersionWeight(lambda). From then on every dispersive dielectric bends it by
// n(lambda); RGB reflectances and emission met later filter that weighted throughput (an RGB
// filter per wavelength: exact for grey surfaces). The weight's average over lambda is exactly
// (1, 1, 1), so white light through dispersive glass keeps its colour on average. With
// --spectral hero the path carries four wavelengths instead (heroLaneWavelength below;
// wave/hero_lanes.glsl).
//
// The weight: the CIE 1931 2-degree colour matching functions, by Wyman, Sloan and Shirley's
// multi-lobe Gaussian fit (JCGT 2(2), 2013), to linear sRGB (D65), negative parts clipped, each
// channel scaled to average 1 over the range (scripts/dispersion_weights.py computes the
// scales). Closed form, not a table: a constant array indexed at run time compiles to a select
// ladder on lavapipe (sheen_albedo_table.h says why).
#ifndef WF_DISPERSION_H
#define WF_DISPERSION_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

#define WF_LAMBDA_MIN 380.0f
#define WF_LAMBDA_MAX 780.0f
#define WF_LAMBDA_D 587.56f // the Fraunhofer d line, where n = the material's ior
// From scripts/dispersion_weights.py (midpoint rule, 400000 nodes).
#define WF_DISPERSION_SCALE_R 2.2704398f
#define WF_DISPERSION_SCALE_G 3.4666380f
#define WF_DISPERSION_SCALE_B 3.6590345f

// The spec's n(lambda) (Cauchy's first two terms through n_d with Abbe number V = 20 /
// dispersion, lambda in nm): max(n_d + (n_d - 1) / V (523655 / lambda^2 - 1.5168), 1).
WF_INLINE float dispersionIor(float nd, float dispersion, float lambda) {
    float inverseAbbe = dispersion * (1.0f / 20.0f);
    return max(nd + (nd - 1.0f) * inverseAbbe * (523655.0f / (lambda * lambda) - 1.5168f),
               1.0f);
}

WF_INLINE float cieLobe(float lambda, float mu, float below, float above) {
    float t = (lambda - mu) / (lambda < mu ? below : above);
    return exp(-0.5f * t * t);
}

// CIE 1931 XYZ colour matching functions (Wyman, Sloan and Shirley 2013).
WF_INLINE vec3 cieXyz(float lambda) {
    float x = 1.056f * cieLobe(lambda, 599.8f, 37.9f, 31.0f) +
              0.362f * cieLobe(lambda, 442.0f, 16.0f, 26.7f) -
              0.065f * cieLobe(lambda, 501.1f, 20.4f, 26.2f);
    float y = 0.821f * cieLobe(lambda, 568.8f, 46.9f, 40.5f) +
              0.286f * cieLobe(lambda, 530.9f, 16.3f, 31.1f);
    float z = 1.217f * cieLobe(lambda, 437.0f, 11.8f, 36.0f) +
              0.681f * cieLobe(lambda, 459.0f, 26.0f, 13.8f);
    return vec3(x, y, z);
}

// The RGB weight of wavelength lambda: its average over [380, 780] nm is (1, 1, 1).
WF_INLINE vec3 dispersionWeight(float lambda) {
    vec3 c = cieXyz(lambda);
    vec3 rgb = vec3(3.2404542f * c.x - 1.5371385f * c.y - 0.4985314f * c.z,
                    -0.9692660f * c.x + 1.8760108f * c.y + 0.0415560f * c.z,
                    0.0556434f * c.x - 0.2040259f * c.y + 1.0572252f * c.z);
    return max(rgb, vec3(0.0f)) *
           vec3(WF_DISPERSION_SCALE_R, WF_DISPERSION_SCALE_G, WF_DISPERSION_SCALE_B);
}

// The wavelength of sample u in [0, 1): uniform over the range, so the weight of that pick is
// dispersionWeight(lambda) (the colour's density over the uniform pdf, both per 400 nm).
WF_INLINE float sampleWavelength(float u) {
    return WF_LAMBDA_MIN + (WF_LAMBDA_MAX - WF_LAMBDA_MIN) * u;
}

// --spectral hero (WF_SPECTRAL_HERO; Wilkie et al. 2014, "Hero wavelength spectral sampling"):
// at its first dispersive vertex a path takes WF_HERO_LANES wavelengths, the hero (drawn as
// above) and the others a quarter of the range apart, wrapped into it; each lane is then
// uniform over the range, and the four stratify it.
#define WF_HERO_LANES 4u
WF_INLINE float heroLaneWavelength(float hero, uint lane) {
    const float range = WF_LAMBDA_MAX - WF_LAMBDA_MIN;
    float lambda = hero + float(lane) * (range / float(WF_HERO_LANES));
    return lambda >= WF_LAMBDA_MAX ? lambda - range : lambda;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
