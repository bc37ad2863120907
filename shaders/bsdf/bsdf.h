// The glTF 2.0 metallic-roughness BSDF with KHR_materials_specular, _transmission and _ior, one
// header for the shade pass (GLSL) and the CPU tests (C++, tests/unit/test_bsdf.cpp).
//
// Frame: local shading frame, normal +z; wo (towards the previous vertex) and wi (towards the
// next) are unit vectors pointing away from the surface. Transmissive materials need +z on the
// geometric outside: wo.z < 0 means the path is inside. Reflection lobes always act on wo's side
// (the frame is mirrored when wo.z < 0), so opaque materials are two-sided.
//
// Model (glTF 2.0 appendix B): material = mix(dielectric, metal, metallic), alpha = roughness^2.
//   metal      = GGX(alpha) * Schlick(F0 = baseColor, |wo.h|)
//   dielectric = F * GGX(alpha) + base, base = mix(diffuse, baseColor * BTDF(alpha), transmission)
//   F          = specular * Schlick(F0 = min(((ior-1)/(ior+1))^2 specularColor, 1), cosine), the
//                cosine being, for the transmissive part, the one on the optically thinner side
//                of the interface (F = specular beyond the critical angle: exact TIR)
//   BTDF       = Walter et al. 2007, weighted 1 - max(F) at its microfacet.
//   diffuse    = Lambert, split by KHR_materials_diffuse_transmission into a reflected and a
//                transmitted Lambert lobe (diffuse_base.h)
// GGX is Trowbridge-Reitz with height-correlated Smith G2, sampled by visible normals. Roughness
// exactly 0 makes reflection and refraction Dirac lobes, with the same Schlick F. Anisotropic
// materials stretch all three lobes' GGX along the frame's x axis (anisotropy.h).
//
// One deliberate departure: the spec weights the diffuse base by 1 - specular max(F(wo.h)),
// which reflects up to ~1.3 of the incident energy at grazing wo (roughness 0.2-0.3) and is
// ill-defined for a Dirac layer. Here the base is weighted by what the layer reflects at each end:
//   diffuse = baseColor / pi * (1 - w E(mu_o)) (1 - w E(mu_i)) / (1 - w E_avg),  w = specular,
//   E(mu) = F0max + (1 - F0max) kappa(r) (1 - mu)^n(r),  E_avg = 2 * integral of E(mu) mu dmu,
// where kappa and n bound the Schlick part of the GGX layer's directional albedo (fitted to
// quadrature over roughness r and mu; excess <= 0.0012). It is reciprocal, conserves energy,
// has albedo baseColor (1 - w E(mu_o)), and specular = 0 leaves baseColor / pi exactly.
//
// Transport: radiance. For refraction eta = eta(wi side) / eta(wo side): ior when wo.z > 0
// (the path enters), 1 / ior when it leaves. The BTDF carries 1 / eta^2, the change of radiance
// across the interface, so f(wi, wo) = eta^2 f(wo, wi) (f / eta_o^2 is symmetric). For Russian
// roulette multiply the throughput by s.eta^2 (pbrt's etaScale) to remove that scaling. ior == 1
// (within 1e-3) is index-matched: transmission passes straight through as a Dirac lobe.
//
// Sampling: lobe "diffuse" (cosine) or "microfacet" (visible normal h, then reflect or refract
// with probabilities proportional to the colours the microfacet reflects and transmits), picked
// by uLobe with probabilities proportional to lobe albedo estimates at wo (see
// bsdfDiffuseProbability). Non-delta samples get pdf = bsdfPdf (the mixture over all
// non-delta lobes) and weight = bsdfEval |cos| / pdf; Dirac samples get isDelta, pdf = the
// probability of that discrete choice, and weight = lobe throughput / that probability.
#ifndef WF_BSDF_H
#define WF_BSDF_H

#include "bsdf/microfacet.h"

