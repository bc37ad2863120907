// KHR_materials_anisotropy on the CPU (shaders/bsdf/anisotropy.h and bsdf.h's lobes, exactly as
// the shade pass runs them): D's normalisation and Lambda's agreement with D (quadrature), G2's
// symmetry, the visible normals and the BSDF's samples against their pdfs (chi-square, with
// the helpers of tests/unit/chi_square.h), sample weights against eval / pdf, reciprocity,
// strength 0 against the BSDF built without the switch (bit for bit), and the white furnace.
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

vec3 direction(float cosTheta, float phi) {
    return wf::test::sphereDirection(cosTheta, phi);
}

BsdfParams material(vec3 baseColor, float metallic, float roughness, float anisotropy,
                    float transmission = 0.0f, float ior = 1.5f) {
    BsdfParams m{baseColor, metallic, roughness, ior, transmission, 1.0f, vec3(1.0f)};
    m.anisotropy = anisotropy;
    return m;
}

// Integral over the sphere of f(direction), by chi_square.h's adaptive cells.
double integrate(const std::function<double(vec3)>& f, double tolerance) {
    wf::test::SphereGrid grid{20, 48};
    double sum = 0.0;
    for (double cell : wf::test::integrateOverCells(grid, f, tolerance))
        sum += cell;
    return sum;
}

const vec2 ALPHAS[] = {vec2(0.6f, 0.1f), vec2(0.08f, 0.35f), vec2(1.0f, 0.3f), vec2(0.25f)};

// D is a density of projected area (integral of D(h) h.z = 1), and Lambda is the one that D
// implies: the visible projected area of the microsurface, integral of max(0, wo.h) D(h), is
// the macro surface's wo.z times 1 + Lambda(wo) (Heitz 2014, eq. 17).
TEST(AnisotropicGgx, DIsNormalisedAndLambdaMatchesIt) {
    for (vec2 alpha : ALPHAS) {
        const double area = integrate([&](vec3 h) { return ggxD(h, alpha) * double(h.z); }, 1e-8);
        EXPECT_NEAR(area, 1.0, 2e-3) << alpha.x << " " << alpha.y;
        for (vec3 wo : {direction(0.8f, 0.3f), direction(0.3f, 1.4f), direction(0.1f, 2.5f)}) {
            const double visible = integrate(
                [&](vec3 h) { return ggxD(h, alpha) * std::max(0.0, double(glm::dot(wo, h))); },
                1e-8);
            const double expected = (1.0 + ggxLambda(wo, alpha)) * wo.z;
            EXPECT_NEAR(visible, expected, 3e-3 * expected)
                << alpha.x << " " << alpha.y << " cos " << wo.z;
        }
    }
}

// Height-correlated Smith: G2 = 1 / (1 + Lambda(wo) + Lambda(wi)), the same both ways round.
TEST(AnisotropicGgx, G2IsSymmetricAndMatchesLambda) {
    std::mt19937 rng(3u);
    for (int i = 0; i < 20000; ++i) {
        const vec2 alpha(0.01f + uniform01(rng), 0.01f + uniform01(rng));
        const vec3 wo = direction(uniform01(rng), TWO_PI * uniform01(rng));
        const vec3 wi = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
        const float g = ggxG2OverCosines(wo, wi, alpha);
        ASSERT_EQ(g, ggxG2OverCosines(wi, wo, alpha)) << i;
        const float lambda = 1.0f + ggxLambda(wo, alpha) + ggxLambda(wi, alpha);
        if (std::abs(wo.z) > 1e-3f && std::abs(wi.z) > 1e-3f)
            ASSERT_NEAR(g * std::abs(wo.z) * std::abs(wi.z), 1.0f / lambda, 2e-5f / lambda) << i;
    }
}

// Visible normals drawn by ggxSampleVisibleNormal follow ggxVisibleNormalPdf.
constexpr int VNDF_SAMPLES = 200000;

