// KHR_materials_dispersion on the CPU (shaders/bsdf/dispersion.h and bsdf.h, exactly as the
// shade pass runs them): n(lambda) against the spec's formula and its Abbe number, the RGB
// weights of a wavelength (average (1, 1, 1), finite, the rainbow's order), and refraction
// through a dispersive slab following Snell with n(lambda) at each wavelength; --spectral
// hero's lanes (one per quarter of the range, each uniform over it, their mean weight white)
// and the Dirac reflection every lane weighs (bsdfDeltaReflection, bsdfSample's own).
#include <gtest/gtest.h>

#include <cmath>

#include "shaders/bsdf/bsdf.h"
#include "shaders/bsdf/dispersion.h"

namespace {

using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;

constexpr double LAMBDA_F = 486.13, LAMBDA_D = 587.56, LAMBDA_C = 656.27;

// The spec's derivation, in double: Cauchy's n = A + B / lambda^2 through n_d with Abbe V.
double specIor(double nd, double dispersion, double lambda) {
    const double abbe = 20.0 / dispersion;
    const double b = (nd - 1.0) / (abbe * (1.0 / (LAMBDA_F * LAMBDA_F) -
                                           1.0 / (LAMBDA_C * LAMBDA_C)));
    const double a = nd - b / (LAMBDA_D * LAMBDA_D);
    return std::max(a + b / (lambda * lambda), 1.0);
}

TEST(Dispersion, IorFollowsTheSpecsFormula) {
    for (float nd : {1.33f, 1.5f, 1.6f, 2.42f})
        for (float d : {0.1f, 0.33f, 1.0f, 2.04f})
            for (float lambda = 380.0f; lambda <= 780.0f; lambda += 10.0f)
                EXPECT_NEAR(dispersionIor(nd, d, lambda), specIor(nd, d, lambda), 2e-4)
                    << nd << " " << d << " " << lambda;
}

TEST(Dispersion, IorAtTheDLineIsTheMaterialsAndTheAbbeNumberHolds) {
    for (float nd : {1.33f, 1.5f, 1.7f})
        for (float d : {0.2f, 0.5f, 1.0f, 2.0f}) {
            EXPECT_NEAR(dispersionIor(nd, d, WF_LAMBDA_D), nd, 2e-5f);
            const float nF = dispersionIor(nd, d, float(LAMBDA_F));
            const float nC = dispersionIor(nd, d, float(LAMBDA_C));
            EXPECT_GT(nF, nC); // normal dispersion: blue bends more
            EXPECT_NEAR((nd - 1.0f) / (nF - nC), 20.0f / d, 2e-3f * 20.0f / d);
        }
}

TEST(Dispersion, ZeroDispersionIsTheIorAtEveryWavelength) {
    for (float lambda = 380.0f; lambda <= 780.0f; lambda += 1.0f)
        EXPECT_EQ(dispersionIor(1.5f, 0.0f, lambda), 1.5f);
    // Extreme dispersion never takes the ior below 1.
    EXPECT_EQ(dispersionIor(1.1f, 1000.0f, 780.0f), 1.0f);
}

TEST(Dispersion, WeightsAverageToWhiteAndAreFinite) {
    const int n = 200000;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
        const vec3 w = dispersionWeight(sampleWavelength((i + 0.5f) / n));
        for (int c = 0; c < 3; ++c) {
            ASSERT_TRUE(std::isfinite(w[c])) << i;
            ASSERT_GE(w[c], 0.0f) << i;
            ASSERT_LT(w[c], 16.0f) << i;
        }
        sum += glm::dvec3(w);
    }
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sum[c] / n, 1.0, 1e-4) << "channel " << c;
    EXPECT_EQ(sampleWavelength(0.0f), WF_LAMBDA_MIN);
    EXPECT_NEAR(sampleWavelength(0x1.fffffep-1f), WF_LAMBDA_MAX, 1e-3f);
}

TEST(Dispersion, WeightsHaveTheRainbowsOrder) {
    auto dominant = [](vec3 w) { return w.x > std::max(w.y, w.z) ? 0 : w.y > w.z ? 1 : 2; };
    EXPECT_EQ(dominant(dispersionWeight(450.0f)), 2);
    EXPECT_EQ(dominant(dispersionWeight(530.0f)), 1);
    EXPECT_EQ(dominant(dispersionWeight(640.0f)), 0);
}

