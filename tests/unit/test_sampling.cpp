// Chi-square goodness-of-fit tests of the shared warps (shaders/sampling/sampling.h) against the
// densities the renderer divides by, plus negative controls proving the test can fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "chi_square.h"
#include "shaders/sampling/sampling.h"

namespace {

using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;

using wf::test::chiSquarePValue;

constexpr int COS_BINS = 10;
constexpr int PHI_BINS = 20;
constexpr int HEMISPHERE_SAMPLES = 1000000;

// Bins directions by (cos theta, phi) and integrates `pdf` over each cell with Simpson's rule
// (d omega = d cos(theta) d phi), then returns the p-value of the warp against that pdf.
double hemisphereFit(const std::function<float(float)>& pdf) {
    std::mt19937 rng(20240601u);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<double> observed(COS_BINS * PHI_BINS, 0.0), expected(observed.size(), 0.0);
    for (int i = 0; i < HEMISPHERE_SAMPLES; ++i) {
        vec3 w = sampleCosineHemisphere(vec2(uniform(rng), uniform(rng)));
        double phi = std::atan2(double(w.y), double(w.x));
        phi = phi < 0.0 ? phi + 2.0 * M_PI : phi;
        int ci = std::clamp(int(w.z * COS_BINS), 0, COS_BINS - 1);
        int pi = std::clamp(int(phi / (2.0 * M_PI) * PHI_BINS), 0, PHI_BINS - 1);
        observed[ci * PHI_BINS + pi] += 1.0;
    }
    const int steps = 8; // Simpson sub-intervals per cell and dimension (even)
    for (int ci = 0; ci < COS_BINS; ++ci) {
        for (int pi = 0; pi < PHI_BINS; ++pi) {
            double c0 = double(ci) / COS_BINS, hc = 1.0 / COS_BINS / steps;
            double hp = 2.0 * M_PI / PHI_BINS / steps;
            double sum = 0.0;
            for (int a = 0; a <= steps; ++a) {
                double wa = (a == 0 || a == steps) ? 1.0 : (a % 2 ? 4.0 : 2.0);
                for (int b = 0; b <= steps; ++b) {
                    double wb = (b == 0 || b == steps) ? 1.0 : (b % 2 ? 4.0 : 2.0);
                    sum += wa * wb * pdf(float(c0 + a * hc)); // pdf does not depend on phi
                }
            }
            expected[ci * PHI_BINS + pi] = sum * hc * hp / 9.0 * HEMISPHERE_SAMPLES;
        }
    }
    return chiSquarePValue(observed, expected);
}

TEST(Sampling, CosineHemisphereMatchesItsPdf) {
    EXPECT_GT(hemisphereFit(cosineHemispherePdf), 1e-3);
}

TEST(Sampling, ChiSquareRejectsWrongPdf) {
    // Uniform-hemisphere density: the cosine sampler must be told apart from it.
    EXPECT_LT(hemisphereFit([](float) { return 0.5f * WF_INV_PI; }), 1e-3);
}

TEST(Sampling, CosineHemisphereSamplesAreUnitAndUp) {
    std::mt19937 rng(7u);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (int i = 0; i < 10000; ++i) {
        vec3 w = sampleCosineHemisphere(vec2(uniform(rng), uniform(rng)));
        EXPECT_GE(w.z, 0.0f);
        EXPECT_NEAR(glm::length(w), 1.0f, 1e-5f);
    }
    EXPECT_EQ(sampleCosineHemisphere(vec2(0.5f)), vec3(0.0f, 0.0f, 1.0f));
}

// Splits the triangle into N^2 congruent sub-triangles of the barycentric grid (equal areas,
// so each expects samples / N^2) and tests a barycentric warp against uniform area.
double triangleFit(const std::function<vec2(vec2)>& warp) {
    const int n = 12, samples = 500000;
    std::mt19937 rng(99u);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    // Cell (i, j, upper): lower triangles exist for i + j <= n - 1, upper ones for <= n - 2.
    std::vector<double> observed(2 * n * n, 0.0), expected(observed.size(), 0.0);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            expected[(i * n + j) * 2] = i + j <= n - 1 ? double(samples) / (n * n) : 0.0;
            expected[(i * n + j) * 2 + 1] = i + j <= n - 2 ? double(samples) / (n * n) : 0.0;
        }
    }
    for (int s = 0; s < samples; ++s) {
        vec2 b = warp(vec2(uniform(rng), uniform(rng)));
        EXPECT_TRUE(b.x >= 0.0f && b.y >= 0.0f && b.x + b.y <= 1.0f) << b.x << " " << b.y;
        int i = std::clamp(int(b.x * n), 0, n - 1), j = std::clamp(int(b.y * n), 0, n - 1);
        bool upper = (b.x * n - i) + (b.y * n - j) >= 1.0f && i + j <= n - 2;
        observed[(i * n + j) * 2 + (upper ? 1 : 0)] += 1.0;
    }
    return chiSquarePValue(observed, expected);
}

