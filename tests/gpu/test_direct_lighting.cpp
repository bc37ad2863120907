// The light-agreement tests' closed forms (direct_lighting.h) against brute-force quadrature
// over the light's surface, E = L * integral of cos(at p) cos(at the light) / r^2 dA, on the
// CPU: above, across and below the horizon.
#include <cmath>

#include <gtest/gtest.h>

#include "direct_lighting.h"

namespace wf::test {
namespace {

// Midpoint rule over the sphere in (z, phi), which is uniform in area: dA = R dz dphi.
double sphereByQuadrature(glm::dvec3 p, glm::dvec3 n, glm::dvec3 center, double radius) {
    const int steps = 1500;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < 2 * steps; ++j) {
            const double z = -1.0 + 2.0 * (i + 0.5) / steps, phi = M_PI * (j + 0.5) / steps;
            const double s = std::sqrt(1.0 - z * z);
            const glm::dvec3 normal(s * std::cos(phi), s * std::sin(phi), z);
            const glm::dvec3 toLight = center + radius * normal - p;
            const double r2 = glm::dot(toLight, toLight), r = std::sqrt(r2);
            const double cosLight = -glm::dot(normal, toLight) / r;
            const double cosHere = glm::dot(n, toLight) / r;
            if (cosLight > 0.0 && cosHere > 0.0)
                sum += cosHere * cosLight / r2;
        }
    const double dA = radius * (2.0 / steps) * radius * (M_PI / steps);
    return sum * dA;
}

double quadByQuadrature(glm::dvec3 p, glm::dvec3 n, glm::dvec3 corner, glm::dvec3 u,
                        glm::dvec3 v) {
    const int steps = 2000;
    const glm::dvec3 front = glm::normalize(glm::cross(u, v));
    double sum = 0.0;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const glm::dvec3 toLight = corner + u * ((i + 0.5) / steps) + v * ((j + 0.5) / steps) - p;
            const double r2 = glm::dot(toLight, toLight), r = std::sqrt(r2);
            const double cosLight = -glm::dot(front, toLight) / r;
            const double cosHere = glm::dot(n, toLight) / r;
            if (cosLight > 0.0 && cosHere > 0.0)
                sum += cosHere * cosLight / r2;
        }
    return sum * glm::length(glm::cross(u, v)) / (double(steps) * steps);
}

TEST(DirectLighting, SphereMatchesQuadrature) {
    const glm::dvec3 p(0.0), up(0, 1, 0);
    struct Case {
        glm::dvec3 center;
        double radius;
    } cases[] = {
        {{0.3, 2.0, -0.2}, 0.5},   // wholly above the horizon
        {{1.5, 0.2, 0.0}, 0.5},    // across it, centre above
        {{1.5, -0.3, 0.4}, 0.5},   // across it, centre below
        {{0.0, 1.05, 0.0}, 1.0},   // almost touching: nearly 2 pi
        {{2.0, -0.6, 0.0}, 0.5},   // wholly below
    };
    for (const Case& c : cases) {
        const double exact = sphereIrradiance(p, up, c.center, c.radius, 1.0);
        const double quadrature = sphereByQuadrature(p, up, c.center, c.radius);
        EXPECT_NEAR(exact, quadrature, 2e-4 * std::max(quadrature, 1e-3))
            << "centre " << c.center.x << " " << c.center.y << " " << c.center.z;
    }
    EXPECT_EQ(sphereIrradiance(p, up, {0.0, 0.2, 0.0}, 0.5, 1.0), 0.0); // inside
}

TEST(DirectLighting, PolygonMatchesQuadrature) {
    const glm::dvec3 p(0.0), up(0, 1, 0);
    struct Case {
        glm::dvec3 corner, u, v;
    } cases[] = {
        {{-0.2, 1.0, -0.3}, {0.5, 0.0, 0.0}, {0.0, 0.0, 0.4}}, // overhead, facing down
        {{-0.5, -0.3, -1.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}}, // a wall across the horizon
        {{-0.4, 0.01, -0.5}, {0.8, 0.0, 0.0}, {0.0, 0.5, 0.5}}, // leaning, 1 cm above
    };
    for (const Case& c : cases) {
        const glm::dvec3 corners[4] = {c.corner, c.corner + c.u, c.corner + c.u + c.v,
                                       c.corner + c.v};
        const double exact = polygonIrradiance(p, up, corners, 4, 1.0);
        const double quadrature = quadByQuadrature(p, up, c.corner, c.u, c.v);
        EXPECT_NEAR(exact, quadrature, 1e-3 * quadrature);
        // Seen from behind, a one-sided emitter gives nothing.
        const glm::dvec3 reversed[4] = {corners[0], corners[3], corners[2], corners[1]};
        EXPECT_EQ(polygonIrradiance(p, up, reversed, 4, 1.0), 0.0);
    }
}

TEST(DirectLighting, DiracLights) {
    const glm::dvec3 p(0.0), up(0, 1, 0), light(0.3, 2.0, -0.4);
    const double d = glm::length(light);
    EXPECT_NEAR(pointIrradiance(p, up, light, 5.0), 5.0 * 2.0 / (d * d * d), 1e-12);
    // Inside the inner cone, full intensity; outside the outer, none; between, the ramp squared.
    const glm::dvec3 down = glm::normalize(-light);
    EXPECT_DOUBLE_EQ(spotIrradiance(p, up, light, down, 0.99, 0.9, 5.0),
                     pointIrradiance(p, up, light, 5.0));
    const glm::dvec3 aside = glm::normalize(glm::dvec3(1.0, 0.0, 0.0));
    EXPECT_EQ(spotIrradiance(p, up, light, aside, 0.99, 0.9, 5.0), 0.0);
    EXPECT_NEAR(directionalIrradiance(up, glm::normalize(glm::dvec3(1, -1, 0)), 2.0),
                std::sqrt(2.0), 1e-12);
}

} // namespace
} // namespace wf::test