#ifndef WF_BSDF_DIFFUSE_ONLY
#define WF_BSDF_DIFFUSE_ONLY 0
#endif
#ifndef WF_BSDF_DELTA_ONLY
#define WF_BSDF_DELTA_ONLY 0
#endif
// KHR_materials_iridescence: compiled into shaders only where some material has a thin film
// (ShaderVariant); the C++ tests always have it (iridescence 0 leaves the plain BSDF exactly).
#ifndef WF_HAS_IRIDESCENCE
#ifdef __cplusplus
#define WF_HAS_IRIDESCENCE 1
#else
#define WF_HAS_IRIDESCENCE 0
#endif
#endif
#if WF_HAS_IRIDESCENCE
#include "bsdf/iridescence.h"
#endif
// KHR_materials_anisotropy: the lobes' GGX takes (alpha_t, alpha_b) along the frame's x and y
// where some material is anisotropic (WF_HAS_ANISOTROPY; always in the C++ tests).
#include "bsdf/anisotropy.h"
// KHR_materials_diffuse_transmission splits the diffuse base (diffuse_base.h): compiled in only
// where some material has it; always in the C++ tests.
#ifndef WF_HAS_DIFFUSE_TRANSMISSION
#ifdef __cplusplus
#define WF_HAS_DIFFUSE_TRANSMISSION 1
#else
#define WF_HAS_DIFFUSE_TRANSMISSION 0
#endif
#endif

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

struct BsdfParams {
    vec3 baseColor;
    float metallic;
    float roughness;    // perceptual: alpha = roughness^2; exactly 0 is a Dirac lobe
    float ior;          // KHR_materials_ior, 1.5 by default
    float transmission; // KHR_materials_transmission factor
    float specular;     // KHR_materials_specular specularFactor: 0 leaves exact Lambert
    vec3 specularColor; // specularColorFactor
#if WF_HAS_IRIDESCENCE
#ifdef __cplusplus
    float iridescence = 0.0f;          // iridescenceFactor (x texture R): 0 is no film
    float iridescenceIor = 1.3f;       // the film's ior
    float iridescenceThickness = 0.0f; // nm, mix(minimum, maximum, thickness texture G)
#else
    float iridescence;
    float iridescenceIor;
    float iridescenceThickness;
#endif
#endif
#if WF_HAS_ANISOTROPY
#ifdef __cplusplus
    float anisotropy = 0.0f; // anisotropyStrength (x texture B) along the frame's +x axis
#else
    float anisotropy;
#endif
#endif
#if WF_HAS_DIFFUSE_TRANSMISSION
#ifdef __cplusplus
    float diffuseTransmission = 0.0f;            // factor (x texture A): 0 is opaque
    vec3 diffuseTransmissionColor = vec3(1.0f);  // colour factor (x texture RGB)
#else
    float diffuseTransmission;
    vec3 diffuseTransmissionColor;
#endif
#endif
};

struct BsdfSample {
    vec3 wi;
    float pdf;    // solid-angle pdf (bsdfPdf); for Dirac samples the discrete choice probability
    vec3 weight;  // f |cos| / pdf; for Dirac samples the lobe throughput / choice probability
    bool isDelta;
    float eta;    // eta crossed (see above); 1 for reflection and index-matched transmission
};

// What eval, pdf and sample share for one material and side.
struct BsdfLobes {
#if WF_HAS_ANISOTROPY
    vec2 alpha;         // (alpha_t, alpha_b) along x and y, each >= WF_GGX_MIN_ALPHA
#else
    float alpha;        // GGX alpha, >= WF_GGX_MIN_ALPHA; unused by Dirac lobes
#endif
    bool delta;         // roughness == 0 (and anisotropy 0)
    bool indexMatched;  // ior == 1: transmission is a straight pass-through
    float etaRel;       // eta(far side) / eta(wo side)
    vec3 f0;            // dielectric F0
    float f0Max;
    float kDiffuse;     // (1 - metallic)(1 - transmission)
    float kTransmit;    // (1 - metallic) transmission
    float kappa;        // diffuse coupling bound E(mu), see the header comment
    float power;
    float diffuseNorm;  // 1 - specular E_avg
};

WF_INLINE BsdfParams bsdfSanitize(BsdfParams m) {
    m.baseColor = clamp(m.baseColor, vec3(0.0f), vec3(1.0f));
    m.metallic = clamp(m.metallic, 0.0f, 1.0f);
    m.roughness = clamp(m.roughness, 0.0f, 1.0f);
    m.ior = max(m.ior, 0.0f); // 0 is legal: F0 = 1, for converted specular-glossiness
    m.transmission = clamp(m.transmission, 0.0f, 1.0f);
    m.specular = clamp(m.specular, 0.0f, 1.0f);
    m.specularColor = max(m.specularColor, vec3(0.0f));
#if WF_HAS_IRIDESCENCE
    m.iridescence = clamp(m.iridescence, 0.0f, 1.0f);
    m.iridescenceIor = max(m.iridescenceIor, 1.0f);
    m.iridescenceThickness = max(m.iridescenceThickness, 0.0f);
#endif
#if WF_HAS_ANISOTROPY
    m.anisotropy = clamp(m.anisotropy, 0.0f, 1.0f);
#endif
#if WF_HAS_DIFFUSE_TRANSMISSION
    m.diffuseTransmission = clamp(m.diffuseTransmission, 0.0f, 1.0f);
    m.diffuseTransmissionColor = clamp(m.diffuseTransmissionColor, vec3(0.0f), vec3(1.0f));
#endif
    return m;
}

