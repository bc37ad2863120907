// KHR_materials_diffuse_transmission on the CPU (shaders/bsdf/bsdf.h's split diffuse base,
// exactly as the shade pass runs it): samples on both sides against the pdf (chi-square, the
// helpers of tests/unit/chi_square.h), sample weights against eval / pdf, the lobe's symmetry
// (no eta: f(a, b) = f(b, a) across the surface too), the analytic Lambert split, the white
// furnace (exactly 1 for a lossless white split, at most 1 under the specular layer), and
// factor 0 against the BSDF built without the switch (bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "shaders/bsdf/bsdf.h"
#include "tests/unit/chi_square.h"
#include "tests/unit/isotropic_bsdf.h"

namespace {

using glm::dvec3;
using glm::vec2;
using glm::vec3;
using wf::test::uniform01;
using namespace wf::gpu_types;

constexpr float TWO_PI = 6.2831853f;
constexpr float INV_PI = 0.31830988618f;

vec3 direction(float cosTheta, float phi) {
    return wf::test::sphereDirection(cosTheta, phi);
}

BsdfParams material(vec3 baseColor, float roughness, float specular, float dt, vec3 dtColor,
                    float metallic = 0.0f, float transmission = 0.0f) {
    BsdfParams m{baseColor, metallic, roughness, 1.5f, transmission, specular, vec3(1.0f)};
    m.diffuseTransmission = dt;
    m.diffuseTransmissionColor = dtColor;
    return m;
}

struct Case {
    std::string name;
    BsdfParams m;
    vec3 wo;
};

// A leaf, a lamp shade, paper; seen from either side (opaque: mirrored); beside refraction
// and metal; a black base that only transmits.
std::vector<Case> cases() {
    const vec3 leaf(0.2f, 0.5f, 0.1f), green(0.4f, 0.9f, 0.2f);
    return {
        {"LeafFront", material(leaf, 0.5f, 1.0f, 0.5f, green), direction(0.7f, 0.3f)},
        {"LeafBack", material(leaf, 0.5f, 1.0f, 0.5f, green), direction(-0.6f, 2.0f)},
        {"LambertSplit", material(vec3(1.0f), 1.0f, 0.0f, 0.3f, vec3(1.0f)),
         direction(0.4f, 1.0f)},
        {"SmoothLayerGrazing", material(vec3(0.8f), 0.0f, 1.0f, 0.8f, vec3(0.9f, 0.7f, 0.5f)),
         direction(0.15f, 4.0f)},
        {"OnlyTransmits", material(vec3(0.0f), 0.3f, 1.0f, 1.0f, vec3(0.8f)),
         direction(0.8f, 5.0f)},
        {"WithRoughGlass", material(vec3(0.9f), 0.4f, 1.0f, 0.6f, vec3(0.7f), 0.0f, 0.5f),
         direction(0.65f, 0.5f)},
        {"WithRoughGlassInside", material(vec3(0.9f), 0.4f, 1.0f, 0.6f, vec3(0.7f), 0.0f, 0.5f),
         direction(-0.75f, 2.5f)},
        {"WithMetal", material(vec3(0.9f, 0.6f, 0.3f), 0.3f, 1.0f, 0.4f, vec3(1.0f), 0.4f),
         direction(0.5f, 3.0f)},
    };
}

constexpr int BSDF_SAMPLES = 300000;

TEST(DiffuseTransmissionBsdf, SampledDirectionsFollowBsdfPdf) {
    wf::test::SphereGrid grid;
    unsigned seed = 201u;
    for (const Case& c : cases()) {
        int below = 0;
        auto sample = [&](float uLobe, vec2 u, vec3& wi) {
            BsdfSample s;
            const bool sampled = bsdfSample(c.m, c.wo, uLobe, u, s) && !s.isDelta;
            wi = s.wi;
            below += sampled && wi.z * c.wo.z < 0.0f;
            return sampled;
        };
        std::vector<double> counts =
            wf::test::sampleHistogram(grid, seed++, BSDF_SAMPLES, sample);
        auto pdf = [&](vec3 wi) { return double(bsdfPdf(c.m, c.wo, wi)); };
        EXPECT_GT(wf::test::pdfFitPValue(counts, grid, BSDF_SAMPLES, pdf), 1e-3) << c.name;
        EXPECT_GT(below, BSDF_SAMPLES / 20) << c.name; // the other side is sampled
    }
}

TEST(DiffuseTransmissionBsdf, SampleWeightIsEvalCosOverPdf) {
    for (const Case& c : cases()) {
        ASSERT_TRUE(bsdfHasNonDelta(c.m)) << c.name;
        std::mt19937 rng(22u);
        int checked = 0;
        for (int i = 0; i < 4000; ++i) {
            BsdfSample s;
            if (!bsdfSample(c.m, c.wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s) ||
                s.isDelta)
                continue;
            ++checked;
            const float pdf = bsdfPdf(c.m, c.wo, s.wi);
            const vec3 expected = bsdfEval(c.m, c.wo, s.wi) * std::abs(s.wi.z) / pdf;
            ASSERT_GT(pdf, 0.0f) << c.name;
            EXPECT_NEAR(s.pdf, pdf, 1e-5f * pdf) << c.name;
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(s.weight[k], expected[k], 1e-4f * expected[k] + 1e-7f) << c.name;
        }
        EXPECT_GT(checked, 1000) << c.name;
    }
}

// Without refraction, every lobe is symmetric: f(a, b) = f(b, a), on one side and across.
TEST(DiffuseTransmissionBsdf, LobeIsSymmetricAcrossTheSurface) {
    std::mt19937 rng(8u);
    for (const Case& c : cases()) {
        if (c.m.transmission > 0.0f)
            continue; // refraction carries 1 / eta^2 (test_bsdf.cpp)
        int across = 0;
        for (int i = 0; i < 4000; ++i) {
            const vec3 a = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
            const vec3 b = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
            const vec3 fab = bsdfEval(c.m, a, b), fba = bsdfEval(c.m, b, a);
            across += a.z * b.z < 0.0f && fab.x > 0.0f;
            for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(fba[k], fab[k], 1e-4f * fab[k] + 1e-7f) << c.name << " " << i;
        }
        EXPECT_GT(across, 1000) << c.name;
    }
}

// Without the specular layer the split is the spec's mix of two Lambert lobes, exactly:
// (1 - dt) baseColor / pi on wo's side and dt colour / pi on the other.
TEST(DiffuseTransmissionBsdf, WithoutTheLayerItIsTwoLambertLobes) {
    const vec3 base(0.6f, 0.4f, 0.2f), colour(0.3f, 0.9f, 0.5f);
    const BsdfParams m = material(base, 0.7f, 0.0f, 0.35f, colour);
    std::mt19937 rng(3u);
    for (int i = 0; i < 1000; ++i) {
        const vec3 wo = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
        const vec3 wi = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
        const vec3 expected = wo.z * wi.z > 0.0f ? 0.65f * base * INV_PI : 0.35f * colour * INV_PI;
        const vec3 f = bsdfEval(m, wo, wi);
        for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(f[k], expected[k], 1e-6f) << i;
    }
}

// Directional albedo by sampling, split into what stays on wo's side and what crosses.
struct Albedo {
    dvec3 reflected{0.0}, transmitted{0.0}, stdError{0.0};
    dvec3 total() const { return reflected + transmitted; }
};

Albedo albedo(const BsdfParams& m, vec3 wo, int n, unsigned seed) {
    std::mt19937 rng(seed);
    Albedo a;
    dvec3 sum2(0.0);
    for (int i = 0; i < n; ++i) {
        BsdfSample s;
        if (bsdfSample(m, wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s)) {
            const dvec3 w = dvec3(s.weight) * double(s.eta * s.eta);
            (s.wi.z * wo.z > 0.0f ? a.reflected : a.transmitted) += w;
            sum2 += w * w;
        }
    }
    a.reflected /= double(n);
    a.transmitted /= double(n);
    const dvec3 mean = a.total();
    a.stdError = glm::sqrt(glm::max(sum2 / double(n) - mean * mean, 0.0) / double(n));
    return a;
}

// A white Lambert base without the layer, split in half, loses nothing: every sample's weight
// is 1, half of them cross (the analytic albedo: 1 - dt reflected, dt transmitted).
TEST(DiffuseTransmissionBsdf, WhiteLosslessSplitConservesEnergyExactly) {
    for (float dt : {0.5f, 0.2f, 1.0f}) {
        const BsdfParams m = material(vec3(1.0f), 0.5f, 0.0f, dt, vec3(1.0f));
        unsigned seed = 5u;
        for (float cosTheta : {1.0f, 0.6f, 0.1f, -0.4f}) {
            const Albedo a = albedo(m, direction(cosTheta, 0.7f), 200000, seed++);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(a.total()[k], 1.0, 1e-5) << dt << " " << cosTheta;
                EXPECT_NEAR(a.transmitted[k], dt, 5e-3) << dt << " " << cosTheta;
                EXPECT_NEAR(a.reflected[k], 1.0 - dt, 5e-3) << dt << " " << cosTheta;
            }
        }
    }
}

