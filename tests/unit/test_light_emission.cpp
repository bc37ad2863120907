// The first segment of a light subpath (shaders/bidir/light_emission.h): every kind's
// throughput emitted cos / (pdfA pdfW) averages to the light's analytic power, the sampled
// directions and disk origins fit the densities the functions report, and the origins lie where
// they must (on the triangle, on the sphere, on a disk outside the scene's bounding sphere).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "chi_square.h"
#include "shaders/bidir/light_emission.h"

namespace {

using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;

using wf::test::uniform01;

const vec3 kP0(-1.0f, 0.2f, 0.5f), kP1(1.5f, -0.4f, 0.8f), kP2(0.3f, 1.2f, -0.2f);
const vec3 kSceneCenter(0.5f, -1.0f, 2.0f);
const float kSceneRadius = 3.0f;

using Emitter = std::function<EmissionSample(vec2 uPoint, vec2 uDirection)>;

// lights.glsl's sampleDeltaLight spot falloff, written out again so the header's copy is checked.
double lightsGlslFalloff(double cosAngle, double cosInner, double cosOuter) {
    double x = std::clamp((cosAngle - cosOuter) / std::max(cosInner - cosOuter, 1e-4), 0.0, 1.0);
    return x * x;
}

// The mean of emitted.x cos / (pdfA pdfW) with its standard error; it also checks that
// emissionThroughput agrees with the formula written out here.
void expectPower(const Emitter& emit, double power, unsigned seed) {
    std::mt19937 rng(seed);
    const int samples = 200000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < samples; ++i) {
        vec2 uPoint(uniform01(rng), uniform01(rng)), uDirection(uniform01(rng), uniform01(rng));
        EmissionSample s = emit(uPoint, uDirection);
        bool deltaPosition = (s.flags & WF_EMISSION_DELTA_POSITION) != 0u;
        double cosOrigin = deltaPosition ? 1.0 : double(glm::dot(s.normal, s.direction));
        double density = double(s.pdfA) * double(s.pdfW);
        double value = density > 0.0 ? s.emitted.x * cosOrigin / density : 0.0;
        ASSERT_NEAR(emissionThroughput(s).x, value, 1e-3 * std::abs(value) + 1e-6);
        sum += value;
        sum2 += value * value;
    }
    double mean = sum / samples;
    double standardError = std::sqrt(std::max(sum2 / samples - mean * mean, 0.0) / samples);
    // Some kinds have no variance at all (Le cos / (cos / pi) is constant): rounding decides.
    EXPECT_NEAR(mean, power, std::max(5.0 * standardError, 1e-3 * power));
}

TEST(LightEmission, TrianglePowerIsPiLeArea) {
    float area = 0.5f * glm::length(glm::cross(kP1 - kP0, kP2 - kP0));
    vec3 le(2.0f, 1.0f, 0.5f);
    expectPower([&](vec2 a, vec2 b) { return emitTriangle(kP0, kP1, kP2, le, false, a, b); },
                M_PI * 2.0 * area, 11);
    expectPower([&](vec2 a, vec2 b) { return emitTriangle(kP0, kP1, kP2, le, true, a, b); },
                2.0 * M_PI * 2.0 * area, 12);
}

TEST(LightEmission, SpherePowerIsPiLeFourPiRSquared) {
    const float r = 0.7f;
    expectPower([&](vec2 a, vec2 b) { return emitSphere(kSceneCenter, r, vec3(1.5f), a, b); },
                M_PI * 1.5 * 4.0 * M_PI * r * r, 13);
}

TEST(LightEmission, PointPowerIsFourPiI) {
    expectPower([](vec2, vec2 b) { return emitPoint(kP0, vec3(3.0f), b); }, 4.0 * M_PI * 3.0, 14);
}