// The ior that bends rays, kept where refraction stays finite.
WF_INLINE float bsdfRefractiveIor(BsdfParams m) {
    return clamp(m.ior, 0.01f, 100.0f);
}

WF_INLINE BsdfLobes bsdfLobes(BsdfParams m, bool inside) {
    BsdfLobes l;
#if WF_HAS_ANISOTROPY
    l.delta = m.roughness == 0.0f && m.anisotropy == 0.0f; // alpha_t = s^2 is not a Dirac lobe
    l.alpha = anisotropicAlpha(m.roughness, m.anisotropy);
    m.roughness = anisotropyCouplingRoughness(m.roughness, m.anisotropy); // for E(mu) below
#else
    l.delta = m.roughness == 0.0f;
    l.alpha = max(m.roughness * m.roughness, WF_GGX_MIN_ALPHA);
#endif
    float ior = bsdfRefractiveIor(m);
    l.indexMatched = abs(ior - 1.0f) < 1e-3f;
    l.etaRel = inside ? 1.0f / ior : ior;
    float r = (m.ior - 1.0f) / (m.ior + 1.0f);
    l.f0 = min(r * r * m.specularColor, vec3(1.0f));
    l.f0Max = maxComponent(l.f0);
    l.kDiffuse = (1.0f - m.metallic) * (1.0f - m.transmission);
    l.kTransmit = (1.0f - m.metallic) * m.transmission;
    l.kappa = 1.0f / (1.0f + 20.7f * pow(m.roughness, 2.32f));
#if WF_HAS_IRIDESCENCE
    if (m.iridescence > 0.0f) {
        // The diffuse coupling bounds the layer's albedo by its F0 and Schlick's rise: a film
        // reflects more at both ends, so take the film's F0 bound and a steeper rise
        // (tests/unit/test_iridescence.cpp checks the white furnace).
        l.f0Max = mix(l.f0Max, max(l.f0Max, iridescenceF0Bound(1.0f, m.iridescenceIor, l.f0)),
                      m.iridescence);
        l.kappa = mix(l.kappa, min(1.0f, 1.25f * l.kappa + 0.05f), m.iridescence);
    }
#endif
    float d = m.roughness - 0.44f;
    l.power = 2.84f + 5.15f * d * d;
    // 2 * integral of (1 - mu)^n mu dmu over [0, 1] = 2 / ((n + 1)(n + 2)).
    float avgPower = 2.0f / ((l.power + 1.0f) * (l.power + 2.0f));
    float eAvg = l.f0Max + (1.0f - l.f0Max) * l.kappa * avgPower;
    l.diffuseNorm = 1.0f - m.specular * eAvg;
    return l;
}

// The diffuse base and its split; the Lambert-only BSDF of diffuse scenes (diffuse_base.h).
#include "bsdf/diffuse_base.h"

// Fresnel of the dielectric layer (F0 = l.f0) and of the metal (F0 = baseColor) at cosine c:
// Schlick's, mixed by iridescenceFactor with the thin film's over the same F0.
WF_INLINE vec3 dielectricFresnel(BsdfParams m, BsdfLobes l, float c) {
    vec3 f = fresnelSchlick(l.f0, c);
#if WF_HAS_IRIDESCENCE
    if (m.iridescence > 0.0f) {
        f = mix(f, fresnelIridescence(1.0f, m.iridescenceIor, c, m.iridescenceThickness, l.f0),
                m.iridescence);
    }
#endif
    return f;
}

WF_INLINE vec3 metalFresnel(BsdfParams m, float c) {
    vec3 f = fresnelSchlick(m.baseColor, c);
#if WF_HAS_IRIDESCENCE
    if (m.iridescence > 0.0f) {
        f = mix(f,
                fresnelIridescence(1.0f, m.iridescenceIor, c, m.iridescenceThickness,
                                   m.baseColor),
                m.iridescence);
    }
#endif
    return f;
}

