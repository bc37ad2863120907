// Tests of the clearcoat and sheen layers (shaders/bsdf/bsdf_layers.h, sheen.h) on the CPU,
// as the shade pass runs them: sampled directions against layeredPdf (chi-square over the
// sphere), weights against eval / pdf, reciprocity, white furnaces at full strength over white
// bases, the tabulated sheen albedo bound against quadrature, and no layer = the base exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "shaders/bsdf/bsdf_layers.h"
#include "tests/unit/chi_square.h"

namespace {

using wf::test::uniform01;

using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;

BsdfParams base(vec3 color, float metallic, float roughness, float specular = 1.0f,
                float transmission = 0.0f, float ior = 1.5f) {
    return BsdfParams{color, metallic, roughness, ior, transmission, specular, vec3(1.0f)};
}

BsdfLayers layers(float coat, float coatRoughness, vec3 sheen = vec3(0.0f),
                  float sheenRoughness = 0.5f) {
    return BsdfLayers{coat, coatRoughness, sheen, sheenRoughness};
}

vec3 direction(float cosTheta, float phi) { return wf::test::sphereDirection(cosTheta, phi); }

struct Case {
    std::string name;
    BsdfParams m;
    BsdfLayers l;
    vec3 wo;
};

std::vector<Case> cases() {
    const vec3 red(0.8f, 0.2f, 0.1f), gold(1.0f, 0.78f, 0.34f), velvet(0.9f, 0.3f, 0.6f);
    const vec3 wo = direction(0.75f, 0.7f), grazing = direction(0.15f, 2.0f);
    return {
        {"CoatOverPlastic", base(red, 0.0f, 0.6f), layers(1.0f, 0.2f), wo},
        {"CoatOverPlasticGrazing", base(red, 0.0f, 0.6f), layers(0.7f, 0.3f), grazing},
        {"CoatOverMetal", base(gold, 1.0f, 0.4f), layers(1.0f, 0.05f), wo},
        {"SmoothCoatOverRoughBase", base(red, 0.0f, 0.5f), layers(1.0f, 0.0f), wo},
        {"SheenOverLambert", base(red, 0.0f, 1.0f, 0.0f), layers(0.0f, 0.0f, velvet, 0.5f), wo},
        {"SheenSmoothGrazing", base(red, 0.0f, 1.0f, 0.0f), layers(0.0f, 0.0f, vec3(1.0f), 0.1f),
         grazing},
        {"SheenRough", base(red, 0.0f, 0.8f), layers(0.0f, 0.0f, vec3(0.5f), 1.0f), wo},
        {"CoatAndSheen", base(red, 0.0f, 0.5f), layers(0.8f, 0.25f, velvet, 0.3f), wo},
        {"CoatOverRoughGlassEntering", base(vec3(1.0f), 0.0f, 0.3f, 1.0f, 1.0f),
         layers(1.0f, 0.2f), wo},
        {"CoatOverRoughGlassLeaving", base(vec3(1.0f), 0.0f, 0.3f, 1.0f, 1.0f),
         layers(1.0f, 0.2f), direction(-0.85f, 1.1f)},
    };
}

constexpr int CHI2_SAMPLES = 300000;

std::vector<double> sampleHistogram(const Case& c, const wf::test::SphereGrid& grid,
                                    unsigned seed) {
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

TEST(BsdfLayers, SampledDirectionsFollowLayeredPdf) {
    wf::test::SphereGrid grid;
    for (const Case& c : cases()) {
        std::vector<double> counts = sampleHistogram(c, grid, 20261202u);
        EXPECT_GT(pdfFit(c, counts, grid, c.l), 1e-3) << c.name;
    }
}

TEST(BsdfLayers, ChiSquareRejectsWrongLayerPdf) {
    wf::test::SphereGrid grid;
    Case coat = cases()[0];
    std::vector<double> counts = sampleHistogram(coat, grid, 8u);
    BsdfLayers rougher = coat.l;
    rougher.clearcoatRoughness = 0.22f; // a 10% error in the coat's roughness
    EXPECT_LT(pdfFit(coat, counts, grid, rougher), 1e-3);
    // Grazing, where the sheen takes a large share from a glossy base.
    Case sheen{"SheenOverGloss", base(vec3(0.8f, 0.2f, 0.1f), 0.0f, 0.3f),
               layers(0.0f, 0.0f, vec3(1.0f), 0.3f), direction(0.15f, 2.0f)};
    counts = sampleHistogram(sheen, grid, 9u);
    BsdfLayers paler = sheen.l;
    paler.sheenColor *= 0.5f; // wrong lobe mixture
    EXPECT_LT(pdfFit(sheen, counts, grid, paler), 1e-3);
}

TEST(BsdfLayers, SampleWeightIsEvalCosOverPdf) {
    for (const Case& c : cases()) {
        std::mt19937 rng(12u);
        int nonDelta = 0;
        for (int i = 0; i < 4000; ++i) {
            BsdfSample s;
            if (!layeredSample(c.m, c.l, c.wo, uniform01(rng), vec2(uniform01(rng),
                               uniform01(rng)), s) || s.isDelta) {
                continue;
            }
            ++nonDelta;
            float pdf = layeredPdf(c.m, c.l, c.wo, s.wi);
            vec3 expected = layeredEval(c.m, c.l, c.wo, s.wi) * std::abs(s.wi.z) / pdf;
            ASSERT_GT(pdf, 0.0f) << c.name;
            EXPECT_NEAR(s.pdf, pdf, 1e-5f * pdf) << c.name;
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(s.weight[k], expected[k], 1e-4f * expected[k] + 1e-7f) << c.name;
            }
            bool refracted = s.wi.z * c.wo.z < 0.0f;
            float eta = refracted ? (c.wo.z > 0.0f ? c.m.ior : 1.0f / c.m.ior) : 1.0f;
            EXPECT_FLOAT_EQ(s.eta, eta) << c.name;
        }
        EXPECT_GT(nonDelta, 1000) << c.name;
    }
}

TEST(BsdfLayers, ReflectionIsReciprocal) {
    std::mt19937 rng(5u);
    for (const Case& c : cases()) {
        for (int i = 0; i < 2000; ++i) {
            vec3 a = direction(uniform01(rng), 6.2831853f * uniform01(rng));
            vec3 b = direction(uniform01(rng), 6.2831853f * uniform01(rng));
            float side = c.wo.z < 0.0f ? -1.0f : 1.0f;
            a.z *= side;
            b.z *= side;
            vec3 fab = layeredEval(c.m, c.l, a, b), fba = layeredEval(c.m, c.l, b, a);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(fab[k], fba[k], 2e-4f * std::max(fab[k], fba[k]) + 1e-7f) << c.name;
            }
        }
    }
}