TEST(LightEmission, SpotPowerIsTheFalloffOverTheCone) {
    const float cosInner = std::cos(0.3f), cosOuter = std::cos(0.6f);
    const double intensity = 5.0;
    // 2 pi I integral of falloff(c) dc over [cosOuter, 1], by the midpoint rule.
    const int steps = 1000000;
    double integral = 0.0, dc = (1.0 - cosOuter) / steps;
    for (int i = 0; i < steps; ++i)
        integral += lightsGlslFalloff(cosOuter + (i + 0.5) * dc, cosInner, cosOuter) * dc;
    vec3 axis = glm::normalize(vec3(0.2f, -1.0f, 0.4f));
    expectPower(
        [&](vec2, vec2 b) {
            return emitSpot(kP1, axis, vec3(float(intensity)), cosInner, cosOuter, b);
        },
        2.0 * M_PI * intensity * integral, 15);
}

TEST(LightEmission, DirectionalPowerIsIrradianceThroughTheDisk) {
    vec3 direction = glm::normalize(vec3(0.3f, -0.9f, 0.1f));
    expectPower(
        [&](vec2 a, vec2) {
            return emitDirectional(direction, vec3(2.0f), kSceneCenter, kSceneRadius, a);
        },
        2.0 * M_PI * kSceneRadius * kSceneRadius, 16);
}

TEST(LightEmission, EnvironmentPowerIsRadianceThroughTheDisk) {
    // L = 1 + y^2 drawn uniformly: pi sceneRadius^2 times the integral of L, 4 pi (1 + 1/3).
    expectPower(
        [&](vec2 a, vec2 b) {
            vec3 w = sampleUniformSphere(b);
            return emitEnvironment(w, vec3(1.0f + w.y * w.y), 0.25f / float(M_PI), kSceneCenter,
                                   kSceneRadius, a);
        },
        M_PI * kSceneRadius * kSceneRadius * 4.0 * M_PI * (4.0 / 3.0), 17);
}

// Chi-square of directions against pdf, both in the frame where `axis` is z (so a hemisphere's
// horizon falls on a cell edge); every sample's reported pdfW must equal pdf there too.
double directionFit(vec3 axis, const std::function<EmissionSample(vec2)>& emit,
                    const std::function<double(vec3)>& pdf, unsigned seed) {
    vec3 t, b;
    buildOrthonormalBasis(axis, t, b);
    wf::test::SphereGrid grid;
    const int samples = 200000;
    int misreported = 0;
    auto counts = wf::test::sampleHistogram(grid, seed, samples, [&](float, vec2 u, vec3& w) {
        EmissionSample s = emit(u);
        w = vec3(glm::dot(s.direction, t), glm::dot(s.direction, b), glm::dot(s.direction, axis));
        misreported += std::abs(s.pdfW - pdf(w)) > 1e-4 * pdf(w) + 1e-6 ? 1 : 0;
        return true;
    });
    EXPECT_EQ(misreported, 0);
    return wf::test::pdfFitPValue(counts, grid, samples, pdf);
}

TEST(LightEmission, TriangleDirectionsFitPdfW) {
    vec3 n = glm::normalize(glm::cross(kP1 - kP0, kP2 - kP0));
    vec2 uPoint(0.3f, 0.6f);
    auto oneSided = [&](vec2 u) { return emitTriangle(kP0, kP1, kP2, vec3(1), false, uPoint, u); };
    auto twoSided = [&](vec2 u) { return emitTriangle(kP0, kP1, kP2, vec3(1), true, uPoint, u); };
    EXPECT_GT(directionFit(n, oneSided, [](vec3 w) { return std::max(0.0f, w.z) / M_PI; }, 21),
              1e-3);
    EXPECT_GT(directionFit(n, twoSided, [](vec3 w) { return std::abs(w.z) / (2.0 * M_PI); }, 22),
              1e-3);
}

TEST(LightEmission, SphereDirectionsFitPdfWAboutEachPoint) {
    for (vec2 uPoint : {vec2(0.1f, 0.2f), vec2(0.5f, 0.9f), vec2(0.97f, 0.4f)}) {
        vec3 n = emitSphere(kSceneCenter, 0.7f, vec3(1), uPoint, vec2(0.5f)).normal;
        auto emit = [&](vec2 u) { return emitSphere(kSceneCenter, 0.7f, vec3(1), uPoint, u); };
        EXPECT_GT(directionFit(n, emit, [](vec3 w) { return std::max(0.0f, w.z) / M_PI; }, 23),
                  1e-3);
    }
}

