// KHR_materials_clearcoat and KHR_materials_sheen over the glTF BSDF of bsdf.h, one header for
// the shade pass (GLSL, included only where the scene has a coat or sheen: WF_HAS_CLEARCOAT,
// WF_HAS_SHEEN) and the CPU tests (C++, tests/unit/test_bsdf_layers.cpp, both layers on).
// Frames and conventions are bsdf.h's; the layers act on wo's side, like the base's own
// reflection lobes (so inside a coated glass the coat reflects too: two-sided, energy-bounded).
//
// Model (glTF's KHR_materials_clearcoat and _sheen, in a bounded form):
//   f = c f_coat + Wc [ f_sheen + Ws f_base ]
//   f_coat  = Schlick(0.04, wo.h) GGX(clearcoatRoughness^2): a dielectric coat of IOR 1.5
//   f_sheen = sheenColor D V / max(1, S(mu_o), S(mu_i))               (sheen.h)
//   Wc      = min(1 - c C(mu_o), 1 - c C(mu_i)),   Ws = min(1 - s S'(mu_o), 1 - s S'(mu_i))
// with c = clearcoatFactor, s = max(sheenColor), C(mu) the coat's directional albedo bound
// (bsdf.h's F0 + (1 - F0) kappa (1 - mu)^n at F0 0.04, which is at least Schlick's Fresnel at
// the macro normal), S(mu) the sheen albedo bound (sheenAlbedoBound) and S' = min(S, 1).
// The spec's mix(base, coat, c F_c) scales the base by 1 - c F_c(N.V) alone; taking the larger
// albedo bound over view and light keeps f reciprocal, and since each layer reflects at most its
// bound, the albedo at wo is at most c C + (1 - c C)(s S' + (1 - s S')) = 1: no layering gains
// energy. The sheen lobe's own albedo passes 1 at grazing angles for low roughness, which the
// max(1, S) divisor removes. Departure: a coat without a normal map of its own uses the base's
// shading normal (normal map included), where the spec has the vertex normal.
//
// The coat's own normal map (WF_HAS_CLEARCOAT_NORMAL_MAPS: BsdfLayers.coatNormal, in the
// base's shading frame): the coat's GGX lobe and its albedo bound C are evaluated in the coat's
// frame, with the coat's cosine in place of the base's (f_coat |cos_base| = f_coat' cos_coat),
// so the coat reflects exactly what a flat coat reflects at the tilted angle, at most
// c C(mu'_o), and Wc takes the coat-frame cosines: the bound above holds. Directions below either
// horizon get nothing from the coat.
//
// Sampling: the coat (GGX visible normals; a Dirac mirror at roughness 0), the sheen (cosine)
// or the base (bsdfSample), chosen by uLobe with probabilities proportional to c C(mu_o),
// (1 - c C(mu_o)) s S'(mu_o) and the rest times an estimate of the base's albedo; non-delta
// samples get the mixture pdf of every non-delta lobe and weight = f |cos| / pdf.
#ifndef WF_BSDF_LAYERS_H
#define WF_BSDF_LAYERS_H

#include "bsdf/bsdf.h"

#ifdef __cplusplus
#ifndef WF_HAS_CLEARCOAT
#define WF_HAS_CLEARCOAT 1
#endif
#ifndef WF_HAS_SHEEN
#define WF_HAS_SHEEN 1
#endif
#ifndef WF_HAS_CLEARCOAT_NORMAL_MAPS
#define WF_HAS_CLEARCOAT_NORMAL_MAPS 1
#endif
#endif
#if WF_HAS_SHEEN
#include "bsdf/sheen.h"
#endif

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

#define WF_COAT_F0 0.04f // ((1.5 - 1) / (1.5 + 1))^2

struct BsdfLayers {
    float clearcoat;          // clearcoatFactor
    float clearcoatRoughness; // perceptual: alpha = roughness^2; exactly 0 is a Dirac mirror
    vec3 sheenColor;          // sheenColorFactor (linear)
    float sheenRoughness;
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
    // The coat's unit normal in the base's shading frame (+z the base's normal, on the side
    // the frame calls outside); (0, 0, 1) exactly for a coat without a normal map of its own.
#ifdef __cplusplus
    vec3 coatNormal = vec3(0.0f, 0.0f, 1.0f);
#else
    vec3 coatNormal;
#endif
#endif
};