// A smooth dispersive slab: enter, then leave through the parallel face. Each wavelength
// bends by Snell with its own n(lambda) inside and leaves parallel to where it came from.
TEST(Dispersion, SlabRefractsBySnellAtEachWavelength) {
    const vec3 wo = glm::normalize(vec3(0.6f, 0.2f, 0.77f)); // towards the light, outside
    float previousSin = 0.0f;
    for (float lambda : {400.0f, 486.13f, 550.0f, 587.56f, 656.27f, 700.0f, 780.0f}) {
        const float n = dispersionIor(1.5f, 1.0f, lambda);
        BsdfParams glass{vec3(1.0f), 0.0f, 0.0f, n, 1.0f, 1.0f, vec3(1.0f)};
        BsdfSample in, out;
        ASSERT_TRUE(bsdfSample(glass, wo, 0x1.fffffep-1f, vec2(0.5f), in)); // refract
        ASSERT_TRUE(in.isDelta);
        ASSERT_LT(in.wi.z, 0.0f);
        EXPECT_FLOAT_EQ(in.eta, n);
        const float sinO = std::sqrt(1.0f - wo.z * wo.z);
        const float sinT = std::sqrt(1.0f - in.wi.z * in.wi.z);
        EXPECT_NEAR(sinT, sinO / n, 1e-5f) << lambda;
        // Longer waves bend less: their angle inside stays nearer the incident one.
        EXPECT_GT(sinT, previousSin) << lambda;
        previousSin = sinT;
        // The far face, parallel, its outside below: its frame mirrors z, and the path
        // arrives from inside (wo.z < 0 there).
        const vec3 woFar(-in.wi.x, -in.wi.y, in.wi.z);
        ASSERT_TRUE(bsdfSample(glass, woFar, 0x1.fffffep-1f, vec2(0.5f), out));
        ASSERT_GT(out.wi.z, 0.0f);
        EXPECT_FLOAT_EQ(out.eta, 1.0f / n);
        // Back in the slab's frame (z mirrored again): the incoming ray's direction, -wo.
        EXPECT_NEAR(out.wi.x, -wo.x, 1e-5f);
        EXPECT_NEAR(out.wi.y, -wo.y, 1e-5f);
        EXPECT_NEAR(-out.wi.z, -wo.z, 1e-5f);
    }
}

// --spectral hero: the four lanes of any hero fall one in each quarter of the range, 100 nm
// apart (wrapped), so each lane is uniform over it as the hero is, and a path's weight, the
// lanes' mean, averages to white as the single wavelength's does.
TEST(Dispersion, HeroLanesStratifyTheRange) {
    const int n = 100000;
    glm::dvec3 sum(0.0);
    for (int i = 0; i < n; ++i) {
        const float hero = sampleWavelength((i + 0.5f) / n);
        int quarters = 0;
        vec3 mean(0.0f);
        for (uint j = 0; j < WF_HERO_LANES; ++j) {
            const float lambda = heroLaneWavelength(hero, j);
            ASSERT_GE(lambda, WF_LAMBDA_MIN) << hero << " " << j;
            ASSERT_LT(lambda, WF_LAMBDA_MAX) << hero << " " << j;
            quarters |= 1 << int((lambda - WF_LAMBDA_MIN) / 100.0f);
            const float shift = std::fmod(lambda - hero + 400.0f, 400.0f);
            ASSERT_NEAR(shift, 100.0f * float(j), 1e-3f) << hero << " " << j;
            mean += dispersionWeight(lambda) * 0.25f;
        }
        ASSERT_EQ(quarters, 15) << hero;
        sum += glm::dvec3(mean);
    }
    EXPECT_EQ(heroLaneWavelength(WF_LAMBDA_MIN, 0), WF_LAMBDA_MIN);
    for (float hero : {380.0f, 480.0f, 580.0f, 680.0f}) // lanes that land on 780 exactly wrap
        for (uint j = 0; j < WF_HERO_LANES; ++j)
            EXPECT_LT(heroLaneWavelength(hero, j), WF_LAMBDA_MAX) << hero << " " << j;
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sum[c] / n, 1.0, 1e-4) << "channel " << c;
}

// bsdfDeltaReflection is the Dirac reflection bsdfSample picks, its throughput and chance, at
// every ior a lane takes, on both sides of the glass (TIR included), and nothing where the
// surface is rough.
TEST(Dispersion, DeltaReflectionIsTheSamplesReflection) {
    for (float lambda : {380.0f, 450.0f, 587.56f, 700.0f})
        for (float cosine : {0.95f, 0.6f, 0.3f, 0.1f, -0.3f, -0.8f, -0.95f}) {
            const float n = dispersionIor(1.5f, 5.0f, lambda);
            BsdfParams glass{vec3(0.9f, 0.8f, 1.0f), 0.0f, 0.0f, n, 1.0f, 1.0f, vec3(1.0f)};
            const float sine = std::sqrt(1.0f - cosine * cosine);
            const vec3 wo(sine, 0.0f, cosine);
            BsdfSample s;
            ASSERT_TRUE(bsdfSample(glass, wo, 0.0f, vec2(0.5f), s)) << lambda << " " << cosine;
            ASSERT_TRUE(s.isDelta);
            ASSERT_GT(s.wi.z * wo.z, 0.0f); // uLobe 0 picks the reflection
            float probability = -1.0f;
            const vec3 throughput = bsdfDeltaReflection(glass, wo, probability);
            EXPECT_NEAR(probability, s.pdf, 1e-6f) << lambda << " " << cosine;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(throughput[c], s.weight[c] * s.pdf, 1e-6f) << lambda << " " << cosine;
            glass.roughness = 0.2f;
            EXPECT_EQ(bsdfDeltaReflection(glass, wo, probability), vec3(0.0f));
            EXPECT_EQ(probability, 0.0f);
        }
}

} // namespace