// Counts in cells of (a coordinate uniform under the claimed density, angle) against
// samples x reported density x the cell's measure, plus one cell for anything outside.
double uniformCellsFit(const std::vector<vec2>& points, const std::vector<double>& densities,
                       double totalMeasure) {
    const int bins = 10, phiBins = 12;
    std::vector<double> observed(bins * phiBins + 1, 0.0), expected(bins * phiBins + 1, 0.0);
    for (size_t k = 0; k < points.size(); ++k) {
        vec2 p = points[k]; // (s in [0, 1], phi in [0, 2 pi))
        int i = int(std::floor(p.x * bins)), j = int(p.y / (2.0 * M_PI) * phiBins);
        bool inside = p.x >= 0.0f && p.x <= 1.0f + 1e-5f;
        int cell = inside ? std::min(i, bins - 1) * phiBins + std::clamp(j, 0, phiBins - 1)
                          : bins * phiBins;
        observed[cell] += 1.0;
        for (int c = 0; c < bins * phiBins; ++c)
            expected[c] += densities[k] * totalMeasure / (bins * phiBins);
    }
    return wf::test::chiSquarePValue(observed, expected);
}

TEST(LightEmission, SpotDirectionsFitPdfWInTheOuterCone) {
    const float cosOuter = std::cos(0.6f);
    vec3 axis = glm::normalize(vec3(0.2f, -1.0f, 0.4f)), t, b;
    buildOrthonormalBasis(axis, t, b);
    std::mt19937 rng(31);
    std::vector<vec2> points;
    std::vector<double> densities;
    for (int k = 0; k < 100000; ++k) {
        vec2 u(uniform01(rng), uniform01(rng));
        EmissionSample s = emitSpot(kP1, axis, vec3(1), std::cos(0.3f), cosOuter, u);
        ASSERT_EQ(s.flags, WF_EMISSION_DELTA_POSITION);
        ASSERT_EQ(s.origin, kP1);
        // (1 - cos) / (1 - cosOuter) and phi are uniform; the cone's solid angle is the measure.
        double c = glm::dot(glm::dvec3(s.direction), glm::dvec3(axis));
        double phi = std::atan2(glm::dot(s.direction, b), glm::dot(s.direction, t));
        points.push_back(vec2(float((1.0 - c) / (1.0 - cosOuter)),
                              float(phi < 0.0 ? phi + 2.0 * M_PI : phi)));
        densities.push_back(s.pdfW);
    }
    EXPECT_GT(uniformCellsFit(points, densities, 2.0 * M_PI * (1.0 - cosOuter)), 1e-3);
}

// Origins of a far light: on its disk (r^2 / R^2 and phi uniform, pdfA reported), the disk
// wholly outside the bounding sphere and its rays crossing the sphere's plane.
void checkSceneDisk(const std::function<EmissionSample(vec2)>& emit, vec3 direction) {
    vec3 t, b;
    buildOrthonormalBasis(direction, t, b);
    std::mt19937 rng(41);
    std::vector<vec2> points;
    std::vector<double> densities;
    for (int k = 0; k < 100000; ++k) {
        EmissionSample s = emit(vec2(uniform01(rng), uniform01(rng)));
        vec3 fromCenter = s.origin - kSceneCenter;
        // The plane of every origin is beyond the sphere, so is all of the disk; the centre's
        // plane lies ahead along the direction.
        float along = -glm::dot(fromCenter, direction);
        ASSERT_GT(along, kSceneRadius * 1.001f);
        ASSERT_GT(glm::dot(kSceneCenter - s.origin, s.direction), 0.0f);
        ASSERT_NEAR(glm::length(s.direction - direction), 0.0f, 1e-6f);
        ASSERT_NEAR(glm::length(s.normal - direction), 0.0f, 1e-6f);
        vec2 lateral(glm::dot(fromCenter, t), glm::dot(fromCenter, b));
        double phi = std::atan2(lateral.y, lateral.x);
        points.push_back(vec2(glm::dot(lateral, lateral) / (kSceneRadius * kSceneRadius),
                              float(phi < 0.0 ? phi + 2.0 * M_PI : phi)));
        densities.push_back(s.pdfA);
    }
    // Centred on the sphere's axis with the sphere's radius: it covers the whole silhouette.
    EXPECT_GT(uniformCellsFit(points, densities, M_PI * kSceneRadius * kSceneRadius), 1e-3);
}