// What eval, pdf and sample share for one material and wo.
struct LayerLobes {
    float coat;       // c
    float coatAlpha;
    bool coatDelta;
    float coatKappa;  // C(mu) = F0 + (1 - F0) kappa (1 - mu)^power
    float coatPower;
    float sheen;      // s = max(sheenColor)
    float sheenRoughness;
    float sheenAlpha;
    float pCoat;      // lobe choice probabilities at wo
    float pSheen;
    float pBase;
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
    bool coatTilted;  // the coat's frame below, in the mirrored frame, differs from the base's
    vec3 coatT;
    vec3 coatB;
    vec3 coatN;
#endif
};

WF_INLINE BsdfLayers layersSanitize(BsdfLayers l) {
    l.clearcoat = clamp(l.clearcoat, 0.0f, 1.0f);
    l.clearcoatRoughness = clamp(l.clearcoatRoughness, 0.0f, 1.0f);
    l.sheenColor = clamp(l.sheenColor, vec3(0.0f), vec3(1.0f));
    l.sheenRoughness = clamp(l.sheenRoughness, 0.0f, 1.0f);
#if !WF_HAS_CLEARCOAT
    l.clearcoat = 0.0f;
#endif
#if !WF_HAS_SHEEN
    l.sheenColor = vec3(0.0f);
#endif
    return l;
}

WF_INLINE float coatAlbedoBound(LayerLobes w, float mu) {
    return WF_COAT_F0 +
           (1.0f - WF_COAT_F0) * w.coatKappa * pow(clamp(1.0f - mu, 0.0f, 1.0f), w.coatPower);
}

#if WF_HAS_CLEARCOAT_NORMAL_MAPS
// A mirrored-frame direction in the coat's frame, and back.
WF_INLINE vec3 toCoatFrame(LayerLobes w, vec3 v) {
    return w.coatTilted ? vec3(dot(v, w.coatT), dot(v, w.coatB), dot(v, w.coatN)) : v;
}
WF_INLINE vec3 fromCoatFrame(LayerLobes w, vec3 v) {
    return w.coatTilted ? w.coatT * v.x + w.coatB * v.y + w.coatN * v.z : v;
}
// The cosine C and Wc take: the coat's (clamped to [0, 1]: C(0) bounds every angle).
WF_INLINE float coatCosine(LayerLobes w, vec3 vM) {
    return w.coatTilted ? clamp(dot(vM, w.coatN), 0.0f, 1.0f) : abs(vM.z);
}
#endif

#if WF_HAS_SHEEN
// min(1, S(mu)): the albedo of the normalised sheen lobe is at most this.
WF_INLINE float sheenAlbedoCapped(LayerLobes w, float mu) {
    return min(sheenAlbedoBound(w.sheenRoughness, mu), 1.0f);
}
#endif

// Wc: what the coat leaves to the layers beneath, for the pair of cosines.
WF_INLINE float coatScale(LayerLobes w, float muO, float muI) {
    if (w.coat <= 0.0f) {
        return 1.0f;
    }
    return 1.0f - w.coat * max(coatAlbedoBound(w, muO), coatAlbedoBound(w, muI));
}

// Ws: what the sheen leaves to the base.
WF_INLINE float sheenScale(LayerLobes w, float muO, float muI) {
#if WF_HAS_SHEEN
    if (w.sheen > 0.0f) {
        return 1.0f - w.sheen * max(sheenAlbedoCapped(w, muO), sheenAlbedoCapped(w, muI));
    }
#endif
    return 1.0f;
}