// Through a coated glass: f(wi, wo) = eta^2 f(wo, wi), as for the bare base (test_bsdf.cpp).
TEST(BsdfLayers, RefractionThroughACoatIsReciprocalUpToEtaSquared) {
    std::mt19937 rng(6u);
    BsdfParams glass = base(vec3(0.9f, 0.8f, 1.0f), 0.0f, 0.4f, 1.0f, 1.0f, 1.5f);
    BsdfLayers coat = layers(1.0f, 0.3f, vec3(0.3f), 0.5f);
    int compared = 0;
    for (int i = 0; i < 20000; ++i) {
        vec3 out = direction(uniform01(rng), 6.2831853f * uniform01(rng));
        vec3 in = direction(-uniform01(rng), 6.2831853f * uniform01(rng));
        vec3 fOutIn = layeredEval(glass, coat, out, in), fInOut = layeredEval(glass, coat, in, out);
        if (fOutIn.x <= 0.0f && fInOut.x <= 0.0f) {
            continue;
        }
        ++compared;
        for (int k = 0; k < 3; ++k) {
            float expected = 1.5f * 1.5f * fOutIn[k];
            EXPECT_NEAR(fInOut[k], expected, 1e-3f * expected + 1e-7f);
        }
    }
    EXPECT_GT(compared, 500);
}