TEST(Sampling, UniformTriangleIsUniformInArea) {
    EXPECT_GT(triangleFit(sampleUniformTriangle), 1e-3);
}

TEST(Sampling, ChiSquareRejectsNonUniformTriangleWarp) {
    // The classic mistake: b1 = u, b2 = v (1 - u) crowds samples towards the p2 corner.
    EXPECT_LT(triangleFit([](vec2 u) { return vec2(u.x, u.y * (1.0f - u.x)); }), 1e-3);
}

TEST(Sampling, OrthonormalBasisIsRightHandedAndOrthonormal) {
    std::mt19937 rng(3u);
    std::normal_distribution<float> gauss;
    // The poles and n.z = -0, where the basis switches branch.
    std::vector<vec3> normals = {vec3(0, 0, 1), vec3(0, 0, -1), vec3(1, 0, 0), vec3(1, 0, -0.0f)};
    for (int i = 0; i < 10000; ++i) {
        normals.push_back(glm::normalize(vec3(gauss(rng), gauss(rng), gauss(rng))));
    }
    for (vec3 n : normals) {
        vec3 t, b;
        buildOrthonormalBasis(n, t, b);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::length(b), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t, b), 0.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-5f);
        EXPECT_LT(glm::length(glm::cross(t, b) - n), 1e-5f);
    }
}

TEST(Sampling, PowerHeuristicEdgeCases) {
    const float inf = std::numeric_limits<float>::infinity();
    EXPECT_EQ(powerHeuristic(0.0f, 0.0f), 1.0f);
    EXPECT_EQ(powerHeuristic(2.0f, 0.0f), 1.0f);
    EXPECT_EQ(powerHeuristic(0.0f, 2.0f), 0.0f);
    EXPECT_EQ(powerHeuristic(inf, 1.0f), 1.0f);
    EXPECT_EQ(powerHeuristic(1.0f, inf), 0.0f);
    EXPECT_EQ(powerHeuristic(inf, inf), 0.5f);
    EXPECT_EQ(powerHeuristic(FLT_MAX, FLT_MAX), 0.5f);
    EXPECT_FLOAT_EQ(powerHeuristic(1.0f, 1.0f), 0.5f);
    EXPECT_FLOAT_EQ(powerHeuristic(3.0f, 1.0f), 0.9f);
    EXPECT_FLOAT_EQ(powerHeuristic(1e30f, 1e29f), 100.0f / 101.0f); // a^2 would overflow
    const float values[] = {0.0f, 1e-45f, 1e-38f, 1e-20f, 0.5f, 1.0f, 1e20f, FLT_MAX, inf};
    for (float a : values) {
        for (float b : values) {
            float w = powerHeuristic(a, b);
            EXPECT_TRUE(w >= 0.0f && w <= 1.0f) << a << " " << b << " -> " << w;
            if (b != 0.0f && a != 0.0f) {
                EXPECT_NEAR(w + powerHeuristic(b, a), 1.0f, 1e-6f) << a << " " << b;
            }
        }
    }
}

} // namespace