// Under the specular layer (and a coloured split, metal, rough glass) nothing gains energy.
TEST(DiffuseTransmissionBsdf, WhiteFurnaceAtMostOne) {
    const std::vector<BsdfParams> whites = {
        material(vec3(1.0f), 0.0f, 1.0f, 0.5f, vec3(1.0f)),
        material(vec3(1.0f), 0.3f, 1.0f, 0.7f, vec3(1.0f)),
        material(vec3(1.0f), 0.6f, 1.0f, 1.0f, vec3(1.0f)),
        material(vec3(1.0f), 1.0f, 1.0f, 0.3f, vec3(1.0f)),
        material(vec3(1.0f), 0.4f, 1.0f, 0.6f, vec3(1.0f), 0.0f, 0.5f),
        material(vec3(1.0f), 0.4f, 1.0f, 0.6f, vec3(1.0f), 0.5f)};
    unsigned seed = 1u;
    double maxSeen = 0.0;
    for (const BsdfParams& m : whites) {
        for (float cosTheta : {1.0f, 0.5f, 0.2f, 0.05f, -0.3f, -0.8f}) {
            const int n = std::abs(cosTheta) < 0.1f ? 40000 : 8000;
            const Albedo a = albedo(m, direction(cosTheta, 0.3f), n, seed++);
            maxSeen = std::max(maxSeen, a.total().x);
            EXPECT_LE(a.total().x, 1.0 + 4.0 * a.stdError.x + 2e-3)
                << "roughness " << m.roughness << " dt " << m.diffuseTransmission
                << " transmission " << m.transmission << " cos " << cosTheta;
            EXPECT_GT(a.transmitted.x, 0.0);
        }
    }
    EXPECT_GT(maxSeen, 0.9); // the furnace measured something
}