WF_INLINE LayerLobes layerLobes(BsdfParams m, BsdfLayers layers, vec3 wo) {
    float muO = abs(wo.z);
    LayerLobes w;
    w.coat = layers.clearcoat;
    w.coatDelta = layers.clearcoatRoughness == 0.0f;
    w.coatAlpha = max(layers.clearcoatRoughness * layers.clearcoatRoughness, WF_GGX_MIN_ALPHA);
    // bsdf.h's fit of the GGX layer's albedo bound, at the coat's roughness.
    w.coatKappa = 1.0f / (1.0f + 20.7f * pow(layers.clearcoatRoughness, 2.32f));
    float d = layers.clearcoatRoughness - 0.44f;
    w.coatPower = 2.84f + 5.15f * d * d;
    w.sheen = maxComponent(layers.sheenColor);
    w.sheenRoughness = layers.sheenRoughness;
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
    // The coat's normal mirrored with wo (see layeredSample): (side x, side y, z), or the
    // base's where it does not point above the base's horizon.
    float side = wo.z < 0.0f ? -1.0f : 1.0f;
    vec3 cn = layers.coatNormal;
    w.coatTilted = cn.z > 0.0f && cn != vec3(0.0f, 0.0f, 1.0f);
    w.coatN = w.coatTilted ? normalize(vec3(side * cn.x, side * cn.y, cn.z))
                           : vec3(0.0f, 0.0f, 1.0f);
    buildOrthonormalBasis(w.coatN, w.coatT, w.coatB);
    float muCoat = coatCosine(w, vec3(wo.x, wo.y, muO));
#else
    float muCoat = muO;
#endif
    float eCoat = w.coat > 0.0f ? w.coat * coatAlbedoBound(w, muCoat) : 0.0f;
    float eSheen = 0.0f;
#if WF_HAS_SHEEN
    w.sheenAlpha = sheenAlpha(layers.sheenRoughness);
    eSheen = w.sheen > 0.0f ? (1.0f - eCoat) * w.sheen * sheenAlbedoCapped(w, muO) : 0.0f;
#else
    w.sheenAlpha = 1.0f;
#endif
    // The base's share, by an albedo estimate that never starves a base that scatters at all.
    // (diffuseAlbedo: the base colour, and with diffuse transmission what crosses too.)
    bool baseScatters = m.metallic > 0.0f || m.specular > 0.0f ||
                        maxComponent(m.baseColor) > 0.0f ||
                        maxComponent(diffuseTransmittance(m)) > 0.0f;
    float eBase = baseScatters
                      ? (1.0f - eCoat - eSheen) * max(averageComponent(diffuseAlbedo(m)), 0.2f)
                      : 0.0f;
    float total = eCoat + eSheen + eBase;
    w.pCoat = total > 0.0f ? eCoat / total : 0.0f;
    w.pSheen = total > 0.0f ? eSheen / total : 0.0f;
    w.pBase = total > 0.0f ? eBase / total : 0.0f;
    return w;
}

// The coat's GGX reflection for wo, wi in the upper hemisphere (rough coats only).
WF_INLINE float coatReflection(LayerLobes w, vec3 wo, vec3 wi) {
    vec3 h = normalize(wo + wi);
    float f = WF_COAT_F0 + (1.0f - WF_COAT_F0) * schlickWeight(dot(wo, h));
    return w.coat * f * ggxD(h, w.coatAlpha) * 0.25f * ggxG2OverCosines(wo, wi, w.coatAlpha);
}

WF_INLINE float coatReflectionPdf(LayerLobes w, vec3 wo, vec3 wi) {
    vec3 h = normalize(wo + wi);
    return ggxD(h, w.coatAlpha) * 0.5f / (wo.z + ggxStretchedLength(wo, w.coatAlpha));
}

#if WF_HAS_SHEEN
WF_INLINE vec3 sheenReflection(BsdfLayers layers, LayerLobes w, vec3 wo, vec3 wi) {
    float norm = max(1.0f, max(sheenAlbedoBound(w.sheenRoughness, wo.z),
                               sheenAlbedoBound(w.sheenRoughness, wi.z)));
    return layers.sheenColor * (sheenLobe(w.sheenAlpha, wo, wi) / norm);
}
#endif

