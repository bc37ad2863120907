// Tests of the shared glTF BSDF (shaders/bsdf/bsdf.h) on the CPU, exactly as the shade pass
// runs it: sampled directions against bsdfPdf (chi-square over the whole sphere), sample weights
// against eval / pdf, reciprocity, energy, the Dirac lobes and numerical robustness.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "shaders/bsdf/bsdf.h"
#include "tests/unit/chi_square.h"

namespace {

using wf::test::uniform01;

using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;

BsdfParams material(vec3 baseColor, float metallic, float roughness, float specular = 1.0f,
                    float transmission = 0.0f, float ior = 1.5f, vec3 specularColor = vec3(1.0f)) {
    return BsdfParams{baseColor, metallic, roughness, ior, transmission, specular, specularColor};
}

vec3 direction(float cosTheta, float phi) {
    return wf::test::sphereDirection(cosTheta, phi);
}

struct Case {
    std::string name;
    BsdfParams m;
    vec3 wo;
};

// The table every statistical test runs over. wo avoids phi = 0 so that no lobe lines up with
// the bin edges by accident.
std::vector<Case> cases() {
    const vec3 plastic(0.8f, 0.5f, 0.3f), gold(1.0f, 0.78f, 0.34f);
    const vec3 wo = direction(0.75f, 0.7f), grazing = direction(0.2f, 2.0f);
    return {
        {"LambertSpecular0", material(plastic, 0.0f, 0.5f, 0.0f), wo},
        {"DielectricRough0.2", material(plastic, 0.0f, 0.2f), wo},
        {"DielectricRough0.5", material(plastic, 0.0f, 0.5f), grazing},
        {"DielectricRough1.0", material(plastic, 0.0f, 1.0f), wo},
        {"MetalRough0.1", material(gold, 1.0f, 0.1f), wo},
        {"MetalRough0.5", material(gold, 1.0f, 0.5f), grazing},
        {"MixedMetallic0.5", material(gold, 0.5f, 0.4f), wo},
        {"RoughGlassEntering", material(vec3(1.0f), 0.0f, 0.3f, 1.0f, 1.0f), wo},
        {"RoughGlassLeaving", material(vec3(1.0f), 0.0f, 0.3f, 1.0f, 1.0f),
         direction(-0.85f, 1.1f)},
        {"RoughGlassLeavingBeyondCritical", material(vec3(0.9f), 0.0f, 0.3f, 1.0f, 1.0f),
         direction(-0.6f, 1.1f)},
        {"HalfTransmissive", material(plastic, 0.2f, 0.4f, 1.0f, 0.5f, 1.33f), wo},
        {"ColouredSpecular", material(vec3(0.2f, 0.4f, 0.6f), 0.0f, 0.3f, 0.8f, 0.0f, 1.5f,
                                      vec3(1.0f, 0.5f, 3.0f)), wo},
        {"IndexMatchedRough", material(vec3(1.0f), 0.0f, 0.4f, 1.0f, 1.0f, 1.0f), wo},
    };
}

bool finite(vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

constexpr int CHI2_SAMPLES = 300000;

std::vector<double> sampleHistogram(const Case& c, const wf::test::SphereGrid& grid,
                                    unsigned seed) {
    auto sample = [&](float uLobe, vec2 u, vec3& wi) {
        BsdfSample s;
        const bool sampled = bsdfSample(c.m, c.wo, uLobe, u, s) && !s.isDelta;
        wi = s.wi;
        return sampled;
    };
    return wf::test::sampleHistogram(grid, seed, CHI2_SAMPLES, sample);
}

double pdfFit(const Case& c, const std::vector<double>& counts, const wf::test::SphereGrid& grid,
              const BsdfParams& pdfMaterial) {
    auto pdf = [&](vec3 wi) { return double(bsdfPdf(pdfMaterial, c.wo, wi)); };
    return wf::test::pdfFitPValue(counts, grid, CHI2_SAMPLES, pdf);
}

TEST(Bsdf, SampledDirectionsFollowBsdfPdf) {
    wf::test::SphereGrid grid;
    for (const Case& c : cases()) {
        std::vector<double> counts = sampleHistogram(c, grid, 20240601u);
        EXPECT_GT(pdfFit(c, counts, grid, c.m), 1e-3) << c.name;
    }
}

TEST(Bsdf, ChiSquareRejectsWrongPdf) {
    wf::test::SphereGrid grid;
    Case c = cases()[2]; // rough dielectric 0.5 at a grazing wo
    std::vector<double> counts = sampleHistogram(c, grid, 7u);
    BsdfParams rougher = c.m;
    rougher.roughness = 0.55f; // a 10% roughness error in the density
    EXPECT_LT(pdfFit(c, counts, grid, rougher), 1e-3);
    BsdfParams moreDiffuse = c.m;
    moreDiffuse.specular = 0.7f; // wrong lobe mixture
    EXPECT_LT(pdfFit(c, counts, grid, moreDiffuse), 1e-3);
}

TEST(Bsdf, SampleWeightIsEvalCosOverPdf) {
    for (const Case& c : cases()) {
        std::mt19937 rng(11u);
        int nonDelta = 0;
        for (int i = 0; i < 4000; ++i) {
            BsdfSample s;
            if (!bsdfSample(c.m, c.wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s) ||
                s.isDelta) {
                continue;
            }
            ++nonDelta;
            float pdf = bsdfPdf(c.m, c.wo, s.wi);
            vec3 expected = bsdfEval(c.m, c.wo, s.wi) * std::abs(s.wi.z) / pdf;
            ASSERT_GT(pdf, 0.0f) << c.name;
            EXPECT_NEAR(s.pdf, pdf, 1e-5f * pdf) << c.name;
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(s.weight[k], expected[k], 1e-4f * expected[k] + 1e-7f) << c.name;
            }
            bool refracted = s.wi.z * c.wo.z < 0.0f;
            float eta = refracted ? (c.wo.z > 0.0f ? c.m.ior : 1.0f / c.m.ior) : 1.0f;
            EXPECT_FLOAT_EQ(s.eta, eta) << c.name;
        }
        EXPECT_GT(nonDelta, 0) << c.name; // index-matched glass is mostly its Dirac lobe
    }
}

TEST(Bsdf, ReflectionIsReciprocal) {
    std::mt19937 rng(5u);
    for (const Case& c : cases()) {
        for (int i = 0; i < 2000; ++i) {
            vec3 a = direction(uniform01(rng), 6.2831853f * uniform01(rng));
            vec3 b = direction(uniform01(rng), 6.2831853f * uniform01(rng));
            float side = c.wo.z < 0.0f ? -1.0f : 1.0f; // same side as the case's wo
            a.z *= side;
            b.z *= side;
            vec3 fab = bsdfEval(c.m, a, b), fba = bsdfEval(c.m, b, a);
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(fab[k], fba[k], 2e-4f * std::max(fab[k], fba[k]) + 1e-7f) << c.name;
            }
        }
    }
}