std::vector<double> normalHistogram(vec3 wo, vec2 alpha, const wf::test::SphereGrid& grid,
                                    unsigned seed) {
    auto sample = [&](float, vec2 u, vec3& h) {
        h = ggxSampleVisibleNormal(wo, alpha, u);
        return true;
    };
    return wf::test::sampleHistogram(grid, seed, VNDF_SAMPLES, sample);
}

double normalFit(const std::vector<double>& counts, const wf::test::SphereGrid& grid, vec3 wo,
                 vec2 pdfAlpha) {
    auto pdf = [&](vec3 h) { return double(ggxVisibleNormalPdf(wo, h, pdfAlpha)); };
    return wf::test::pdfFitPValue(counts, grid, VNDF_SAMPLES, pdf);
}

TEST(AnisotropicGgx, VisibleNormalsFollowTheirPdf) {
    wf::test::SphereGrid grid;
    unsigned seed = 11u;
    for (vec2 alpha : ALPHAS)
        for (vec3 wo : {direction(0.9f, 0.3f), direction(0.4f, 1.7f), direction(0.12f, 0.8f)}) {
            std::vector<double> counts = normalHistogram(wo, alpha, grid, seed++);
            EXPECT_GT(normalFit(counts, grid, wo, alpha), 1e-3)
                << alpha.x << " " << alpha.y << " cos " << wo.z;
        }
}

// The test has teeth: the same samples against the lobe turned by 90 degrees, or 10% wider
// along the tangent, are rejected.
TEST(AnisotropicGgx, ChiSquareRejectsATurnedOrWiderLobe) {
    wf::test::SphereGrid grid;
    const vec3 wo = direction(0.6f, 0.9f);
    const vec2 alpha(0.5f, 0.15f);
    std::vector<double> counts = normalHistogram(wo, alpha, grid, 5u);
    EXPECT_LT(normalFit(counts, grid, wo, vec2(alpha.y, alpha.x)), 1e-3);
    EXPECT_LT(normalFit(counts, grid, wo, vec2(1.1f * alpha.x, alpha.y)), 1e-3);
}

struct Case {
    std::string name;
    BsdfParams m;
    vec3 wo;
};

// The anisotropic lobes: metal, the dielectric layer over diffuse, rough glass from both sides
// (beyond the critical angle too), a mixture; wo along, across and between the axes.
std::vector<Case> cases() {
    const vec3 plastic(0.8f, 0.5f, 0.3f), gold(1.0f, 0.78f, 0.34f);
    return {
        {"Metal0.3Along", material(gold, 1.0f, 0.3f, 0.8f), direction(0.7f, 0.2f)},
        {"Metal0.5Across", material(gold, 1.0f, 0.5f, 1.0f), direction(0.3f, 1.5f)},
        {"Dielectric0.4", material(plastic, 0.0f, 0.4f, 0.9f), direction(0.75f, 0.7f)},
        {"Dielectric0.2Grazing", material(plastic, 0.0f, 0.2f, 0.6f), direction(0.2f, 2.0f)},
        {"RoughGlassEntering", material(vec3(1.0f), 0.0f, 0.3f, 0.7f, 1.0f),
         direction(0.75f, 0.7f)},
        {"RoughGlassLeaving", material(vec3(1.0f), 0.0f, 0.3f, 0.7f, 1.0f),
         direction(-0.85f, 1.1f)},
        {"RoughGlassBeyondCritical", material(vec3(0.9f), 0.0f, 0.3f, 0.5f, 1.0f),
         direction(-0.6f, 2.4f)},
        {"Mixed", material(plastic, 0.3f, 0.35f, 0.8f, 0.4f, 1.33f), direction(0.6f, 4.0f)},
    };
}

constexpr int BSDF_SAMPLES = 300000;

