// The glTF BSDF as shaders compile it for scenes without KHR_materials_anisotropy and
// _diffuse_transmission (WF_HAS_ANISOTROPY and WF_HAS_DIFFUSE_TRANSMISSION 0), for
// test_anisotropy.cpp and test_diffuse_transmission.cpp: at strength or factor 0 the full
// build must give the same bits. Plain structs cross between the two builds (isotropic_bsdf.cpp).
#pragma once
#include <cstring>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

namespace wf::test {

// Equal bit patterns (so 0 and -0 differ, and NaN equals itself): what "bit for bit" means.
inline bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
inline bool sameBits(glm::vec3 a, glm::vec3 b) {
    return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

struct PlainMaterial {
    glm::vec3 baseColor;
    float metallic;
    float roughness;
    float ior;
    float transmission;
    float specular;
    glm::vec3 specularColor;
};

struct PlainSample {
    bool sampled;
    glm::vec3 wi;
    float pdf;
    glm::vec3 weight;
    bool isDelta;
    float eta;
};

glm::vec3 isotropicEval(const PlainMaterial& m, glm::vec3 wo, glm::vec3 wi);
float isotropicPdf(const PlainMaterial& m, glm::vec3 wo, glm::vec3 wi);
PlainSample isotropicSample(const PlainMaterial& m, glm::vec3 wo, float uLobe, glm::vec2 u);
bool isotropicHasNonDelta(const PlainMaterial& m);

// The full build's BSDF `m` (its extension at strength or factor 0) against the plain one,
// bit for bit: eval, pdf, hasNonDelta and a sample drawn with the same numbers. Params and
// Sample are the including test's BsdfParams and BsdfSample (its own defines).
template <class Params, class Sample>
::testing::AssertionResult matchesPlainBsdf(const Params& m, const PlainMaterial& plain,
                                            glm::vec3 wo, glm::vec3 wi, float uLobe,
                                            glm::vec2 u) {
    if (!sameBits(bsdfEval(m, wo, wi), isotropicEval(plain, wo, wi)))
        return ::testing::AssertionFailure() << "eval differs";
    if (!sameBits(bsdfPdf(m, wo, wi), isotropicPdf(plain, wo, wi)))
        return ::testing::AssertionFailure() << "pdf differs";
    if (bsdfHasNonDelta(m) != isotropicHasNonDelta(plain))
        return ::testing::AssertionFailure() << "hasNonDelta differs";
    Sample s;
    const bool sampled = bsdfSample(m, wo, uLobe, u, s);
    const PlainSample reference = isotropicSample(plain, wo, uLobe, u);
    if (sampled != reference.sampled)
        return ::testing::AssertionFailure() << "one samples, the other does not";
    if (sampled && !(sameBits(s.wi, reference.wi) && sameBits(s.weight, reference.weight) &&
                     sameBits(s.pdf, reference.pdf) && sameBits(s.eta, reference.eta) &&
                     s.isDelta == reference.isDelta))
        return ::testing::AssertionFailure() << "the samples differ";
    return ::testing::AssertionSuccess();
}

} // namespace wf::test