// Colour a microfacet at cosine c = wo.h > 0 reflects: metal, plus the dielectric layer, whose
// opaque part uses Schlick at c and whose transmissive part the interface (with TIR).
WF_INLINE vec3 microReflectance(BsdfParams m, BsdfLobes l, float c) {
    float ct = interfaceCosine(c, l.etaRel);
    vec3 fInterface = ct < 0.0f ? vec3(1.0f) : dielectricFresnel(m, l, ct);
    vec3 fOpaque = dielectricFresnel(m, l, c);
    vec3 dielectric = m.specular * mix(fOpaque, fInterface, m.transmission);
    return (1.0f - m.metallic) * dielectric + m.metallic * metalFresnel(m, c);
}

// Colour a microfacet transmits (before the 1 / eta^2 radiance scaling), given the cosine on
// the thin side of the interface (-1: total internal reflection).
WF_INLINE vec3 microTransmittanceThin(BsdfParams m, BsdfLobes l, float ct) {
    if (ct < 0.0f || l.kTransmit <= 0.0f) {
        return vec3(0.0f);
    }
    float f = m.specular * maxComponent(dielectricFresnel(m, l, ct));
    return m.baseColor * (l.kTransmit * (1.0f - f));
}

// The same at cosine c = wo.h > 0.
WF_INLINE vec3 microTransmittance(BsdfParams m, BsdfLobes l, float c) {
    return microTransmittanceThin(m, l, interfaceCosine(c, l.etaRel));
}

// (reflect, refract) probabilities at a microfacet: proportional to what each carries, so a
// sample's weight stays near the lobe albedo. (0, 0) when the microfacet carries nothing.
WF_INLINE vec2 microChoice(BsdfParams m, BsdfLobes l, float c) {
    float r = averageComponent(microReflectance(m, l, c));
    float t = averageComponent(microTransmittance(m, l, c));
    return r + t > 0.0f ? vec2(r, t) / (r + t) : vec2(0.0f);
}

// Probability of the diffuse lobe for wo (mirrored, muO = wo.z > 0): proportional to the
// diffuse albedo versus the microfacet lobe's Fresnel at the macro normal. The microfacet lobe
// keeps at least 1/11 whenever it exists: rough refraction can happen where the macro Fresnel
// says TIR, and F0 = 0 (ior 1) still reflects at tilted microfacets.
WF_INLINE float bsdfDiffuseProbability(BsdfParams m, BsdfLobes l, float muO) {
    float eD = l.diffuseNorm > 1e-6f ? l.kDiffuse * averageComponent(diffuseAlbedo(m)) *
                                           specularComplement(m, l, muO)
                                     : 0.0f;
    float eM = averageComponent(microReflectance(m, l, muO) + microTransmittance(m, l, muO));
    bool microExists = m.metallic > 0.0f || m.specular > 0.0f ||
                       l.kTransmit * maxComponent(m.baseColor) > 0.0f;
    if (!microExists || eD <= 0.0f) {
        return !microExists && eD > 0.0f ? 1.0f : 0.0f;
    }
    eM = max(eM, 0.1f * eD);
    return eD / (eD + eM);
}

// Generalized half vector of a refraction pair (Walter et al. 2007), turned to wo's side; false
// when no microfacet can refract wo into wi.
WF_INLINE bool refractionHalfVector(vec3 wo, vec3 wi, float etaRel, WF_OUT(vec3) h) {
    h = wo + etaRel * wi;
    float len2 = dot(h, h);
    if (!(len2 > 1e-12f)) {
        return false;
    }
    h *= inversesqrt(len2);
    h = h.z < 0.0f ? -h : h;
    return dot(wo, h) > 0.0f && dot(wi, h) < 0.0f;
}