TEST(AnisotropicBsdf, SampledDirectionsFollowBsdfPdf) {
    wf::test::SphereGrid grid;
    unsigned seed = 101u;
    for (const Case& c : cases()) {
        auto sample = [&](float uLobe, vec2 u, vec3& wi) {
            BsdfSample s;
            const bool sampled = bsdfSample(c.m, c.wo, uLobe, u, s) && !s.isDelta;
            wi = s.wi;
            return sampled;
        };
        std::vector<double> counts =
            wf::test::sampleHistogram(grid, seed++, BSDF_SAMPLES, sample);
        auto pdf = [&](vec3 wi) { return double(bsdfPdf(c.m, c.wo, wi)); };
        EXPECT_GT(wf::test::pdfFitPValue(counts, grid, BSDF_SAMPLES, pdf), 1e-3) << c.name;
    }
}

TEST(AnisotropicBsdf, SampleWeightIsEvalCosOverPdf) {
    std::vector<Case> table = cases();
    table.push_back({"SmoothMetalStretched", material(vec3(0.9f), 1.0f, 0.0f, 0.5f),
                     direction(0.6f, 1.0f)});
    for (const Case& c : table) {
        ASSERT_TRUE(bsdfHasNonDelta(c.m)) << c.name;
        std::mt19937 rng(12u);
        int checked = 0;
        for (int i = 0; i < 4000; ++i) {
            BsdfSample s;
            if (!bsdfSample(c.m, c.wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s))
                continue;
            ASSERT_FALSE(s.isDelta) << c.name;
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

TEST(AnisotropicBsdf, ReciprocalUpToEtaSquared) {
    std::mt19937 rng(8u);
    for (const Case& c : cases()) {
        for (int i = 0; i < 4000; ++i) {
            const vec3 a = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
            const vec3 b = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
            const vec3 fab = bsdfEval(c.m, a, b), fba = bsdfEval(c.m, b, a);
            // f(b, a) = eta^2 f(a, b), eta = eta(a's side) / eta(b's side).
            const float eta = a.z * b.z > 0.0f ? 1.0f : (a.z > 0.0f ? 1.0f / c.m.ior : c.m.ior);
            for (int k = 0; k < 3; ++k) {
                const float expected = fab[k] / (eta * eta);
                ASSERT_NEAR(fba[k], expected, 1e-3f * expected + 1e-6f) << c.name << " " << i;
            }
        }
    }
}

using wf::test::sameBits;

// Strength 0 is the isotropic BSDF exactly: the same bits as bsdf.h built without the switch,
// which is what scenes without anisotropy run, for random materials of every kind (roughness
// 0 included), directions on both sides, and samples drawn with the same numbers.
TEST(AnisotropicBsdf, StrengthZeroIsTheIsotropicBsdfBitForBit) {
    std::mt19937 rng(13u);
    for (int i = 0; i < 20000; ++i) {
        const wf::test::PlainMaterial plain{
            vec3(uniform01(rng), uniform01(rng), uniform01(rng)),
            i % 3 == 0 ? 1.0f : uniform01(rng),
            i % 7 == 0 ? 0.0f : uniform01(rng),
            i % 11 == 0 ? 1.0f : 1.0f + uniform01(rng),
            i % 2 == 0 ? uniform01(rng) : 0.0f,
            uniform01(rng),
            vec3(1.0f, uniform01(rng), 2.0f * uniform01(rng))};
        const BsdfParams m = {plain.baseColor, plain.metallic, plain.roughness, plain.ior,
                              plain.transmission, plain.specular, plain.specularColor};
        ASSERT_EQ(m.anisotropy, 0.0f);
        const vec3 wo = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
        const vec3 wi = direction(2.0f * uniform01(rng) - 1.0f, TWO_PI * uniform01(rng));
        const float uLobe = uniform01(rng);
        const vec2 u(uniform01(rng), uniform01(rng));
        ASSERT_TRUE((wf::test::matchesPlainBsdf<BsdfParams, BsdfSample>(m, plain, wo, wi, uLobe,
                                                                        u)))
            << i;
    }
}

// Directional albedo by sampling, times eta^2 (test_bsdf.cpp says why).
vec3 albedo(const BsdfParams& m, vec3 wo, int n, unsigned seed, vec3* stdError) {
    std::mt19937 rng(seed);
    dvec3 sum(0.0), sum2(0.0);
    for (int i = 0; i < n; ++i) {
        BsdfSample s;
        if (bsdfSample(m, wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s)) {
            const dvec3 w = dvec3(s.weight) * double(s.eta * s.eta);
            sum += w;
            sum2 += w * w;
        }
    }
    const dvec3 mean = sum / double(n);
    *stdError = vec3(glm::sqrt(glm::max(sum2 / double(n) - mean * mean, 0.0) / double(n)));
    return vec3(mean);
}

// No white anisotropic material reflects more than it receives, at any cosine and azimuth
// (grazing and along the narrow axis is where the diffuse coupling's bound is tightest).
TEST(AnisotropicBsdf, WhiteFurnaceAtMostOne) {
    const std::vector<BsdfParams> whites = {
        material(vec3(1.0f), 1.0f, 0.0f, 0.5f), material(vec3(1.0f), 1.0f, 0.3f, 1.0f),
        material(vec3(1.0f), 0.0f, 0.2f, 0.7f), material(vec3(1.0f), 0.0f, 0.4f, 1.0f),
        material(vec3(1.0f), 0.0f, 0.5f, 1.0f), material(vec3(1.0f), 0.0f, 0.8f, 0.6f),
        material(vec3(1.0f), 0.0f, 0.3f, 0.8f, 1.0f)};
    unsigned seed = 1u;
    float maxSeen = 0.0f;
    for (const BsdfParams& m : whites) {
        const bool glass = m.transmission > 0.0f;
        for (float cosTheta : {1.0f, 0.5f, 0.2f, 0.05f, 0.02f, -0.3f, -0.8f}) {
            if (cosTheta < 0.0f && !glass)
                continue;
            for (float phi : {0.0f, 0.785f, 1.5708f}) {
                vec3 err;
                const int n = std::abs(cosTheta) < 0.1f ? 40000 : 6000;
                const vec3 a = albedo(m, direction(cosTheta, phi), n, seed++, &err);
                maxSeen = std::max(maxSeen, a.x);
                EXPECT_LE(a.x, 1.0f + 4.0f * err.x + 2e-3f)
                    << "metallic " << m.metallic << " roughness " << m.roughness
                    << " anisotropy " << m.anisotropy << " transmission " << m.transmission
                    << " cos " << cosTheta << " phi " << phi;
            }
        }
    }
    EXPECT_GT(maxSeen, 0.9f); // the furnace measured something
}

// The furnace is honest: a white metal's sampled albedo is the integral of its own
// f |cos| (quadrature), so the sampler loses nothing the lobe reflects; and as both alphas
// shrink the lobe becomes lossless, like the mirror it tends to.
TEST(AnisotropicBsdf, MetalAlbedoIsItsIntegralAndNearlySmoothIsLossless) {
    for (const BsdfParams& m : {material(vec3(1.0f), 1.0f, 0.4f, 0.8f),
                                material(vec3(1.0f), 1.0f, 0.6f, 1.0f)}) {
        for (vec3 wo : {direction(0.8f, 0.4f), direction(0.35f, 1.9f)}) {
            vec3 err;
            const vec3 a = albedo(m, wo, 40000, 9u, &err);
            const double integral = integrate(
                [&](vec3 wi) { return double(bsdfEval(m, wo, wi).x) * std::abs(wi.z); }, 1e-7);
            EXPECT_NEAR(a.x, integral, 4.0 * err.x + 2e-3)
                << m.roughness << " " << m.anisotropy << " cos " << wo.z;
            EXPECT_LT(integral, 1.0);
        }
    }
    const BsdfParams nearlySmooth = material(vec3(1.0f), 1.0f, 0.0f, 0.1f); // alpha 0.01, 1e-4
    for (float cosTheta : {0.9f, 0.5f, 0.2f}) {
        vec3 err;
        const vec3 a = albedo(nearlySmooth, direction(cosTheta, 0.6f), 4000, 10u, &err);
        EXPECT_NEAR(a.x, 1.0f, 5e-3f) << cosTheta;
    }
}

} // namespace