// Refraction: f(wo, wi) / eta(wo)^2 = f(wi, wo) / eta(wi)^2, i.e. f(wi, wo) = eta^2 f(wo, wi)
// with eta = eta(wi side) / eta(wo side): the radiance BTDF's 1 / eta^2.
TEST(Bsdf, RefractionIsReciprocalUpToEtaSquared) {
    std::mt19937 rng(6u);
    for (float ior : {1.5f, 1.1f, 2.4f}) {
        BsdfParams glass = material(vec3(0.9f, 0.8f, 1.0f), 0.0f, 0.4f, 1.0f, 1.0f, ior);
        int compared = 0;
        for (int i = 0; i < 20000; ++i) {
            vec3 out = direction(uniform01(rng), 6.2831853f * uniform01(rng));
            vec3 in = direction(-uniform01(rng), 6.2831853f * uniform01(rng));
            vec3 fOutIn = bsdfEval(glass, out, in), fInOut = bsdfEval(glass, in, out);
            if (fOutIn.x <= 0.0f && fInOut.x <= 0.0f) {
                continue;
            }
            ++compared;
            for (int k = 0; k < 3; ++k) {
                float expected = ior * ior * fOutIn[k];
                EXPECT_NEAR(fInOut[k], expected, 1e-3f * expected + 1e-7f) << ior;
            }
        }
        EXPECT_GT(compared, 500) << ior;
    }
}

