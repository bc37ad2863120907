// KHR_materials_iridescence: the thin-film Fresnel of Belcour and Barla 2017 ("A Practical
// Extension to Microfacet Theory for the Modeling of Varying Iridescence"), evaluated in RGB as
// the extension's specification defines it. One header for the shade pass (GLSL, included only
// where some material has iridescenceFactor > 0: WF_HAS_IRIDESCENCE) and the CPU tests (C++,
// tests/unit/test_iridescence.cpp).
//
// Three media: outside (ior n1) | film (n2 = iridescenceIor, thickness d in nm) | base, whose
// ior per channel comes from its F0 (n3 = (1 + sqrt F0) / (1 - sqrt F0)). With cos1 the cosine
// to the microfacet normal outside and cos2 the one in the film (Snell):
//   R12 = Schlick((n2 - n1)^2 / (n2 + n1)^2, cos1),   T121 = 1 - R12
//   R23 = Schlick((n3 - n2)^2 / (n3 + n2)^2, cos2)
//   OPD = 2 n2 d cos2,  phi = phi21 + phi23 (pi phase flips where the next medium is thinner)
//   I   = R12 + T121^2 R23 / (1 - R12 R23)
//       + sum_{m=1,2} 2 (T121^2 R23 / (1 - R12 R23) - T121) sqrt(R12 R23)^m S(m OPD, m phi)
// where S is the CIE XYZ sensitivity in Fourier space (Gaussian fit) taken to linear Rec. 709.
// Departures, each documented: the film is absent (the plain Schlick Fresnel of the base
// exactly) at thickness 0 or where the film's ior equals the outside one; the result is clamped
// to [0, 1] so that no microfacet reflects more than it receives (the RGB fit can overshoot).
#ifndef WF_IRIDESCENCE_H
#define WF_IRIDESCENCE_H

#include "bsdf/microfacet.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// The XYZ sensitivity of an optical path difference (nm) with phase shift `shift`, in linear
// Rec. 709 (Belcour and Barla's Gaussian fit of the colour matching functions' spectra).
WF_INLINE vec3 iridescenceSensitivity(float opd, vec3 shift) {
    float phase = 2.0f * WF_PI * opd * 1.0e-9f;
    vec3 val = vec3(5.4856e-13f, 4.4201e-13f, 5.2481e-13f);
    vec3 pos = vec3(1.6810e+06f, 1.7953e+06f, 2.2084e+06f);
    vec3 var = vec3(4.3278e+09f, 9.3046e+09f, 6.6121e+09f);
    vec3 xyz = val * sqrt(2.0f * WF_PI * var) * cos(pos * phase + shift) *
               exp(-(phase * phase) * var);
    xyz.x += 9.7470e-14f * sqrt(2.0f * WF_PI * 4.5282e+09f) * cos(2.2399e+06f * phase + shift.x) *
             exp(-4.5282e+09f * (phase * phase));
    xyz *= 1.0f / 1.0685e-7f;
    // XYZ to linear Rec. 709 (columns, as GLSL and glm store a mat3).
    return vec3(3.2404542f, -0.9692660f, 0.0556434f) * xyz.x +
           vec3(-1.5371385f, 1.8760108f, -0.2040259f) * xyz.y +
           vec3(-0.4985314f, 0.0415560f, 1.0572252f) * xyz.z;
}

// Reflectance of the film over a base of Fresnel F0 `baseF0`, seen at cosine cos1 > 0 from a
// medium of ior outsideIor; thickness in nanometres.
WF_INLINE vec3 fresnelIridescence(float outsideIor, float filmIor, float cos1, float thickness,
                                  vec3 baseF0) {
    if (!(thickness > 0.0f) || filmIor == outsideIor) {
        return fresnelSchlick(baseF0, cos1); // no film
    }
    // The film's ior tends to the outside one as the film vanishes (the reference's smoothstep).
    float n2 = mix(outsideIor, filmIor, smoothstep(0.0f, 0.03f, thickness));
    float ratio = outsideIor / n2;
    float cos2Sq = 1.0f - ratio * ratio * (1.0f - cos1 * cos1);
    if (cos2Sq <= 0.0f) {
        return vec3(1.0f); // total internal reflection in the film
    }
    float cos2 = sqrt(cos2Sq);
    float r0 = (n2 - outsideIor) / (n2 + outsideIor);
    float r12 = r0 * r0 + (1.0f - r0 * r0) * schlickWeight(cos1);
    float t121 = 1.0f - r12;
    float phi12 = n2 < outsideIor ? WF_PI : 0.0f;
    float phi21 = WF_PI - phi12;
    vec3 sqrtF0 = sqrt(clamp(baseF0, vec3(0.0f), vec3(0.9999f)));
    vec3 n3 = (vec3(1.0f) + sqrtF0) / (vec3(1.0f) - sqrtF0);
    vec3 r1 = (n3 - vec3(n2)) / (n3 + vec3(n2));
    vec3 r23 = fresnelSchlick(r1 * r1, cos2);
    vec3 phi23 = vec3(n3.x < n2 ? WF_PI : 0.0f, n3.y < n2 ? WF_PI : 0.0f,
                      n3.z < n2 ? WF_PI : 0.0f);
    float opd = 2.0f * n2 * thickness * cos2;
    vec3 phi = vec3(phi21) + phi23;
    vec3 r123 = clamp(r12 * r23, vec3(1e-5f), vec3(0.9999f));
    vec3 sqrtR123 = sqrt(r123);
    vec3 rs = t121 * t121 * r23 / (vec3(1.0f) - r123);
    vec3 result = r12 + rs;
    vec3 cm = rs - vec3(t121);
    for (int m = 1; m <= 2; ++m) {
        cm *= sqrtR123;
        result += cm * (2.0f * iridescenceSensitivity(float(m) * opd, float(m) * phi));
    }
    return clamp(result, vec3(0.0f), vec3(1.0f));
}

// A bound on fresnelIridescence over every film thickness at normal incidence, for the diffuse
// coupling of bsdf.h: the Airy envelope ((r12 + r23) / (1 + r12 r23))^2 of the two interfaces'
// amplitudes, plus the overshoot of the RGB fit.
WF_INLINE float iridescenceF0Bound(float outsideIor, float filmIor, vec3 baseF0) {
    float a = abs(filmIor - outsideIor) / (filmIor + outsideIor);
    vec3 sqrtF0 = sqrt(clamp(baseF0, vec3(0.0f), vec3(0.9999f)));
    vec3 n3 = (vec3(1.0f) + sqrtF0) / (vec3(1.0f) - sqrtF0);
    vec3 b = abs(n3 - vec3(filmIor)) / (n3 + vec3(filmIor));
    vec3 env = (vec3(a) + b) / (vec3(1.0f) + a * b);
    return min(1.0f, maxComponent(env * env) * 1.1f + 0.02f);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