// f and pdf of the layers' own lobes, mirrored frame (woM.z > 0, wiM.z > 0); `scale` is Wc.
WF_INLINE vec3 layersEvalMirrored(BsdfLayers layers, LayerLobes w, vec3 woM, vec3 wiM,
                                  float scale) {
    vec3 f = vec3(0.0f);
#if WF_HAS_SHEEN
    if (w.sheen > 0.0f) {
        f += scale * sheenReflection(layers, w, woM, wiM);
    }
#endif
#if WF_HAS_CLEARCOAT
    if (w.coat > 0.0f && !w.coatDelta) {
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
        vec3 woC = toCoatFrame(w, woM);
        vec3 wiC = toCoatFrame(w, wiM);
        if (woC.z > 0.0f && wiC.z > 0.0f) {
            f += vec3(coatReflection(w, woC, wiC) * (wiC.z / wiM.z));
        }
#else
        f += vec3(coatReflection(w, woM, wiM));
#endif
    }
#endif
    return f;
}

WF_INLINE float layersPdfMirrored(LayerLobes w, vec3 woM, vec3 wiM) {
    float pdf = 0.0f;
#if WF_HAS_SHEEN
    pdf += w.pSheen * cosineHemispherePdf(wiM.z);
#endif
#if WF_HAS_CLEARCOAT
    if (w.pCoat > 0.0f && !w.coatDelta) {
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
        vec3 woC = toCoatFrame(w, woM);
        vec3 wiC = toCoatFrame(w, wiM);
        if (woC.z > 0.0f && wiC.z > 0.0f) {
            pdf += w.pCoat * coatReflectionPdf(w, woC, wiC);
        }
#else
        pdf += w.pCoat * coatReflectionPdf(w, woM, wiM);
#endif
    }
#endif
    return pdf;
}

WF_INLINE vec3 layeredEvalWith(BsdfParams m, BsdfLayers layers, LayerLobes w, vec3 wo, vec3 wi) {
    float muO = abs(wo.z);
    float muI = abs(wi.z);
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
    float wc = coatScale(w, coatCosine(w, vec3(wo.x, wo.y, muO)),
                         coatCosine(w, vec3(wi.x, wi.y, muI)));
#else
    float wc = coatScale(w, muO, muI);
#endif
    vec3 f = bsdfEval(m, wo, wi) * (wc * sheenScale(w, muO, muI));
    float side = wo.z < 0.0f ? -1.0f : 1.0f;
    if (side * wi.z > 0.0f) {
        f += layersEvalMirrored(layers, w, vec3(wo.x, wo.y, muO), vec3(wi.x, wi.y, muI), wc);
    }
    return f;
}

WF_INLINE float layeredPdfWith(BsdfParams m, LayerLobes w, vec3 wo, vec3 wi) {
    float pdf = w.pBase > 0.0f ? w.pBase * bsdfPdf(m, wo, wi) : 0.0f;
    float side = wo.z < 0.0f ? -1.0f : 1.0f;
    if (side * wi.z > 0.0f) {
        pdf += layersPdfMirrored(w, vec3(wo.x, wo.y, abs(wo.z)), vec3(wi.x, wi.y, abs(wi.z)));
    }
    return pdf;
}

WF_INLINE vec3 layeredEval(BsdfParams m, BsdfLayers layers, vec3 wo, vec3 wi) {
    if (wo.z == 0.0f || wi.z == 0.0f) {
        return vec3(0.0f);
    }
    m = bsdfSanitize(m);
    layers = layersSanitize(layers);
    return layeredEvalWith(m, layers, layerLobes(m, layers, wo), wo, wi);
}

WF_INLINE float layeredPdf(BsdfParams m, BsdfLayers layers, vec3 wo, vec3 wi) {
    if (wo.z == 0.0f || wi.z == 0.0f) {
        return 0.0f;
    }
    m = bsdfSanitize(m);
    layers = layersSanitize(layers);
    return layeredPdfWith(m, layerLobes(m, layers, wo), wo, wi);
}