// Directional albedo: the mean of the sample weights, times eta^2 to undo the radiance scaling
// of refraction (which makes light leaving glass brighter per solid angle, not more energetic).
vec3 albedo(const BsdfParams& m, vec3 wo, int n, unsigned seed, vec3* stdError = nullptr) {
    std::mt19937 rng(seed);
    glm::dvec3 sum(0.0), sum2(0.0);
    for (int i = 0; i < n; ++i) {
        BsdfSample s;
        if (bsdfSample(m, wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s)) {
            glm::dvec3 w = glm::dvec3(s.weight) * double(s.eta * s.eta);
            sum += w;
            sum2 += w * w;
        }
    }
    glm::dvec3 mean = sum / double(n);
    if (stdError) {
        *stdError = vec3(glm::sqrt(glm::max(sum2 / double(n) - mean * mean, 0.0) / double(n)));
    }
    return vec3(mean);
}

TEST(Bsdf, AlbedoAtMostOne) {
    std::vector<Case> table = cases();
    table.push_back({"WhiteDielectric0.3", material(vec3(1.0f), 0.0f, 0.3f), vec3(0, 0, 1)});
    table.push_back({"WhiteDielectricSmooth", material(vec3(1.0f), 0.0f, 0.0f), vec3(0, 0, 1)});
    table.push_back(
        {"WhiteGlassSmooth", material(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.0f), vec3(0, 0, 1)});
    table.push_back({"WhiteSpecularColour", material(vec3(1.0f), 0.0f, 0.6f, 1.0f, 0.0f, 1.5f,
                                                     vec3(20.0f, 1.0f, 0.0f)), vec3(0, 0, 1)});
    for (const Case& c : table) {
        bool transmissive = c.m.transmission > 0.0f;
        for (float cosTheta : {1.0f, 0.8f, 0.5f, 0.2f, 0.05f, -0.05f, -0.5f, -0.9f}) {
            if (cosTheta < 0.0f && !transmissive) {
                continue;
            }
            vec3 wo = direction(cosTheta, 0.3f), err;
            vec3 a = albedo(c.m, wo, 20000, 3u, &err);
            for (int k = 0; k < 3; ++k) {
                EXPECT_LE(a[k], 1.0f + 4.0f * err[k] + 3e-3f) << c.name << " cos " << cosTheta;
            }
        }
    }
}

TEST(Bsdf, SpecularZeroIsExactlyLambert) {
    BsdfParams m = material(vec3(0.8f, 0.5f, 0.3f), 0.0f, 0.7f, 0.0f);
    std::mt19937 rng(9u);
    for (int i = 0; i < 1000; ++i) {
        vec3 wo = direction(uniform01(rng), 6.2831853f * uniform01(rng));
        vec3 wi = direction(uniform01(rng), 6.2831853f * uniform01(rng));
        EXPECT_EQ(bsdfEval(m, wo, wi), m.baseColor * WF_INV_PI);
        EXPECT_FLOAT_EQ(bsdfPdf(m, wo, wi), wi.z * WF_INV_PI);
        vec3 a = albedo(m, wo, 64, i);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(a[k], m.baseColor[k], 1e-5f);
        }
    }
}

// Scenes of Lambertian materials compile the diffuse-only BSDF (WF_BSDF_DIFFUSE_ONLY); it must
// agree with the general model on every such material: colours in and beyond [0, 1], any
// roughness and ior, both sides, black.
TEST(Bsdf, DiffuseOnlyMatchesTheGeneralModel) {
    std::mt19937 rng(21u);
    for (int i = 0; i < 4000; ++i) {
        vec3 color(1.2f * uniform01(rng) - 0.1f, uniform01(rng), uniform01(rng));
        if (i % 50 == 0)
            color = vec3(0.0f);
        BsdfParams m = material(color, 0.0f, i % 7 == 0 ? 0.0f : uniform01(rng), 0.0f, 0.0f,
                                0.5f + 2.0f * uniform01(rng));
        float sideO = i % 2 ? 1.0f : -1.0f;
        float sideI = i % 3 ? 1.0f : -1.0f;
        vec3 wo = direction(sideO * uniform01(rng), 6.2831853f * uniform01(rng));
        vec3 wi = direction(sideI * uniform01(rng), 6.2831853f * uniform01(rng));
        vec3 eval = bsdfEval(m, wo, wi), fast = diffuseOnlyEval(m, wo, wi);
        for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(fast[k], eval[k], 1e-6f * eval[k] + 1e-9f) << i;
        ASSERT_NEAR(diffuseOnlyPdf(m, wo, wi), bsdfPdf(m, wo, wi), 1e-6f) << i;
        ASSERT_EQ(diffuseOnlyHasNonDelta(m), bsdfHasNonDelta(m)) << i;
        vec2 u(uniform01(rng), uniform01(rng));
        BsdfSample general, diffuse;
        bool sampled = bsdfSample(m, wo, uniform01(rng), u, general);
        ASSERT_EQ(diffuseOnlySample(m, wo, u, diffuse), sampled) << i;
        if (!sampled)
            continue;
        for (int k = 0; k < 3; ++k) {
            ASSERT_FLOAT_EQ(diffuse.wi[k], general.wi[k]) << i;
            ASSERT_NEAR(diffuse.weight[k], general.weight[k], 1e-5f) << i;
        }
        ASSERT_FLOAT_EQ(diffuse.pdf, general.pdf) << i;
        ASSERT_EQ(diffuse.isDelta, general.isDelta);
        ASSERT_EQ(diffuse.eta, general.eta);
    }
}

