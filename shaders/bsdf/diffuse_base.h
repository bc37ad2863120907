// The diffuse base of bsdf.h's dielectric: Lambert under the specular layer, coupled to it by
// the layer's complement at each end (bsdf.h's header), and KHR_materials_diffuse_transmission's
// split of it: (1 - diffuseTransmission) baseColor reflects, diffuseTransmission x
// diffuseTransmissionColor crosses to the other hemisphere as a Lambert lobe of its own, under
// the same coupling (the layer's complement at |cos| on each side, as a thin sheet with the layer
// on both faces has it). The split lobe is reciprocal and has no eta (it does not refract); the
// base's albedo is mix(baseColor, colour, diffuseTransmission) (1 - w E(mu_o)), so a white split
// without the layer loses nothing. Also the Lambert-only BSDF of scenes whose every material is
// Lambertian (WF_BSDF_DIFFUSE_ONLY). Included by bsdf.h after BsdfLobes, inside its namespace.
#ifndef WF_BSDF_DIFFUSE_BASE_H
#define WF_BSDF_DIFFUSE_BASE_H

// The diffuse base's colours: what it reflects, and what it sends through the surface.
WF_INLINE vec3 diffuseReflectance(BsdfParams m) {
#if WF_HAS_DIFFUSE_TRANSMISSION
    return m.baseColor * (1.0f - m.diffuseTransmission);
#else
    return m.baseColor;
#endif
}

WF_INLINE vec3 diffuseTransmittance(BsdfParams m) {
#if WF_HAS_DIFFUSE_TRANSMISSION
    return m.diffuseTransmissionColor * m.diffuseTransmission;
#else
    return vec3(0.0f);
#endif
}

// Both: what the diffuse base scatters, before the layer's coupling.
WF_INLINE vec3 diffuseAlbedo(BsdfParams m) {
#if WF_HAS_DIFFUSE_TRANSMISSION
    return diffuseReflectance(m) + diffuseTransmittance(m);
#else
    return m.baseColor;
#endif
}

// 1 - w E(mu): the share of light at cosine mu that the specular layer leaves to the base.
WF_INLINE float specularComplement(BsdfParams m, BsdfLobes l, float mu) {
    float e = l.f0Max + (1.0f - l.f0Max) * l.kappa * pow(clamp(1.0f - mu, 0.0f, 1.0f), l.power);
    return 1.0f - m.specular * e;
}

// The diffuse base's lobe without its colour (muI = |wi.z|: the same on either side).
WF_INLINE float diffuseShape(BsdfParams m, BsdfLobes l, float muO, float muI) {
    if (l.kDiffuse <= 0.0f || l.diffuseNorm <= 1e-6f) {
        return 0.0f;
    }
    return l.kDiffuse * WF_INV_PI * specularComplement(m, l, muO) * specularComplement(m, l, muI) /
           l.diffuseNorm;
}

WF_INLINE vec3 diffuseLobe(BsdfParams m, BsdfLobes l, float muO, float muI) {
    return diffuseReflectance(m) * diffuseShape(m, l, muO, muI);
}

// The share of the diffuse lobe's samples that go through the surface.
WF_INLINE float diffuseTransmitProbability(BsdfParams m) {
#if WF_HAS_DIFFUSE_TRANSMISSION
    float r = averageComponent(diffuseReflectance(m));
    float t = averageComponent(diffuseTransmittance(m));
    return t > 0.0f ? t / (r + t) : 0.0f;
#else
    return 0.0f;
#endif
}

#if WF_HAS_DIFFUSE_TRANSMISSION
// The eta a transmitted direction with density reports when the Lambert transmission and rough
// refraction both reach it (f, their sum, from bsdfEvalMirrored): the one whose square is the
// lobes' average-colour mixture of eta^2 (refraction) and 1 (Lambert), so that the adjoint's
// eta^2 (adjoint_bsdf.h) turns f into f(wi, wo) exactly where the two lobes' colours are
// proportional (grey materials), and approximately otherwise. One lobe alone: its own eta.
WF_INLINE float diffuseTransmissionEta(BsdfParams m, BsdfLobes l, vec3 wo, vec3 wi, vec3 f) {
    if (l.kTransmit <= 0.0f || l.indexMatched || l.delta) {
        return 1.0f; // no rough refraction: Lambert alone
    }
    float lambert = averageComponent(diffuseTransmittance(m)) * diffuseShape(m, l, wo.z, -wi.z);
    if (!(lambert > 0.0f)) {
        return l.etaRel; // rough refraction alone
    }
    float refracted = max(averageComponent(f) - lambert, 0.0f);
    return sqrt((l.etaRel * l.etaRel * refracted + lambert) / (refracted + lambert));
}
#endif

WF_INLINE bool bsdfFinite(vec3 v) {
    return !any(isnan(v)) && !any(isinf(v));
}

// Scenes whose every material is Lambertian (metallic, specular and transmission all 0, which
// no texture can raise) compile with WF_BSDF_DIFFUSE_ONLY, and bsdfEval, bsdfPdf, bsdfSample
// and bsdfHasNonDelta become these: what the general model reduces to for such materials,
// without its layer (tests/unit/test_bsdf.cpp compares the two on random materials).
WF_INLINE bool diffuseOnlySameSide(vec3 wo, vec3 wi) {
    return wo.z != 0.0f && wi.z != 0.0f && (wo.z > 0.0f) == (wi.z > 0.0f);
}

WF_INLINE vec3 diffuseOnlyEval(BsdfParams m, vec3 wo, vec3 wi) {
    return diffuseOnlySameSide(wo, wi) ? clamp(m.baseColor, vec3(0.0f), vec3(1.0f)) * WF_INV_PI
                                       : vec3(0.0f);
}

WF_INLINE float diffuseOnlyPdf(BsdfParams m, vec3 wo, vec3 wi) {
    bool scatters = averageComponent(clamp(m.baseColor, vec3(0.0f), vec3(1.0f))) > 0.0f;
    return scatters && diffuseOnlySameSide(wo, wi) ? cosineHemispherePdf(abs(wi.z)) : 0.0f;
}

WF_INLINE bool diffuseOnlyHasNonDelta(BsdfParams m) {
    return maxComponent(clamp(m.baseColor, vec3(0.0f), vec3(1.0f))) > 0.0f;
}

// The sample every sampler starts from and returns on failure: no direction, no weight.
WF_INLINE void bsdfNoSample(WF_OUT(BsdfSample) s) {
    s.wi = vec3(0.0f);
    s.pdf = 0.0f;
    s.weight = vec3(0.0f);
    s.isDelta = false;
    s.eta = 1.0f;
}

WF_INLINE bool diffuseOnlySample(BsdfParams m, vec3 wo, vec2 u, WF_OUT(BsdfSample) s) {
    bsdfNoSample(s);
    vec3 albedo = clamp(m.baseColor, vec3(0.0f), vec3(1.0f));
    if (wo.z == 0.0f || !(averageComponent(albedo) > 0.0f)) {
        return false;
    }
    vec3 wi = sampleCosineHemisphere(u);
    s.pdf = cosineHemispherePdf(wi.z);
    if (!(s.pdf > 0.0f)) {
        return false;
    }
    s.weight = albedo * WF_INV_PI * (wi.z / s.pdf);
    s.wi = vec3(wi.x, wi.y, wo.z < 0.0f ? -wi.z : wi.z);
    return bsdfFinite(s.weight);
}

#endif
