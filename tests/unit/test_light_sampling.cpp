// The light-sampling warps (shaders/lights/light_sampling.h) against their densities:
// spherical triangles uniform in solid angle, cones uniform in solid angle, the equirectangular
// density integrating to one, and the solid angle formula against brute force.
#include <random>

#include <gtest/gtest.h>

#include "chi_square.h"
#include "shaders/lights/light_sampling.h"

namespace wf {
namespace {

using namespace gpu_types;

// Barycentric sub-triangle index of a point in a triangle cut into n x n sub-triangles.
int subTriangle(vec2 b, int n) {
    // (b1, b2) in the unit right triangle; cell (i, j) with i + j < n, split by the diagonal.
    float x = b.x * n, y = b.y * n;
    int i = std::clamp(int(x), 0, n - 1), j = std::clamp(int(y), 0, n - 1);
    // Rounding can put a point on the hypotenuse a hair outside: it belongs to the edge cell.
    bool upper = (x - i) + (y - j) > 1.0f && i + j + 1 < n;
    return (i * n + j) * 2 + (upper ? 1 : 0);
}

// Chi-square of sampleSphericalTriangle seen from `p`: each sub-triangle should receive a share
// of the samples equal to its solid angle over the whole triangle's.
double sphericalTriangleFit(vec3 p, vec3 p0, vec3 p1, vec3 p2, bool wrongDensity) {
    const int n = 8;
    std::vector<double> expected(2 * n * n, 0.0), observed(2 * n * n, 0.0);
    const float total = triangleSolidAngle(p, p0, p1, p2);
    auto corner = [&](float b1, float b2) { return p0 + b1 * (p1 - p0) + b2 * (p2 - p0); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; i + j < n; ++j) {
            float b1 = float(i) / n, b2 = float(j) / n, h = 1.0f / n;
            expected[(i * n + j) * 2] = triangleSolidAngle(p, corner(b1, b2), corner(b1 + h, b2),
                                                           corner(b1, b2 + h)) / total;
            if (i + j + 1 < n)
                expected[(i * n + j) * 2 + 1] = triangleSolidAngle(
                    p, corner(b1 + h, b2), corner(b1 + h, b2 + h), corner(b1, b2 + h)) / total;
        }
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const int samples = 200000;
    vec3 nl = normalize(cross(p1 - p0, p2 - p0));
    for (int k = 0; k < samples; ++k) {
        vec2 u(uniform(rng), uniform(rng));
        if (wrongDensity)
            u.x = u.x * u.x; // skews the sub-area choice: must be rejected
        vec3 d = sampleSphericalTriangle(normalize(p0 - p), normalize(p1 - p), normalize(p2 - p),
                                         triangleSolidAngle(p, p0, p1, p2), u);
        float t = dot(p0 - p, nl) / dot(d, nl);
        vec3 q = p + t * d - p0;
        // Barycentrics of q by least squares in the triangle's plane.
        vec3 e1 = p1 - p0, e2 = p2 - p0;
        float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
        float d20 = dot(q, e1), d21 = dot(q, e2), den = d00 * d11 - d01 * d01;
        vec2 b((d11 * d20 - d01 * d21) / den, (d00 * d21 - d01 * d20) / den);
        observed[subTriangle(b, n)] += 1.0;
    }
    for (double& e : expected)
        e *= samples;
    return test::chiSquarePValue(observed, expected);
}

TEST(LightSampling, SphericalTriangleIsUniformInSolidAngle) {
    EXPECT_GT(sphericalTriangleFit({0.1f, 0.2f, 0.0f}, {-1, -1, 2}, {2, -0.5f, 1.5f},
                                   {0.3f, 1.5f, 1.0f}, false),
              1e-3);
    // Large and close: the case where area sampling is worst.
    EXPECT_GT(sphericalTriangleFit({0.0f, 0.0f, 0.0f}, {-3, 0.3f, -3}, {3, 0.3f, -3},
                                   {0, 0.3f, 3}, false),
              1e-3);
}

TEST(LightSampling, ChiSquareRejectsASkewedSphericalTriangleWarp) {
    EXPECT_LT(sphericalTriangleFit({0.1f, 0.2f, 0.0f}, {-1, -1, 2}, {2, -0.5f, 1.5f},
                                   {0.3f, 1.5f, 1.0f}, true),
              1e-6);
}

TEST(LightSampling, TriangleSolidAngleMatchesBruteForce) {
    vec3 p(0.2f, -0.1f, 0.0f), p0(-1, -1, 2), p1(2, -0.5f, 1.5f), p2(0.3f, 1.5f, 1.0f);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    vec3 nl = normalize(cross(p1 - p0, p2 - p0));
    int hits = 0;
    const int samples = 400000;
    for (int k = 0; k < samples; ++k) {
        vec3 d = sampleUniformSphere(vec2(uniform(rng), uniform(rng)));
        float t = dot(p0 - p, nl) / dot(d, nl);
        if (!(t > 0.0f))
            continue;
        vec3 q = p + t * d;
        vec3 c0 = cross(p1 - p0, q - p0), c1 = cross(p2 - p1, q - p1), c2 = cross(p0 - p2, q - p2);
        hits += (dot(c0, nl) >= 0 && dot(c1, nl) >= 0 && dot(c2, nl) >= 0) ? 1 : 0;
    }
    double estimate = 4.0 * M_PI * hits / samples;
    double sigma = 4.0 * M_PI * std::sqrt(double(hits)) / samples;
    EXPECT_NEAR(triangleSolidAngle(p, p0, p1, p2), estimate, 4.0 * sigma);
}

// Cone sampling: (1 - cos theta) / (1 - cos thetaMax) and phi must both be uniform.
double coneFit(float oneMinusCosMax, bool wrong) {
    const int bins = 10, phiBins = 12;
    std::vector<double> observed(bins * phiBins, 0.0), expected(bins * phiBins, 0.0);
    vec3 axis = normalize(vec3(0.3f, -0.5f, 0.8f)), t, b;
    buildOrthonormalBasis(axis, t, b);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const int samples = 120000;
    for (int k = 0; k < samples; ++k) {
        vec2 u(uniform(rng), uniform(rng));
        if (wrong)
            u.x = std::sqrt(u.x);
        vec3 d = sampleCone(axis, oneMinusCosMax, u);
        // 1 - cos from the sine, in double: for a tiny cone 1 - dot() would be all rounding.
        glm::dvec3 dd(d), da(axis);
        double sin2 = glm::dot(glm::cross(dd, da), glm::cross(dd, da));
        double s = sin2 / (1.0 + std::sqrt(1.0 - sin2)) / oneMinusCosMax;
        double phi = std::atan2(dot(d, b), dot(d, t));
        phi = phi < 0 ? phi + 2 * M_PI : phi;
        int i = std::clamp(int(s * bins), 0, bins - 1);
        int j = std::clamp(int(phi / (2 * M_PI) * phiBins), 0, phiBins - 1);
        observed[i * phiBins + j] += 1.0;
    }
    for (double& e : expected)
        e = double(samples) / (bins * phiBins);
    return test::chiSquarePValue(observed, expected);
}

TEST(LightSampling, ConeIsUniformInSolidAngle) {
    EXPECT_GT(coneFit(sphereConeOneMinusCos(1.0f, 1.02f), false), 1e-3); // almost a hemisphere
    EXPECT_GT(coneFit(sphereConeOneMinusCos(0.01f, 3.0f), false), 1e-3); // a small light
    EXPECT_LT(coneFit(0.3f, true), 1e-6);
}

TEST(LightSampling, SmallSphereConeIsStable) {
    // 1 - cos for a sphere seen at 1e4 radii: no cancellation to zero.
    float value = sphereConeOneMinusCos(1.0f, 1e4f);
    EXPECT_NEAR(value, 0.5e-8f, 1e-12f);
}

TEST(LightSampling, EquirectRoundTripAndDensity) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int k = 0; k < 1000; ++k) {
        vec3 d = sampleUniformSphere(vec2(uniform(rng), uniform(rng)));
        vec3 back = equirectToDirection(directionToEquirect(d));
        EXPECT_NEAR(glm::length(back - d), 0.0f, 1e-4f);
    }
    // A uniform density over (u, v) maps to a solid-angle density that integrates to one.
    test::SphereGrid grid;
    auto cells = test::integrateOverCells(
        grid, [](glm::vec3 d) { return double(equirectSolidAnglePdf(1.0f, d)); }, 1e-5);
    double total = 0.0;
    for (double c : cells)
        total += c;
    EXPECT_NEAR(total, 1.0, 2e-3);
}

} // namespace
} // namespace wf