// f(wo, wi) in the mirrored frame (wo.z > 0, wi.z != 0).
WF_INLINE vec3 bsdfEvalMirrored(BsdfParams m, BsdfLobes l, vec3 wo, vec3 wi) {
    if (wi.z > 0.0f) {
        vec3 f = diffuseLobe(m, l, wo.z, wi.z);
        if (!l.delta) {
            vec3 h = normalize(wo + wi); // nonzero: both are in the upper hemisphere
            f += microReflectance(m, l, dot(wo, h)) *
                 (ggxD(h, l.alpha) * 0.25f * ggxG2OverCosines(wo, wi, l.alpha));
        }
        return f;
    }
#if WF_HAS_DIFFUSE_TRANSMISSION
    vec3 fd = diffuseTransmittance(m) * diffuseShape(m, l, wo.z, -wi.z);
#else
    vec3 fd = vec3(0.0f);
#endif
    vec3 h;
    if (l.delta || l.indexMatched || !refractionHalfVector(wo, wi, l.etaRel, h)) {
        return fd;
    }
    float co = dot(wo, h);
    float ci = dot(wi, h);
    // Walter's |wi.h| |wo.h| / (wi.h + wo.h / eta)^2 times the radiance scaling 1 / eta^2.
    // Fresnel takes the thin side's cosine as it is, not through Snell, which cancels
    // catastrophically near grazing and would break reciprocity.
    float denom = co + l.etaRel * ci;
    return fd + microTransmittanceThin(m, l, l.etaRel >= 1.0f ? co : -ci) *
                    (ggxD(h, l.alpha) * ggxG2OverCosines(wo, wi, l.alpha) * (-ci) * co /
                     (denom * denom));
}

// bsdfPdf in the mirrored frame, given the diffuse lobe's probability for this wo.
WF_INLINE float bsdfPdfMirrored(BsdfParams m, BsdfLobes l, float pDiffuse, vec3 wo, vec3 wi) {
    if (wi.z > 0.0f) {
        float pdf = pDiffuse * cosineHemispherePdf(wi.z);
#if WF_HAS_DIFFUSE_TRANSMISSION
        pdf *= 1.0f - diffuseTransmitProbability(m);
#endif
        if (!l.delta) {
            vec3 h = normalize(wo + wi);
            // Visible-normal pdf / (4 wo.h) = D / (2 (wo.z + L(wo))).
            pdf += (1.0f - pDiffuse) * microChoice(m, l, dot(wo, h)).x * ggxD(h, l.alpha) * 0.5f /
                   (wo.z + ggxStretchedLength(wo, l.alpha));
        }
        return pdf;
    }
#if WF_HAS_DIFFUSE_TRANSMISSION
    float pdfD = pDiffuse * diffuseTransmitProbability(m) * cosineHemispherePdf(-wi.z);
#else
    float pdfD = 0.0f;
#endif
    vec3 h;
    if (l.delta || l.indexMatched || !refractionHalfVector(wo, wi, l.etaRel, h)) {
        return pdfD;
    }
    float co = dot(wo, h);
    float ci = dot(wi, h);
    float denom = co + l.etaRel * ci; // d omega_h / d omega_i = eta^2 |wi.h| / denom^2
    return pdfD + (1.0f - pDiffuse) * microChoice(m, l, co).y *
                      ggxVisibleNormalPdf(wo, h, l.alpha) * l.etaRel * l.etaRel * (-ci) /
                      (denom * denom);
}

// The specular kind's shade pass (WF_BSDF_DELTA_ONLY) shades only materials with Dirac lobes
// and no diffuse lobe whatever their textures (roughness 0; metallic or transmission exactly 1
// and untextured: src/passes/shade_kinds.cpp). bsdfSample becomes this: the general sample with
// the diffuse lobe's probability 0 and the microfacet normal +z, the same arithmetic; nothing
// has a density, so bsdfEval and bsdfPdf are 0 and next-event estimation drops out.
WF_INLINE bool deltaOnlySample(BsdfParams m, vec3 wo, float uLobe, WF_OUT(BsdfSample) s) {
    bsdfNoSample(s);
    if (wo.z == 0.0f) {
        return false;
    }
    m = bsdfSanitize(m);
    bool inside = wo.z < 0.0f;
    float side = inside ? -1.0f : 1.0f;
    wo.z *= side;
    BsdfLobes l = bsdfLobes(m, inside);
    float uChoice = min(uLobe, 0.99999994f);
    vec3 h = vec3(0.0f, 0.0f, 1.0f);
    float c = dot(wo, h);
    vec2 choice = microChoice(m, l, c);
    if (!(c > 0.0f) || choice.x + choice.y <= 0.0f) {
        return false;
    }
    vec3 wi;
    if (uChoice < choice.x) {
        wi = 2.0f * c * h - wo;
        if (!(wi.z > 0.0f)) {
            return false;
        }
        s.isDelta = true;
        s.pdf = choice.x;
        s.weight = microReflectance(m, l, c) / s.pdf;
    } else {
        if (l.indexMatched) {
            wi = -wo;
        } else if (!refractDirection(wo, h, l.etaRel, wi) || !(wi.z < 0.0f)) {
            return false;
        } else {
            s.eta = l.etaRel;
        }
        s.isDelta = true;
        s.pdf = choice.y;
        s.weight = microTransmittance(m, l, c) / (s.eta * s.eta * s.pdf);
    }
    s.wi = vec3(wi.x, wi.y, side * wi.z);
    return s.pdf > 0.0f && bsdfFinite(s.weight) && bsdfFinite(vec3(s.pdf));
}