WF_INLINE bool layeredSample(BsdfParams m, BsdfLayers layers, vec3 wo, float uLobe, vec2 u,
                             WF_OUT(BsdfSample) s) {
    bsdfNoSample(s);
    if (wo.z == 0.0f) {
        return false;
    }
    m = bsdfSanitize(m);
    layers = layersSanitize(layers);
    float side = wo.z < 0.0f ? -1.0f : 1.0f;
    vec3 woM = vec3(wo.x, wo.y, abs(wo.z));
    LayerLobes w = layerLobes(m, layers, wo);
    vec3 wiM;
    float eta = 1.0f;
    if (uLobe < w.pCoat) {
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
        // In the coat's frame, then back; what leaves below the base's horizon is lost.
        vec3 woC = toCoatFrame(w, woM);
        if (!(woC.z > 0.0f)) {
            return false;
        }
        if (w.coatDelta) {
            wiM = fromCoatFrame(w, vec3(-woC.x, -woC.y, woC.z));
            if (!(wiM.z > 0.0f)) {
                return false;
            }
            s.wi = vec3(wiM.x, wiM.y, side * wiM.z);
            s.isDelta = true;
            s.pdf = w.pCoat;
            float f = WF_COAT_F0 + (1.0f - WF_COAT_F0) * schlickWeight(woC.z);
            s.weight = vec3(w.coat * f / w.pCoat);
            return true;
        }
        vec3 h = ggxSampleVisibleNormal(woC, w.coatAlpha, u);
        float c = dot(woC, h);
        vec3 wiC = 2.0f * c * h - woC;
        wiM = fromCoatFrame(w, wiC);
        if (!(c > 0.0f) || !(wiC.z > 0.0f) || !(wiM.z > 0.0f)) {
            return false; // masked, or below the base's horizon
        }
#else
        if (w.coatDelta) {
            s.wi = vec3(-wo.x, -wo.y, wo.z);
            s.isDelta = true;
            s.pdf = w.pCoat;
            float f = WF_COAT_F0 + (1.0f - WF_COAT_F0) * schlickWeight(woM.z);
            s.weight = vec3(w.coat * f / w.pCoat);
            return true;
        }
        vec3 h = ggxSampleVisibleNormal(woM, w.coatAlpha, u);
        float c = dot(woM, h);
        wiM = 2.0f * c * h - woM;
        if (!(c > 0.0f) || !(wiM.z > 0.0f)) {
            return false; // reflected below the surface: masked
        }
#endif
    } else if (uLobe < w.pCoat + w.pSheen) {
        wiM = sampleCosineHemisphere(u);
    } else {
        float uBase = min((uLobe - w.pCoat - w.pSheen) / w.pBase, 0.99999994f);
        BsdfSample b;
        if (!(w.pBase > 0.0f) || !bsdfSample(m, wo, uBase, u, b)) {
            return false;
        }
        if (b.isDelta) {
            float muI = abs(b.wi.z);
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
            float scale =
                coatScale(w, coatCosine(w, woM), coatCosine(w, vec3(b.wi.x, b.wi.y, muI))) *
                sheenScale(w, woM.z, muI);
#else
            float scale = coatScale(w, woM.z, muI) * sheenScale(w, woM.z, muI);
#endif
            s.wi = b.wi;
            s.isDelta = true;
            s.pdf = w.pBase * b.pdf;
            s.weight = b.weight * (scale / w.pBase);
            s.eta = b.eta;
            return s.pdf > 0.0f && bsdfFinite(s.weight);
        }
        wiM = vec3(b.wi.x, b.wi.y, side * b.wi.z);
        eta = b.eta;
    }
    vec3 wi = vec3(wiM.x, wiM.y, side * wiM.z);
    s.pdf = layeredPdfWith(m, w, wo, wi);
    if (!(s.pdf > 0.0f)) {
        return false;
    }
    s.wi = wi;
    s.eta = eta;
    s.weight = layeredEvalWith(m, layers, w, wo, wi) * (abs(wi.z) / s.pdf);
    return bsdfFinite(s.weight) && bsdfFinite(vec3(s.pdf));
}

WF_INLINE bool layeredHasNonDelta(BsdfParams m, BsdfLayers layers) {
    layers = layersSanitize(layers);
    bool coat = layers.clearcoat > 0.0f && layers.clearcoatRoughness > 0.0f;
    bool sheen = maxComponent(layers.sheenColor) > 0.0f;
    return coat || sheen || bsdfHasNonDelta(m);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
