// Spawned rays must never re-hit the surface they leave, at any scale: triangles from 1e-6 to
// 1e6 across, placed from 1e-6 to 1e6 away from the origin, long and skinny ones included.
// The control test shows the raw hit point does self-intersect, so the main test can fail.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "shaders/traversal/geometry.h"
#include "shaders/sampling/sampling.h"

namespace {

using glm::dvec3;
using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;

const float INF = std::numeric_limits<float>::infinity();
constexpr int TRIALS = 200000;

struct Case {
    vec3 p0, p1, p2;
    vec3 n;      // float geometric normal, as a renderer computes it
    dvec3 exactN; // unnormalised normal of the float vertices, in double
    vec3 p, pError, w; // pError: hit point only (pbrt-v4's bound)
    float b1, b2;
};

// Random triangle, hit point and outgoing direction; false when the triangle is degenerate
// at float precision (its float normal is not its normal), which no offset can rescue.
bool makeCase(std::mt19937& rng, Case& c) {
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> gauss;
    auto randomDir = [&] { return glm::normalize(dvec3(gauss(rng), gauss(rng), gauss(rng))); };
    double scale = std::pow(10.0, -6.0 + 12.0 * uniform(rng));
    double distance = uniform(rng) < 0.1 ? 0.0 : std::pow(10.0, -6.0 + 12.0 * uniform(rng));
    dvec3 t = distance * randomDir();
    dvec3 q0 = t + scale * randomDir(), q1, q2;
    if (uniform(rng) < 0.3) { // long and skinny: width 1e-4 .. 1e-1 of the length
        dvec3 axis = randomDir(), side = glm::normalize(glm::cross(axis, randomDir()));
        double width = std::pow(10.0, -4.0 + 3.0 * uniform(rng));
        q1 = q0 + scale * axis;
        q2 = q0 + scale * (uniform(rng) * axis + width * side);
    } else {
        q1 = t + scale * randomDir();
        q2 = t + scale * randomDir();
    }
    c.p0 = vec3(q0);
    c.p1 = vec3(q1);
    c.p2 = vec3(q2);
    c.exactN = glm::cross(dvec3(c.p1) - dvec3(c.p0), dvec3(c.p2) - dvec3(c.p0));
    vec3 cr = glm::cross(c.p1 - c.p0, c.p2 - c.p0);
    float len = glm::length(cr);
    if (!(len > 0.0f) || !std::isfinite(len) || glm::length(c.exactN) == 0.0) {
        return false;
    }
    c.n = cr / len;
    if (glm::dot(dvec3(c.n), glm::normalize(c.exactN)) < 0.999) {
        return false;
    }
    vec2 b = sampleUniformTriangle(vec2(float(uniform(rng)), float(uniform(rng))));
    c.b1 = b.x;
    c.b2 = b.y;
    c.p = triangleHitPoint(c.p0, c.p1, c.p2, b.x, b.y);
    c.pError = triangleHitPointError(c.p0, c.p1, c.p2, b.x, b.y);
    c.w = vec3(randomDir()); // either hemisphere, grazing ones included
    return glm::dot(c.w, c.n) != 0.0f;
}

TEST(RayOffset, SpawnedRaysNeverHitTheirOwnTriangle) {
    std::mt19937 rng(12345u);
    int valid = 0, selfHits = 0, wrongSide = 0;
    for (int i = 0; i < TRIALS; ++i) {
        Case c;
        if (!makeCase(rng, c)) {
            continue;
        }
        ++valid;
        vec3 spawnError = triangleSpawnError(c.p0, c.p1, c.p2, c.b1, c.b2);
        vec3 o = offsetRayOrigin(c.p, spawnError, c.n, c.w);
        float t, b1, b2;
        if (intersectTriangle(o, c.w, c.p0, c.p1, c.p2, INF, t, b1, b2)) {
            if (++selfHits <= 5) {
                ADD_FAILURE() << "self-hit at t=" << t << " p0=(" << c.p0.x << "," << c.p0.y
                              << "," << c.p0.z << ") |p1-p0|=" << glm::length(c.p1 - c.p0);
            }
        }
        // The origin must sit strictly on the side w leaves towards, judged in double
        // against the float vertices' exact plane.
        double side = glm::dot(dvec3(o) - dvec3(c.p0), c.exactN);
        bool wantPositive = glm::dot(c.w, c.n) > 0.0f;
        if (side == 0.0 || (side > 0.0) != wantPositive) {
            if (++wrongSide <= 5) {
                ADD_FAILURE() << "origin on the wrong side: " << side;
            }
        }
    }
    EXPECT_GT(valid, TRIALS * 9 / 10) << "too many triangles degenerate at float precision";
    EXPECT_EQ(selfHits, 0) << "of " << valid;
    EXPECT_EQ(wrongSide, 0) << "of " << valid;
}

TEST(RayOffset, RawHitPointsDoSelfIntersect) {
    // Control: spawning from the unoffset hit point must self-hit at a visible rate, or the
    // test above proves nothing.
    std::mt19937 rng(777u);
    int valid = 0, selfHits = 0;
    for (int i = 0; i < TRIALS / 4; ++i) {
        Case c;
        if (!makeCase(rng, c)) {
            continue;
        }
        ++valid;
        float t, b1, b2;
        selfHits += intersectTriangle(c.p, c.w, c.p0, c.p1, c.p2, INF, t, b1, b2);
    }
    EXPECT_GT(selfHits, valid / 20) << selfHits << " self-hits of " << valid;
}

TEST(RayOffset, HitPointBoundAloneIsNotEnoughForNeedles) {
    // Why triangleSpawnError adds triangleIntersectSlack: with pbrt's hit-point bound alone,
    // Möller-Trumbore's own rounding still re-hits thin triangles. Should this start passing
    // with zero self-hits, the intersector became more robust and the slack can be revisited.
    std::mt19937 rng(4242u);
    int valid = 0, selfHits = 0;
    for (int i = 0; i < TRIALS / 4; ++i) {
        Case c;
        if (!makeCase(rng, c)) {
            continue;
        }
        ++valid;
        vec3 o = offsetRayOrigin(c.p, c.pError, c.n, c.w);
        float t, b1, b2;
        selfHits += intersectTriangle(o, c.w, c.p0, c.p1, c.p2, INF, t, b1, b2);
    }
    EXPECT_GT(selfHits, 0) << "of " << valid;
}

TEST(RayOffset, NextFloatStepsOneUlpAcrossZero) {
    EXPECT_EQ(nextFloatUp(0.0f), std::numeric_limits<float>::denorm_min());
    EXPECT_EQ(nextFloatUp(-0.0f), std::numeric_limits<float>::denorm_min());
    EXPECT_EQ(nextFloatDown(0.0f), -std::numeric_limits<float>::denorm_min());
    EXPECT_EQ(nextFloatDown(-0.0f), -std::numeric_limits<float>::denorm_min());
    EXPECT_EQ(nextFloatUp(-std::numeric_limits<float>::denorm_min()), 0.0f);
    EXPECT_EQ(nextFloatUp(1.0f), std::nextafter(1.0f, 2.0f));
    EXPECT_EQ(nextFloatDown(1.0f), std::nextafter(1.0f, 0.0f));
    EXPECT_EQ(nextFloatUp(-1.0f), std::nextafter(-1.0f, 0.0f));
    EXPECT_EQ(nextFloatDown(-1.0f), std::nextafter(-1.0f, -2.0f));
    EXPECT_EQ(nextFloatUp(INF), INF);
    EXPECT_EQ(nextFloatDown(-INF), -INF);
    EXPECT_EQ(nextFloatUp(std::numeric_limits<float>::max()), INF);
}

TEST(RayOffset, OffsetFollowsTheErrorBound) {
    // A zero bound means p is exact: it stays put. Otherwise it moves along n towards w's side,
    // and only along n.
    vec3 p(1.0f, 2.0f, 3.0f), n(0.0f, 0.0f, 1.0f);
    vec3 up = offsetRayOrigin(p, vec3(0.0f), n, vec3(0.0f, 0.0f, 1.0f));
    vec3 down = offsetRayOrigin(p, vec3(0.0f), n, vec3(0.0f, 0.0f, -1.0f));
    EXPECT_EQ(up, p);
    EXPECT_EQ(down, p);
    vec3 moved = offsetRayOrigin(p, vec3(1e-7f), n, vec3(0.3f, 0.0f, -1.0f));
    EXPECT_LT(moved.z, 3.0f);
    EXPECT_EQ(moved.x, 1.0f);
    EXPECT_EQ(moved.y, 2.0f);
}

} // namespace