WF_INLINE vec3 bsdfEval(BsdfParams m, vec3 wo, vec3 wi) {
#if WF_BSDF_DELTA_ONLY
    return vec3(0.0f);
#endif
#if WF_BSDF_DIFFUSE_ONLY
    return diffuseOnlyEval(m, wo, wi);
#endif
    if (wo.z == 0.0f || wi.z == 0.0f) {
        return vec3(0.0f);
    }
    m = bsdfSanitize(m);
    bool inside = wo.z < 0.0f;
    float side = inside ? -1.0f : 1.0f; // mirror so that wo.z > 0; etaRel remembers the side
    return bsdfEvalMirrored(m, bsdfLobes(m, inside), vec3(wo.x, wo.y, side * wo.z),
                            vec3(wi.x, wi.y, side * wi.z));
}

WF_INLINE float bsdfPdf(BsdfParams m, vec3 wo, vec3 wi) {
#if WF_BSDF_DELTA_ONLY
    return 0.0f;
#endif
#if WF_BSDF_DIFFUSE_ONLY
    return diffuseOnlyPdf(m, wo, wi);
#endif
    if (wo.z == 0.0f || wi.z == 0.0f) {
        return 0.0f;
    }
    m = bsdfSanitize(m);
    bool inside = wo.z < 0.0f;
    float side = inside ? -1.0f : 1.0f;
    BsdfLobes l = bsdfLobes(m, inside);
    return bsdfPdfMirrored(m, l, bsdfDiffuseProbability(m, l, side * wo.z),
                           vec3(wo.x, wo.y, side * wo.z), vec3(wi.x, wi.y, side * wi.z));
}

WF_INLINE bool bsdfSample(BsdfParams m, vec3 wo, float uLobe, vec2 u, WF_OUT(BsdfSample) s) {
#if WF_BSDF_DELTA_ONLY
    return deltaOnlySample(m, wo, uLobe, s);
#endif
#if WF_BSDF_DIFFUSE_ONLY
    return diffuseOnlySample(m, wo, u, s);
#endif
    bsdfNoSample(s);
    if (wo.z == 0.0f) {
        return false;
    }
    m = bsdfSanitize(m);
    bool inside = wo.z < 0.0f;
    float side = inside ? -1.0f : 1.0f;
    wo.z *= side;
    BsdfLobes l = bsdfLobes(m, inside);
    float pDiffuse = bsdfDiffuseProbability(m, l, wo.z);
    vec3 wi;
    if (uLobe < pDiffuse) {
        wi = sampleCosineHemisphere(u);
#if WF_HAS_DIFFUSE_TRANSMISSION
        // The lobe's dimension, rescaled, picks reflection or transmission.
        if (uLobe < pDiffuse * diffuseTransmitProbability(m)) {
            wi.z = -wi.z;
        }
#endif
    } else {
        float uChoice = min((uLobe - pDiffuse) / (1.0f - pDiffuse), 0.99999994f);
        vec3 h = l.delta ? vec3(0.0f, 0.0f, 1.0f) : ggxSampleVisibleNormal(wo, l.alpha, u);
        float c = dot(wo, h);
        vec2 choice = microChoice(m, l, c);
        if (!(c > 0.0f) || choice.x + choice.y <= 0.0f) {
            return false;
        }
        if (uChoice < choice.x) {
            wi = 2.0f * c * h - wo;
            if (!(wi.z > 0.0f)) {
                return false; // reflected below the surface: masked
            }
            if (l.delta) {
                s.isDelta = true;
                s.pdf = (1.0f - pDiffuse) * choice.x;
                s.weight = microReflectance(m, l, c) / s.pdf;
            }
        } else {
            if (l.indexMatched) {
                wi = -wo;
            } else if (!refractDirection(wo, h, l.etaRel, wi) || !(wi.z < 0.0f)) {
                return false; // total internal reflection, or refracted back up: masked
            } else {
                s.eta = l.etaRel;
            }
            if (l.delta || l.indexMatched) {
                s.isDelta = true;
                s.pdf = (1.0f - pDiffuse) * choice.y;
                s.weight = microTransmittance(m, l, c) / (s.eta * s.eta * s.pdf);
            }
        }
    }
    if (!s.isDelta) {
        // Mixture pdf over every non-delta lobe (one-sample MIS across lobes), so the weight
        // is what bsdfEval and bsdfPdf give the same direction in next-event estimation.
        s.pdf = bsdfPdfMirrored(m, l, pDiffuse, wo, wi);
        if (!(s.pdf > 0.0f)) {
            return false;
        }
        vec3 f = bsdfEvalMirrored(m, l, wo, wi);
        s.weight = f * (abs(wi.z) / s.pdf);
#if WF_HAS_DIFFUSE_TRANSMISSION
        if (wi.z < 0.0f) {
            s.eta = diffuseTransmissionEta(m, l, wo, wi, f);
        }
#endif
    }
    s.wi = vec3(wi.x, wi.y, side * wi.z);
    return s.pdf > 0.0f && bsdfFinite(s.weight) && bsdfFinite(vec3(s.pdf));
}