// Mean sample weight (times eta^2: energy, not radiance), with its standard error.
vec3 albedo(const BsdfParams& m, const BsdfLayers& l, vec3 wo, int n, unsigned seed, vec3* err) {
    std::mt19937 rng(seed);
    glm::dvec3 sum(0.0), sum2(0.0);
    for (int i = 0; i < n; ++i) {
        BsdfSample s;
        if (layeredSample(m, l, wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s)) {
            glm::dvec3 w = glm::dvec3(s.weight) * double(s.eta * s.eta);
            sum += w;
            sum2 += w * w;
        }
    }
    glm::dvec3 mean = sum / double(n);
    *err = vec3(glm::sqrt(glm::max(sum2 / double(n) - mean * mean, 0.0) / double(n)));
    return vec3(mean);
}

// White furnace: coat and sheen at full strength over white bases reflect at most everything,
// at every angle down to grazing, for every roughness.
TEST(BsdfLayers, WhiteFurnaceAlbedoAtMostOne) {
    const vec3 white(1.0f);
    std::vector<std::pair<std::string, std::pair<BsdfParams, BsdfLayers>>> table;
    for (float r : {0.0f, 0.05f, 0.3f, 0.7f, 1.0f}) {
        const std::string tag = std::to_string(r);
        table.push_back({"CoatOverWhiteLambert" + tag, {base(white, 0, 1, 0), layers(1, r)}});
        table.push_back({"CoatOverWhiteDielectric" + tag, {base(white, 0, 0.4f), layers(1, r)}});
        table.push_back({"CoatOverMirror" + tag, {base(white, 1, 0), layers(1, r)}});
    }
    for (float r : {0.0f, 0.1f, 0.3f, 0.6f, 1.0f}) {
        const std::string tag = std::to_string(r);
        table.push_back({"SheenOverWhiteLambert" + tag,
                         {base(white, 0, 1, 0), layers(0, 0, white, r)}});
        table.push_back({"CoatAndSheenOverWhite" + tag,
                         {base(white, 0, 0.5f), layers(1, 0.2f, white, r)}});
    }
    table.push_back({"CoatOverWhiteGlass", {base(white, 0, 0.2f, 1, 1), layers(1, 0.1f)}});
    for (const auto& [name, material] : table) {
        bool transmissive = material.first.transmission > 0.0f;
        for (float cosTheta : {1.0f, 0.7f, 0.4f, 0.15f, 0.05f, 0.01f, -0.3f, -0.9f}) {
            if (cosTheta < 0.0f && !transmissive) {
                continue;
            }
            vec3 err;
            vec3 a = albedo(material.first, material.second, direction(cosTheta, 0.3f), 20000,
                            3u, &err);
            for (int k = 0; k < 3; ++k) {
                EXPECT_LE(a[k], 1.0f + 4.0f * err[k] + 3e-3f) << name << " cos " << cosTheta;
            }
        }
    }
}

// Without layers the layered calls are the base BSDF: same eval and pdf, same samples.
TEST(BsdfLayers, NoLayerIsTheBaseExactly) {
    std::mt19937 rng(22u);
    const BsdfLayers none = layers(0.0f, 0.3f);
    for (int i = 0; i < 2000; ++i) {
        BsdfParams m = base(vec3(uniform01(rng), uniform01(rng), uniform01(rng)),
                            i % 3 == 0 ? 1.0f : 0.0f, uniform01(rng), 1.0f,
                            i % 4 == 0 ? 1.0f : 0.0f);
        vec3 wo = direction(2.0f * uniform01(rng) - 1.0f, 6.2831853f * uniform01(rng));
        vec3 wi = direction(2.0f * uniform01(rng) - 1.0f, 6.2831853f * uniform01(rng));
        ASSERT_EQ(layeredEval(m, none, wo, wi), bsdfEval(m, wo, wi)) << i;
        ASSERT_EQ(layeredPdf(m, none, wo, wi), bsdfPdf(m, wo, wi)) << i;
        float uLobe = uniform01(rng);
        vec2 u(uniform01(rng), uniform01(rng));
        BsdfSample a, b;
        bool sampled = bsdfSample(m, wo, uLobe, u, a);
        ASSERT_EQ(layeredSample(m, none, wo, uLobe, u, b), sampled) << i;
        if (sampled) {
            ASSERT_EQ(a.wi, b.wi) << i;
            ASSERT_EQ(a.isDelta, b.isDelta) << i;
            ASSERT_NEAR(a.pdf, b.pdf, 1e-5f * a.pdf) << i;
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(a.weight[k], b.weight[k], 1e-4f * a.weight[k] + 1e-7f) << i;
        }
    }
}

