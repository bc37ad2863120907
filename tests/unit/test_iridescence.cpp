// KHR_materials_iridescence: the thin-film Fresnel of shaders/bsdf/iridescence.h against an
// independent double-precision evaluation of the extension's formula, its reductions to the
// plain Fresnel, its range, and the BSDF of bsdf.h with a film (factor 0 is the plain BSDF bit
// for bit; the white furnace stays at or below 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "shaders/bsdf/bsdf.h"
#include "tests/unit/chi_square.h"

namespace {

using glm::dvec3;
using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;

// The extension's formula in double, written from the specification (not from the header).
double schlick(double f0, double c) {
    return f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0);
}

dvec3 sensitivity(double opd, dvec3 shift) {
    const double pi = 3.14159265358979323846;
    const double phase = 2.0 * pi * opd * 1.0e-9;
    const double val[3] = {5.4856e-13, 4.4201e-13, 5.2481e-13};
    const double pos[3] = {1.6810e+06, 1.7953e+06, 2.2084e+06};
    const double var[3] = {4.3278e+09, 9.3046e+09, 6.6121e+09};
    double xyz[3];
    for (int k = 0; k < 3; ++k) {
        xyz[k] = val[k] * std::sqrt(2.0 * pi * var[k]) * std::cos(pos[k] * phase + shift[k]) *
                 std::exp(-phase * phase * var[k]);
    }
    xyz[0] += 9.7470e-14 * std::sqrt(2.0 * pi * 4.5282e+09) *
              std::cos(2.2399e+06 * phase + shift[0]) * std::exp(-4.5282e+09 * phase * phase);
    for (double& v : xyz) v /= 1.0685e-7;
    return dvec3(3.2404542 * xyz[0] - 1.5371385 * xyz[1] - 0.4985314 * xyz[2],
                 -0.9692660 * xyz[0] + 1.8760108 * xyz[1] + 0.0415560 * xyz[2],
                 0.0556434 * xyz[0] - 0.2040259 * xyz[1] + 1.0572252 * xyz[2]);
}

dvec3 referenceIridescence(double n1, double n2, double cos1, double d, dvec3 f0) {
    const double pi = 3.14159265358979323846;
    const double sin2Sq = (n1 / n2) * (n1 / n2) * (1.0 - cos1 * cos1);
    const double cos2 = std::sqrt(1.0 - sin2Sq);
    const double r0 = (n2 - n1) * (n2 - n1) / ((n2 + n1) * (n2 + n1));
    const double r12 = schlick(r0, cos1), t121 = 1.0 - r12;
    const double phi21 = n2 < n1 ? 0.0 : pi;
    // Per channel of the base; the spec then evaluates the sensitivity with the channels'
    // phase shifts as one vector (its x, y, z shifts being the red, green and blue ones).
    dvec3 r23, phi;
    for (int k = 0; k < 3; ++k) {
        const double s = std::sqrt(std::min(f0[k], 0.9999)); // the spec's guard against F0 1
        const double n3 = (1.0 + s) / (1.0 - s);
        r23[k] = schlick((n3 - n2) * (n3 - n2) / ((n3 + n2) * (n3 + n2)), cos2);
        phi[k] = phi21 + (n3 < n2 ? pi : 0.0);
    }
    const dvec3 r123 = glm::clamp(r12 * r23, dvec3(1e-5), dvec3(0.9999));
    const dvec3 rs = t121 * t121 * r23 / (1.0 - r123);
    dvec3 sum = r12 + rs, cm = rs - t121;
    for (int m = 1; m <= 2; ++m) {
        cm *= glm::sqrt(r123);
        sum += cm * 2.0 * sensitivity(m * 2.0 * n2 * d * cos2, double(m) * phi);
    }
    return glm::clamp(sum, dvec3(0.0), dvec3(1.0));
}

bool sameBits(vec3 a, vec3 b) {
    return std::memcmp(&a, &b, sizeof(vec3)) == 0;
}

const float kCosines[] = {1.0f, 0.9f, 0.7f, 0.5f, 0.3f, 0.1f, 0.02f};
const vec3 kBaseF0s[] = {vec3(0.04f), vec3(0.02f, 0.05f, 0.1f), vec3(1.0f, 0.78f, 0.34f),
                         vec3(0.95f, 0.64f, 0.54f)};