// The Dirac reflection bsdfSample (and deltaOnlySample) picks for wo where roughness is 0: its
// throughput (a Dirac sample's weight times pdf) and the probability of that choice (its pdf);
// zero for rough lobes. Every ior reflects into the same mirror direction, so --spectral hero
// weighs its four wavelengths' chances of this one event (wave/hero_lanes.glsl).
WF_INLINE vec3 bsdfDeltaReflection(BsdfParams m, vec3 wo, WF_OUT(float) probability) {
    probability = 0.0f;
#if WF_BSDF_DIFFUSE_ONLY
    return vec3(0.0f);
#endif
    if (wo.z == 0.0f) {
        return vec3(0.0f);
    }
    m = bsdfSanitize(m);
    BsdfLobes l = bsdfLobes(m, wo.z < 0.0f);
    float c = abs(wo.z);
    vec2 choice = microChoice(m, l, c);
    if (!l.delta || choice.x + choice.y <= 0.0f) {
        return vec3(0.0f);
    }
#if WF_BSDF_DELTA_ONLY
    float pDiffuse = 0.0f;
#else
    float pDiffuse = bsdfDiffuseProbability(m, l, c);
#endif
    probability = (1.0f - pDiffuse) * choice.x;
    return microReflectance(m, l, c);
}

// Whether some lobe has a density (NEE and MIS can work at this vertex).
WF_INLINE bool bsdfHasNonDelta(BsdfParams m) {
#if WF_BSDF_DELTA_ONLY
    return false;
#endif
#if WF_BSDF_DIFFUSE_ONLY
    return diffuseOnlyHasNonDelta(m);
#endif
    m = bsdfSanitize(m);
    float albedo = maxComponent(m.baseColor);
    if ((1.0f - m.metallic) * (1.0f - m.transmission) * maxComponent(diffuseAlbedo(m)) > 0.0f) {
        return true; // diffuse, reflected or transmitted
    }
#if WF_HAS_ANISOTROPY
    if (m.roughness == 0.0f && m.anisotropy == 0.0f) {
#else
    if (m.roughness == 0.0f) {
#endif
        return false;
    }
    bool refracts = (1.0f - m.metallic) * m.transmission * albedo > 0.0f &&
                    abs(bsdfRefractiveIor(m) - 1.0f) >= 1e-3f;
    return m.metallic > 0.0f || m.specular > 0.0f || refracts;
}

// Whether the BSDF scatters only into Dirac lobes (a black, non-scattering BSDF is neither).
WF_INLINE bool bsdfIsPureDelta(BsdfParams m) {
    m = bsdfSanitize(m);
    bool scatters = m.metallic > 0.0f || m.specular > 0.0f || maxComponent(m.baseColor) > 0.0f ||
                    maxComponent(diffuseTransmittance(m)) > 0.0f;
    return scatters && !bsdfHasNonDelta(m);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