// The specular kind's shade pass (WF_BSDF_DELTA_ONLY) samples with deltaOnlySample: for
// smooth mirrors and glass it must be the general model's sample, and the general model must
// give such materials no density (their pass compiles next-event estimation out).
TEST(Bsdf, DeltaOnlyMatchesTheGeneralModel) {
    std::mt19937 rng(22u);
    for (int i = 0; i < 4000; ++i) {
        vec3 color(uniform01(rng), uniform01(rng), uniform01(rng));
        if (i % 50 == 0)
            color = vec3(0.0f);
        const bool metal = i % 2 == 0;
        const float ior = i % 11 == 0 ? 1.0f : i % 13 == 0 ? 0.0f : 0.5f + 2.0f * uniform01(rng);
        BsdfParams m = material(color, metal ? 1.0f : 0.0f, 0.0f,
                                i % 5 == 0 ? 0.0f : uniform01(rng), metal ? 0.0f : 1.0f, ior,
                                vec3(uniform01(rng), uniform01(rng), uniform01(rng)));
        ASSERT_FALSE(bsdfHasNonDelta(m)) << i;
        vec3 wo = direction((i % 3 ? 1.0f : -1.0f) * uniform01(rng), 6.2831853f * uniform01(rng));
        vec2 u(uniform01(rng), uniform01(rng));
        const float uLobe = uniform01(rng);
        BsdfSample general, delta;
        bool sampled = bsdfSample(m, wo, uLobe, u, general);
        ASSERT_EQ(deltaOnlySample(m, wo, uLobe, delta), sampled) << i;
        if (!sampled)
            continue;
        for (int k = 0; k < 3; ++k) {
            ASSERT_FLOAT_EQ(delta.wi[k], general.wi[k]) << i;
            ASSERT_FLOAT_EQ(delta.weight[k], general.weight[k]) << i;
        }
        ASSERT_FLOAT_EQ(delta.pdf, general.pdf) << i;
        ASSERT_TRUE(delta.isDelta);
        ASSERT_EQ(delta.isDelta, general.isDelta);
        ASSERT_EQ(delta.eta, general.eta);
    }
}

TEST(Bsdf, MetalWhiteFurnaceLosesLittleEnergy) {
    // Single-scattering GGX loses energy with roughness (1 - ln 2 remains at alpha = 1 and
    // normal incidence); it never gains any. Roughness 0 with F0 = 1 reflects everything.
    const float roughness[] = {0.0f, 0.1f, 0.3f, 0.5f, 1.0f};
    const float lowest[] = {1.0f, 0.97f, 0.9f, 0.75f, 0.29f};
    for (int r = 0; r < 5; ++r) {
        BsdfParams m = material(vec3(1.0f), 1.0f, roughness[r]);
        for (float cosTheta : {1.0f, 0.6f, 0.3f}) {
            vec3 err;
            vec3 a = albedo(m, direction(cosTheta, 1.0f), 20000, 4u, &err);
            EXPECT_LE(a.x, 1.0f + 4.0f * err.x + 1e-5f) << roughness[r] << " " << cosTheta;
            EXPECT_GE(a.x, lowest[r] - 4.0f * err.x) << roughness[r] << " " << cosTheta;
        }
    }
}

