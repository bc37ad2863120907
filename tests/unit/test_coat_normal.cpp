// The clear coat's own normal (KHR_materials_clearcoat's clearcoatNormalTexture; bsdf_layers.h,
// BsdfLayers.coatNormal) on the CPU: a coat tilted away from the base's normal is sampled by
// its pdf (chi-square), weighs eval |cos| / pdf, mirrors about its own normal when smooth, and
// stays within the white furnace.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "shaders/bsdf/bsdf_layers.h"
#include "tests/unit/chi_square.h"

namespace {

using glm::vec2;
using glm::vec3;
using wf::test::uniform01;
using namespace wf::gpu_types;

BsdfParams base(vec3 color, float metallic, float roughness, float specular = 1.0f,
                float transmission = 0.0f) {
    return BsdfParams{color, metallic, roughness, 1.5f, transmission, specular, vec3(1.0f)};
}

BsdfLayers coat(float roughness, vec3 normal, float strength = 1.0f) {
    BsdfLayers l{strength, roughness, vec3(0.0f), 0.5f};
    l.coatNormal = glm::normalize(normal);
    return l;
}

vec3 direction(float cosTheta, float phi) { return wf::test::sphereDirection(cosTheta, phi); }

struct Case {
    std::string name;
    BsdfParams m;
    BsdfLayers l;
    vec3 wo;
};

std::vector<Case> cases() {
    const vec3 red(0.8f, 0.2f, 0.1f);
    const vec3 tilt(0.45f, -0.2f, 1.0f); // ~26 degrees off the base's normal
    return {
        {"TiltedCoatOverPlastic", base(red, 0.0f, 0.6f), coat(0.2f, tilt), direction(0.75f, 0.7f)},
        {"TiltedCoatTowardsWo", base(red, 0.0f, 0.6f), coat(0.3f, vec3(0.5f, 0.0f, 1.0f)),
         direction(0.5f, 0.0f)},
        {"TiltedCoatGrazing", base(red, 1.0f, 0.5f), coat(0.3f, tilt), direction(0.2f, 3.0f)},
        {"TiltedCoatOverGlassLeaving", base(vec3(1.0f), 0.0f, 0.3f, 1.0f, 1.0f),
         coat(0.2f, tilt), direction(-0.8f, 1.1f)},
    };
}

constexpr int CHI2_SAMPLES = 300000;

std::vector<double> histogram(const Case& c, const wf::test::SphereGrid& grid, unsigned seed) {
    auto sample = [&](float uLobe, vec2 u, vec3& wi) {
        BsdfSample s;
        const bool sampled = layeredSample(c.m, c.l, c.wo, uLobe, u, s) && !s.isDelta;
        wi = s.wi;
        return sampled;
    };
    return wf::test::sampleHistogram(grid, seed, CHI2_SAMPLES, sample);
}

double pdfFit(const Case& c, const std::vector<double>& counts, const wf::test::SphereGrid& grid,
              const BsdfLayers& pdfLayers) {
    auto pdf = [&](vec3 wi) { return double(layeredPdf(c.m, pdfLayers, c.wo, wi)); };
    return wf::test::pdfFitPValue(counts, grid, CHI2_SAMPLES, pdf);
}

TEST(CoatNormal, SampledDirectionsFollowThePdf) {
    wf::test::SphereGrid grid;
    for (const Case& c : cases()) {
        std::vector<double> counts = histogram(c, grid, 20261207u);
        EXPECT_GT(pdfFit(c, counts, grid, c.l), 1e-3) << c.name;
    }
    // The test's teeth: the same samples against the untilted coat's pdf.
    const Case c = cases()[0];
    EXPECT_LT(pdfFit(c, histogram(c, grid, 5u), grid, coat(0.2f, vec3(0, 0, 1))), 1e-3);
}

TEST(CoatNormal, SampleWeightIsEvalCosOverPdf) {
    for (const Case& c : cases()) {
        std::mt19937 rng(12u);
        int nonDelta = 0;
        for (int i = 0; i < 4000; ++i) {
            BsdfSample s;
            if (!layeredSample(c.m, c.l, c.wo, uniform01(rng),
                               vec2(uniform01(rng), uniform01(rng)), s) ||
                s.isDelta)
                continue;
            ++nonDelta;
            const float pdf = layeredPdf(c.m, c.l, c.wo, s.wi);
            const vec3 expected = layeredEval(c.m, c.l, c.wo, s.wi) * std::abs(s.wi.z) / pdf;
            ASSERT_GT(pdf, 0.0f) << c.name;
            EXPECT_NEAR(s.pdf, pdf, 1e-5f * pdf) << c.name;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(s.weight[k], expected[k], 1e-4f * expected[k] + 1e-7f) << c.name;
        }
        EXPECT_GT(nonDelta, 1000) << c.name;
    }
}

// A smooth tilted coat over a black Lambert base: a Dirac mirror about the coat's normal, of
// weight Schlick(0.04, wo . n_coat) / its probability.
TEST(CoatNormal, SmoothTiltedCoatMirrorsAboutItsOwnNormal) {
    const BsdfParams black = base(vec3(0.0f), 0.0f, 1.0f, 0.0f);
    const vec3 n = glm::normalize(vec3(0.3f, 0.1f, 1.0f));
    const vec3 wo = direction(0.8f, 0.4f);
    BsdfSample s;
    ASSERT_TRUE(layeredSample(black, coat(0.0f, n), wo, 0.3f, vec2(0.5f), s));
    EXPECT_TRUE(s.isDelta);
    const vec3 mirror = 2.0f * glm::dot(wo, n) * n - wo;
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(s.wi[k], mirror[k], 1e-5f) << k;
    const float fresnel = 0.04f + 0.96f * std::pow(1.0f - glm::dot(wo, n), 5.0f);
    EXPECT_NEAR(s.weight.x * s.pdf, fresnel, 1e-5f);
}

// Sample-weight albedo (an unbiased estimate of the integral of f |cos|), with its error.
vec3 albedo(const BsdfParams& m, const BsdfLayers& l, vec3 wo, int n, vec3* err) {
    std::mt19937 rng(3u);
    glm::dvec3 sum(0.0), sum2(0.0);
    for (int i = 0; i < n; ++i) {
        BsdfSample s;
        if (layeredSample(m, l, wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s)) {
            const glm::dvec3 w = glm::dvec3(s.weight) * double(s.eta * s.eta);
            sum += w;
            sum2 += w * w;
        }
    }
    const glm::dvec3 mean = sum / double(n);
    *err = vec3(glm::sqrt(glm::max(sum2 / double(n) - mean * mean, 0.0) / double(n)));
    return vec3(mean);
}

// Tilted coats at full strength over white bases reflect at most everything, at every angle.
TEST(CoatNormal, WhiteFurnaceAlbedoAtMostOne) {
    const vec3 white(1.0f);
    int checked = 0;
    for (float r : {0.0f, 0.1f, 0.4f, 1.0f})
        for (vec3 tilt : {vec3(0.6f, 0.0f, 1.0f), vec3(-0.3f, 0.9f, 1.0f)})
            for (const BsdfParams& m : {base(white, 0, 1, 0), base(white, 0, 0.3f),
                                        base(white, 1, 0.2f)})
                for (float cosTheta : {1.0f, 0.6f, 0.25f, 0.05f}) {
                    vec3 err;
                    const vec3 a = albedo(m, coat(r, tilt), direction(cosTheta, 0.3f), 20000,
                                          &err);
                    for (int k = 0; k < 3; ++k)
                        EXPECT_LE(a[k], 1.0f + 4.0f * err[k] + 3e-3f)
                            << "roughness " << r << " cos " << cosTheta;
                    ++checked;
                }
    EXPECT_EQ(checked, 96);
}

// Over a black base, a tilted coat reflects what a flat coat reflects at the angle wo makes
// with the coat's normal (the coat's own cosine, not the base's; nothing is lost below the
// base's horizon for these angles).
TEST(CoatNormal, TiltedCoatReflectsAsAFlatCoatAtItsOwnAngle) {
    const BsdfParams black = base(vec3(0.0f), 0.0f, 1.0f, 0.0f);
    const vec3 n = glm::normalize(vec3(0.45f, -0.2f, 1.0f));
    vec3 t, b;
    buildOrthonormalBasis(n, t, b);
    for (float cosCoat : {0.95f, 0.7f}) {
        const float sinCoat = std::sqrt(1.0f - cosCoat * cosCoat);
        const vec3 wo = n * cosCoat + t * sinCoat; // tilted further from the base's normal
        vec3 errTilted, errFlat;
        const vec3 tilted = albedo(black, coat(0.15f, n), wo, 40000, &errTilted);
        const vec3 flat = albedo(black, coat(0.15f, vec3(0, 0, 1)), direction(cosCoat, 0.0f),
                                 40000, &errFlat);
        EXPECT_NEAR(tilted.x, flat.x, 4.0f * (errTilted.x + errFlat.x) + 1e-3f)
            << "cos to the coat " << cosCoat;
        EXPECT_GT(flat.x, 0.03f);
    }
}

} // namespace