TEST(LightEmission, DirectionalAndEnvironmentDisksLieOutsideTheScene) {
    vec3 direction = glm::normalize(vec3(0.3f, -0.9f, 0.1f));
    checkSceneDisk(
        [&](vec2 u) {
            EmissionSample s = emitDirectional(direction, vec3(1), kSceneCenter, kSceneRadius, u);
            EXPECT_EQ(s.flags, WF_EMISSION_DELTA_DIRECTION);
            return s;
        },
        direction);
    checkSceneDisk(
        [&](vec2 u) {
            EmissionSample s = emitEnvironment(-direction, vec3(1), 0.1f, kSceneCenter,
                                               kSceneRadius, u);
            EXPECT_EQ(s.flags, 0u);
            return s;
        },
        direction);
}

TEST(LightEmission, TrianglePointsLieUniformlyOnTheTriangle) {
    vec3 e1 = kP1 - kP0, e2 = kP2 - kP0, nl = glm::normalize(glm::cross(e1, e2));
    float d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
    // n x n sub-triangles of equal area: cell (i, j), i + j < n, and its upper half beyond the
    // diagonal; the last entry counts points outside the triangle, which expect none.
    const int n = 4, samples = 80000;
    std::vector<double> observed(2 * n * n + 1, 0.0), expected(2 * n * n + 1, 0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            expected[(i * n + j) * 2] = samples / double(n * n);
            if (i + j + 1 < n)
                expected[(i * n + j) * 2 + 1] = samples / double(n * n);
        }
    std::mt19937 rng(51);
    for (bool doubleSided : {false, true})
        for (int k = 0; k < samples / 2; ++k) {
            vec2 uPoint(uniform01(rng), uniform01(rng)), uDir(uniform01(rng), uniform01(rng));
            EmissionSample s = emitTriangle(kP0, kP1, kP2, vec3(1), doubleSided, uPoint, uDir);
            vec3 q = s.origin - kP0;
            ASSERT_NEAR(glm::dot(q, nl), 0.0f, 1e-5f);
            ASSERT_NEAR(std::abs(glm::dot(s.normal, nl)), 1.0f, 1e-5f);
            ASSERT_GE(glm::dot(s.normal, s.direction), 0.0f);
            if (!doubleSided)
                ASSERT_GT(glm::dot(s.normal, nl), 0.0f);
            float den = d00 * d11 - d01 * d01;
            float b1 = (d11 * glm::dot(q, e1) - d01 * glm::dot(q, e2)) / den;
            float b2 = (d00 * glm::dot(q, e2) - d01 * glm::dot(q, e1)) / den;
            bool inside = b1 >= -1e-5f && b2 >= -1e-5f && b1 + b2 <= 1.0f + 1e-5f;
            float x = b1 * n, y = b2 * n;
            int i = std::clamp(int(x), 0, n - 1), j = std::clamp(int(y), 0, n - 1);
            bool upper = (x - i) + (y - j) > 1.0f && i + j + 1 < n;
            observed[inside ? (i * n + j) * 2 + (upper ? 1 : 0) : 2 * n * n] += 1.0;
        }
    EXPECT_GT(wf::test::chiSquarePValue(observed, expected), 1e-3);
}

TEST(LightEmission, SpherePointsLieOnTheSphere) {
    std::mt19937 rng(61);
    const float r = 0.7f;
    for (int k = 0; k < 20000; ++k) {
        vec2 uPoint(uniform01(rng), uniform01(rng)), uDir(uniform01(rng), uniform01(rng));
        EmissionSample s = emitSphere(kSceneCenter, r, vec3(1), uPoint, uDir);
        ASSERT_NEAR(glm::length(s.origin - kSceneCenter), r, 1e-5f);
        ASSERT_NEAR(glm::length(s.normal - (s.origin - kSceneCenter) / r), 0.0f, 1e-5f);
        ASSERT_GE(glm::dot(s.normal, s.direction), 0.0f);
        ASSERT_EQ(s.flags, 0u);
    }
}

} // namespace