using wf::test::sameBits;

// Factor 0 (whatever the colour) is the BSDF that scenes without the extension compile, bit for
// bit, for random materials of every kind, directions on both sides and the same numbers.
TEST(DiffuseTransmissionBsdf, FactorZeroIsThePlainBsdfBitForBit) {
    std::mt19937 rng(17u);
    for (int i = 0; i < 20000; ++i) {
        const wf::test::PlainMaterial plain{
            vec3(uniform01(rng), uniform01(rng), uniform01(rng)),
            i % 3 == 0 ? 0.0f : uniform01(rng),
            i % 7 == 0 ? 0.0f : uniform01(rng),
            i % 11 == 0 ? 1.0f : 1.0f + uniform01(rng),
            i % 2 == 0 ? uniform01(rng) : 0.0f,
            i % 5 == 0 ? 0.0f : uniform01(rng),
            vec3(1.0f, uniform01(rng), 2.0f * uniform01(rng))};
        BsdfParams m = {plain.baseColor, plain.metallic, plain.roughness, plain.ior,
                        plain.transmission, plain.specular, plain.specularColor};
        m.diffuseTransmissionColor = vec3(uniform01(rng), uniform01(rng), uniform01(rng));
        ASSERT_EQ(m.diffuseTransmission, 0.0f);
        const vec3 wo = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
        const vec3 wi = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
        const float uLobe = uniform01(rng);
        const vec2 u(uniform01(rng), uniform01(rng));
        ASSERT_TRUE((wf::test::matchesPlainBsdf<BsdfParams, BsdfSample>(m, plain, wo, wi, uLobe,
                                                                        u)))
            << i;
    }
}

// A black base that transmits has a density (NEE reaches it) and is not a Dirac BSDF; the
// transmitted lobe's samples cross with eta 1 (nothing for the adjoint to correct).
TEST(DiffuseTransmissionBsdf, TransmittingOnlyBaseHasADensityAndNoEta) {
    const BsdfParams m = material(vec3(0.0f), 0.0f, 0.0f, 1.0f, vec3(0.5f));
    EXPECT_TRUE(bsdfHasNonDelta(m));
    EXPECT_FALSE(bsdfIsPureDelta(m));
    std::mt19937 rng(4u);
    for (int i = 0; i < 100; ++i) {
        BsdfSample s;
        ASSERT_TRUE(bsdfSample(m, direction(0.5f, 1.0f), uniform01(rng),
                               vec2(uniform01(rng), uniform01(rng)), s));
        EXPECT_LT(s.wi.z, 0.0f);
        EXPECT_EQ(s.eta, 1.0f);
        EXPECT_FALSE(s.isDelta);
    }
}

} // namespace