TEST(IridescenceFresnel, MatchesDoubleReference) {
    for (float d : {100.0f, 250.0f, 400.0f, 800.0f}) {
        for (float n2 : {1.3f, 1.8f, 1.2f}) {
            for (float c : {1.0f, 0.8f, 0.45f, 0.2f}) {
                for (vec3 f0 : kBaseF0s) {
                    const vec3 got = fresnelIridescence(1.0f, n2, c, d, f0);
                    const dvec3 want = referenceIridescence(1.0, n2, c, d, dvec3(f0));
                    for (int k = 0; k < 3; ++k) {
                        EXPECT_NEAR(got[k], want[k], 2e-4)
                            << "d " << d << " n2 " << n2 << " cos " << c << " channel " << k;
                    }
                }
            }
        }
    }
    // One value pinned: a 400 nm film of ior 1.3 on glass (F0 0.04) at normal incidence.
    const dvec3 pinned = referenceIridescence(1.0, 1.3, 1.0, 400.0, dvec3(0.04));
    const vec3 got = fresnelIridescence(1.0f, 1.3f, 1.0f, 400.0f, vec3(0.04f));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], pinned[k], 2e-4);
    EXPECT_GT(pinned.x + pinned.y + pinned.z, 0.0);
}

TEST(IridescenceFresnel, NoFilmIsThePlainFresnel) {
    for (float c : kCosines) {
        for (vec3 f0 : kBaseF0s) {
            const vec3 plain = fresnelSchlick(f0, c);
            EXPECT_TRUE(sameBits(fresnelIridescence(1.0f, 1.3f, c, 0.0f, f0), plain)) << c;
            EXPECT_TRUE(sameBits(fresnelIridescence(1.0f, 1.0f, c, 400.0f, f0), plain)) << c;
            EXPECT_TRUE(sameBits(fresnelIridescence(1.33f, 1.33f, c, 250.0f, f0), plain)) << c;
        }
    }
}

TEST(IridescenceFresnel, InRangeAndShiftsColourWithThickness) {
    for (float n2 : {1.0f, 1.2f, 1.3f, 1.5f, 2.0f, 3.0f}) {
        for (float d = 0.0f; d <= 1200.0f; d += 10.0f) {
            for (float c : kCosines) {
                for (vec3 f0 : kBaseF0s) {
                    const vec3 f = fresnelIridescence(1.0f, n2, c, d, f0);
                    for (int k = 0; k < 3; ++k) {
                        ASSERT_TRUE(f[k] >= 0.0f && f[k] <= 1.0f)
                            << "n2 " << n2 << " d " << d << " cos " << c;
                    }
                }
            }
        }
    }
    // Thin films colour the reflection: over 100..400 nm on glass at normal incidence the
    // channels' ratios change, and the reflectance swings.
    float lo = 1.0f, hi = 0.0f, redOverBlueLo = 1e9f, redOverBlueHi = 0.0f;
    for (float d = 100.0f; d <= 400.0f; d += 25.0f) {
        const vec3 f = fresnelIridescence(1.0f, 1.3f, 1.0f, d, vec3(0.04f));
        lo = std::min(lo, averageComponent(f));
        hi = std::max(hi, averageComponent(f));
        const float ratio = (f.x + 1e-4f) / (f.z + 1e-4f);
        redOverBlueLo = std::min(redOverBlueLo, ratio);
        redOverBlueHi = std::max(redOverBlueHi, ratio);
    }
    EXPECT_GT(hi - lo, 0.01f);
    EXPECT_GT(redOverBlueHi, 2.0f * redOverBlueLo);
    // And with angle: a 300 nm film's colour at normal incidence is not the one at 60 degrees.
    const vec3 normal = fresnelIridescence(1.0f, 1.3f, 1.0f, 300.0f, vec3(0.04f));
    const vec3 oblique = fresnelIridescence(1.0f, 1.3f, 0.5f, 300.0f, vec3(0.04f));
    EXPECT_GT(glm::length(normal / averageComponent(normal) - oblique / averageComponent(oblique)),
              0.1f);
}

BsdfParams material(vec3 baseColor, float metallic, float roughness, float transmission = 0.0f) {
    BsdfParams m{baseColor, metallic, roughness, 1.5f, transmission, 1.0f, vec3(1.0f)};
    return m;
}

BsdfParams withFilm(BsdfParams m, float factor, float ior, float thickness) {
    m.iridescence = factor;
    m.iridescenceIor = ior;
    m.iridescenceThickness = thickness;
    return m;
}

std::vector<BsdfParams> materials() {
    return {material(vec3(0.8f, 0.5f, 0.3f), 0.0f, 0.4f), material(vec3(1.0f), 0.0f, 0.0f),
            material(vec3(1.0f, 0.78f, 0.34f), 1.0f, 0.3f), material(vec3(0.9f), 0.5f, 0.6f),
            material(vec3(1.0f), 0.0f, 0.3f, 1.0f), material(vec3(1.0f), 0.0f, 0.0f, 1.0f)};
}