// A smooth coat is a Dirac mirror of weight c Schlick(0.04, cos) / its probability.
TEST(BsdfLayers, SmoothCoatIsAMirror) {
    BsdfParams black = base(vec3(0.0f), 0.0f, 1.0f, 0.0f);
    BsdfLayers coat = layers(1.0f, 0.0f);
    EXPECT_FALSE(layeredHasNonDelta(black, coat));
    vec3 wo = direction(0.5f, 0.4f);
    BsdfSample s;
    ASSERT_TRUE(layeredSample(black, coat, wo, 0.3f, vec2(0.5f), s));
    EXPECT_TRUE(s.isDelta);
    EXPECT_NEAR(s.wi.x, -wo.x, 1e-6f);
    EXPECT_NEAR(s.wi.z, wo.z, 1e-6f);
    float fresnel = 0.04f + 0.96f * std::pow(0.5f, 5.0f);
    EXPECT_NEAR(s.weight.x * s.pdf, fresnel, 1e-5f);
    EXPECT_TRUE(layeredHasNonDelta(black, layers(1.0f, 0.1f)));
    EXPECT_TRUE(layeredHasNonDelta(black, layers(0.0f, 0.0f, vec3(0.2f))));
}

// The sheen albedo table bounds the lobe's albedo (quadrature, away from the table's nodes).
TEST(BsdfLayers, SheenAlbedoBoundHoldsAboveQuadrature) {
    std::mt19937 rng(31u);
    const int n = 256;
    int checked = 0;
    for (int t = 0; t < 30; ++t) {
        float r = WF_SHEEN_MIN_ROUGHNESS + (1.0f - WF_SHEEN_MIN_ROUGHNESS) * uniform01(rng);
        float x = uniform01(rng);
        float mu = std::max(x * x, 1e-4f);
        float alpha = sheenAlpha(r);
        vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            float c = (i + 0.5f) / n, s = std::sqrt(1.0f - c * c);
            for (int j = 0; j < 2 * n; ++j) {
                float phi = 2.0f * WF_PI * (j + 0.5f) / (2 * n);
                sum += sheenLobe(alpha, wo, vec3(s * std::cos(phi), s * std::sin(phi), c)) * c;
            }
        }
        double quadrature = sum * 2.0 * M_PI / (double(n) * 2 * n);
        float bound = sheenAlbedoBound(r, mu);
        EXPECT_GE(bound, quadrature) << "roughness " << r << " mu " << mu;
        EXPECT_LE(bound, 1.25 * quadrature + 0.06) << "loose at roughness " << r << " mu " << mu;
        ++checked;
    }
    EXPECT_EQ(checked, 30);
}

TEST(BsdfLayers, NeverNanOrInf) {
    std::mt19937 rng(41u);
    for (int i = 0; i < 20000; ++i) {
        BsdfParams m = base(vec3(uniform01(rng)), uniform01(rng),
                            i % 5 == 0 ? 0.0f : uniform01(rng),
                            uniform01(rng), i % 2 ? 1.0f : 0.0f);
        BsdfLayers l = layers(uniform01(rng), i % 7 == 0 ? 0.0f : uniform01(rng),
                              vec3(uniform01(rng)), i % 3 == 0 ? 0.0f : uniform01(rng));
        float c = i % 11 == 0 ? 1e-7f : 2.0f * uniform01(rng) - 1.0f;
        vec3 wo = direction(c, 6.2831853f * uniform01(rng));
        vec3 wi = direction(2.0f * uniform01(rng) - 1.0f, 6.2831853f * uniform01(rng));
        vec3 f = layeredEval(m, l, wo, wi);
        float pdf = layeredPdf(m, l, wo, wi);
        ASSERT_TRUE(bsdfFinite(f) && std::isfinite(pdf) && pdf >= 0.0f) << i;
        BsdfSample s;
        if (layeredSample(m, l, wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s)) {
            ASSERT_TRUE(bsdfFinite(s.weight) && std::isfinite(s.pdf) && s.pdf > 0.0f) << i;
        }
    }
}

} // namespace