TEST(Bsdf, RoughnessZeroMetalIsAMirror) {
    BsdfParams m = material(vec3(0.9f, 0.6f, 0.3f), 1.0f, 0.0f);
    EXPECT_TRUE(bsdfIsPureDelta(m));
    EXPECT_FALSE(bsdfHasNonDelta(m));
    std::mt19937 rng(12u);
    for (int i = 0; i < 1000; ++i) {
        vec3 wo = direction(uniform01(rng), 6.2831853f * uniform01(rng));
        BsdfSample s;
        ASSERT_TRUE(bsdfSample(m, wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s));
        EXPECT_TRUE(s.isDelta);
        EXPECT_EQ(s.wi, vec3(-wo.x, -wo.y, wo.z));
        vec3 f = fresnelSchlick(m.baseColor, wo.z);
        for (int k = 0; k < 3; ++k) {
            EXPECT_FLOAT_EQ(s.weight[k], f[k]);
        }
        EXPECT_EQ(s.eta, 1.0f);
        EXPECT_EQ(bsdfEval(m, wo, s.wi), vec3(0.0f));
        EXPECT_EQ(bsdfPdf(m, wo, s.wi), 0.0f);
    }
}

TEST(Bsdf, SmoothGlassSplitsByFresnel) {
    const float ior = 1.5f;
    BsdfParams glass = material(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.0f, ior);
    EXPECT_TRUE(bsdfIsPureDelta(glass));
    for (float cosTheta : {1.0f, 0.7f, 0.2f, -1.0f, -0.9f, -0.8f}) {
        vec3 wo = direction(cosTheta, 0.4f);
        BsdfSample r, t;
        ASSERT_TRUE(bsdfSample(glass, wo, 0.0f, vec2(0.5f), r));
        ASSERT_TRUE(bsdfSample(glass, wo, 0x1.fffffep-1f, vec2(0.5f), t));
        ASSERT_TRUE(r.isDelta && t.isDelta);
        EXPECT_EQ(r.wi, vec3(-wo.x, -wo.y, wo.z));
        EXPECT_LT(t.wi.z * wo.z, 0.0f);
        float eta = cosTheta > 0.0f ? ior : 1.0f / ior;
        EXPECT_FLOAT_EQ(t.eta, eta);
        // Snell: sin(theta_t) = sin(theta_o) / eta, in the plane of wo and the normal.
        float sinO = std::sqrt(1.0f - wo.z * wo.z), sinT = std::sqrt(1.0f - t.wi.z * t.wi.z);
        EXPECT_NEAR(sinT, sinO / eta, 1e-5f);
        EXPECT_NEAR(glm::dot(vec2(t.wi), vec2(wo)), -sinO * sinT, 1e-5f);
        // Discrete probabilities sum to 1; reflected plus transmitted energy is 1.
        EXPECT_NEAR(r.pdf + t.pdf, 1.0f, 1e-6f);
        float reflected = r.weight.x * r.pdf, transmitted = t.weight.x * t.pdf * eta * eta;
        EXPECT_NEAR(reflected + transmitted, 1.0f, 1e-5f);
        // Schlick at the cosine on the air side, which also makes the split reciprocal.
        float cosAir = cosTheta > 0.0f ? wo.z : std::abs(t.wi.z);
        EXPECT_NEAR(reflected, fresnelSchlick(vec3(0.04f), cosAir).x, 1e-5f);
    }
}

TEST(Bsdf, TotalInternalReflectionOnlyReflects) {
    BsdfParams glass = material(vec3(1.0f), 0.0f, 0.0f, 1.0f, 1.0f, 1.5f);
    vec3 wo = direction(-0.3f, 1.0f); // 72.5 degrees inside, past the 41.8 degree critical angle
    for (float uLobe : {0.0f, 0.5f, 0.9f, 0x1.fffffep-1f}) {
        BsdfSample s;
        ASSERT_TRUE(bsdfSample(glass, wo, uLobe, vec2(0.3f, 0.6f), s));
        EXPECT_TRUE(s.isDelta);
        EXPECT_EQ(s.wi, vec3(-wo.x, -wo.y, wo.z));
        EXPECT_FLOAT_EQ(s.weight.x, 1.0f);
        EXPECT_FLOAT_EQ(s.pdf, 1.0f);
        EXPECT_EQ(s.eta, 1.0f);
    }
}

TEST(Bsdf, IndexMatchedTransmissionPassesStraight) {
    for (float roughness : {0.0f, 0.4f}) {
        BsdfParams m = material(vec3(1.0f), 0.0f, roughness, 1.0f, 1.0f, 1.0f);
        std::mt19937 rng(13u);
        int passed = 0;
        for (int i = 0; i < 2000; ++i) {
            vec3 wo = direction(2.0f * uniform01(rng) - 1.0f, 6.2831853f * uniform01(rng));
            BsdfSample s;
            if (bsdfSample(m, wo, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s) &&
                s.wi.z * wo.z < 0.0f) {
                ++passed;
                EXPECT_TRUE(s.isDelta);
                EXPECT_EQ(s.wi, -wo);
                EXPECT_EQ(s.eta, 1.0f);
            }
        }
        EXPECT_GT(passed, 1500) << roughness; // F0 = 0: most light goes through
    }
}