TEST(IridescenceBsdf, FactorZeroIsThePlainBsdf) {
    std::mt19937 rng(7);
    for (const BsdfParams& plain : materials()) {
        const BsdfParams film = withFilm(plain, 0.0f, 2.0f, 350.0f);
        for (int i = 0; i < 400; ++i) {
            const vec3 wo = wf::test::sphereDirection(2.0f * wf::test::uniform01(rng) - 1.0f,
                                                      6.2831853f * wf::test::uniform01(rng));
            const vec3 wi = wf::test::sphereDirection(2.0f * wf::test::uniform01(rng) - 1.0f,
                                                      6.2831853f * wf::test::uniform01(rng));
            ASSERT_TRUE(sameBits(bsdfEval(film, wo, wi), bsdfEval(plain, wo, wi)));
            const float p0 = bsdfPdf(plain, wo, wi), p1 = bsdfPdf(film, wo, wi);
            ASSERT_EQ(std::memcmp(&p0, &p1, sizeof(float)), 0);
            const float uLobe = wf::test::uniform01(rng);
            const vec2 u(wf::test::uniform01(rng), wf::test::uniform01(rng));
            BsdfSample a, b;
            const bool okA = bsdfSample(plain, wo, uLobe, u, a);
            const bool okB = bsdfSample(film, wo, uLobe, u, b);
            ASSERT_EQ(okA, okB);
            if (okA) {
                ASSERT_TRUE(sameBits(a.wi, b.wi) && sameBits(a.weight, b.weight));
                ASSERT_EQ(a.pdf, b.pdf);
            }
        }
    }
}

// Directional albedo by sampling, times eta^2 (see test_bsdf.cpp).
vec3 albedo(const BsdfParams& m, vec3 wo, int n, unsigned seed, vec3* stdError) {
    std::mt19937 rng(seed);
    dvec3 sum(0.0), sum2(0.0);
    for (int i = 0; i < n; ++i) {
        BsdfSample s;
        if (bsdfSample(m, wo, wf::test::uniform01(rng),
                       vec2(wf::test::uniform01(rng), wf::test::uniform01(rng)), s)) {
            const dvec3 w = dvec3(s.weight) * double(s.eta * s.eta);
            sum += w;
            sum2 += w * w;
        }
    }
    const dvec3 mean = sum / double(n);
    *stdError = vec3(glm::sqrt(glm::max(sum2 / double(n) - mean * mean, 0.0) / double(n)));
    return vec3(mean);
}

TEST(IridescenceBsdf, WhiteFurnaceAtMostOne) {
    const std::vector<BsdfParams> whites = {
        material(vec3(1.0f), 0.0f, 0.3f), material(vec3(1.0f), 0.0f, 0.0f),
        material(vec3(1.0f), 0.0f, 0.8f), material(vec3(1.0f), 0.0f, 0.5f),
        material(vec3(1.0f), 1.0f, 0.3f),
        material(vec3(1.0f), 0.0f, 0.3f, 1.0f), material(vec3(1.0f), 0.0f, 0.0f, 1.0f)};
    unsigned seed = 1;
    float maxSeen = 0.0f;
    for (const BsdfParams& white : whites) {
        for (float ior : {1.3f, 2.0f}) {
            for (float thickness : {0.0f, 200.0f, 400.0f, 800.0f}) {
                for (float cosTheta : {0.95f, 0.6f, 0.25f, 0.08f}) {
                    const BsdfParams m = withFilm(white, 1.0f, ior, thickness);
                    const vec3 wo = wf::test::sphereDirection(cosTheta, 0.7f);
                    vec3 err;
                    const vec3 a = albedo(m, wo, cosTheta < 0.5f ? 40000 : 4000, seed++, &err);
                    for (int k = 0; k < 3; ++k) {
                        maxSeen = std::max(maxSeen, a[k] - 4.0f * err[k]);
                        EXPECT_LE(a[k], 1.0f + 4.0f * err[k] + 2e-3f)
                            << "metallic " << white.metallic << " roughness " << white.roughness
                            << " transmission " << white.transmission << " ior " << ior
                            << " thickness " << thickness << " cos " << cosTheta << " ch " << k;
                    }
                }
            }
        }
    }
    EXPECT_GT(maxSeen, 0.5f); // the furnace measured something
}

TEST(IridescenceBsdf, FilmColoursTheReflection) {
    const BsdfParams plain = material(vec3(0.0f), 0.0f, 0.0f); // black base: only the coat
    const vec3 wo = wf::test::sphereDirection(0.9f, 0.3f);
    const vec3 wi = vec3(-wo.x, -wo.y, wo.z);
    BsdfSample a, b;
    ASSERT_TRUE(bsdfSample(plain, wo, 0.5f, vec2(0.5f), a));
    ASSERT_TRUE(bsdfSample(withFilm(plain, 1.0f, 1.3f, 300.0f), wo, 0.5f, vec2(0.5f), b));
    EXPECT_TRUE(a.isDelta && b.isDelta);
    EXPECT_NEAR(a.weight.x, a.weight.z, 1e-6f);
    EXPECT_GT(std::abs(b.weight.x - b.weight.z), 0.01f);
    (void)wi;
}

} // namespace