TEST(Bsdf, NeverNanOrInf) {
    std::mt19937 rng(17u);
    const float roughness[] = {0.0f, 1e-7f, 1e-4f, 0.01f, 0.3f, 1.0f};
    const float iors[] = {0.0f, 1.0f, 1.0005f, 1.5f, 2.4f, 0.7f};
    const float units[] = {0.0f, 1.0f, 0.5f};
    const float edgeZ[] = {0.0f, 1.0f, -1.0f, 1e-7f, -1e-7f};
    for (int i = 0; i < 100000; ++i) {
        BsdfParams m;
        m.baseColor = vec3(uniform01(rng), uniform01(rng), i % 7 == 0 ? 0.0f : 1.0f);
        m.metallic = i % 3 == 0 ? units[i % 2] : uniform01(rng);
        m.roughness = i % 2 == 0 ? roughness[i % 6] : uniform01(rng);
        m.ior = iors[(i / 6) % 6];
        m.transmission = i % 5 < 3 ? units[i % 3] : uniform01(rng);
        m.specular = i % 4 == 0 ? units[(i / 4) % 2] : uniform01(rng);
        m.specularColor = vec3(uniform01(rng) * 4.0f, 1.0f, i % 11 == 0 ? 0.0f : 1.0f);
        vec3 wo, wi;
        if (i % 10 == 0) {
            float z = edgeZ[(i / 10) % 5];
            wo = direction(z, 6.2831853f * uniform01(rng));
        } else {
            wo = direction(2.0f * uniform01(rng) - 1.0f, 6.2831853f * uniform01(rng));
        }
        wi = direction(i % 13 == 0 ? edgeZ[i % 5] : 2.0f * uniform01(rng) - 1.0f,
                       6.2831853f * uniform01(rng));
        vec3 f = bsdfEval(m, wo, wi);
        float pdf = bsdfPdf(m, wo, wi);
        ASSERT_TRUE(finite(f) && f.x >= 0.0f && f.y >= 0.0f && f.z >= 0.0f) << i;
        ASSERT_TRUE(std::isfinite(pdf) && pdf >= 0.0f) << i;
        float uLobe = i % 17 == 0 ? units[i % 2] * 0x1.fffffep-1f : uniform01(rng);
        vec2 u = i % 19 == 0 ? vec2(units[i % 2] * 0x1.fffffep-1f)
                             : vec2(uniform01(rng), uniform01(rng));
        BsdfSample s;
        if (bsdfSample(m, wo, uLobe, u, s)) {
            ASSERT_TRUE(finite(s.weight) && s.weight.x >= 0.0f && s.weight.y >= 0.0f &&
                        s.weight.z >= 0.0f) << i;
            ASSERT_TRUE(std::isfinite(s.pdf) && s.pdf > 0.0f) << i;
            ASSERT_TRUE(std::isfinite(s.eta) && s.eta > 0.0f) << i;
            ASSERT_NEAR(glm::length(s.wi), 1.0f, 1e-3f) << i;
        }
    }
}

TEST(Bsdf, DeltaClassification) {
    EXPECT_TRUE(bsdfHasNonDelta(material(vec3(0.5f), 0.0f, 0.0f)));  // smooth plastic: diffuse
    EXPECT_FALSE(bsdfIsPureDelta(material(vec3(0.5f), 0.0f, 0.0f)));
    EXPECT_TRUE(bsdfHasNonDelta(material(vec3(0.5f), 1.0f, 0.2f)));
    // Index-matched rough glass without a specular layer: only the straight pass-through.
    EXPECT_TRUE(bsdfIsPureDelta(material(vec3(1.0f), 0.0f, 0.7f, 0.0f, 1.0f, 1.0f)));
    // Black, no specular layer: scatters nothing, so neither.
    EXPECT_FALSE(bsdfIsPureDelta(material(vec3(0.0f), 0.0f, 0.0f, 0.0f)));
    EXPECT_FALSE(bsdfHasNonDelta(material(vec3(0.0f), 0.0f, 0.0f, 0.0f)));
}

} // namespace
