// Ray-cone texture LOD (shaders/surface/ray_cones.h, as the shaders run it) against the level a
// rasteriser's rule picks from exact screen-space derivatives: a textured plane at a known
// distance and tilt, seen through the image's centre pixel, gets that level within 0.5.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "shaders/surface/ray_cones.h"

namespace wf {
namespace {

using gpu_types::coneAfterBounce;
using gpu_types::coneFootprint;
using gpu_types::coneTextureLod;
using gpu_types::coneWidthAt;

struct TexturedPlane {
    glm::vec3 centre, normal, axisU, axisV;
    float side;     // world units the texture spans
    float texels;   // texels per side
    // uv in [0, 1]^2 of a point of the plane.
    glm::vec2 uv(const glm::vec3& p) const {
        return glm::vec2(glm::dot(p - centre, axisU), glm::dot(p - centre, axisV)) / side + 0.5f;
    }
};

TexturedPlane tiltedPlane(float distance, float tilt, float side, float texels) {
    TexturedPlane plane;
    plane.centre = glm::vec3(0.0f, 0.0f, -distance);
    plane.normal = glm::vec3(0.0f, std::sin(tilt), std::cos(tilt));
    plane.axisU = glm::vec3(1.0f, 0.0f, 0.0f);
    plane.axisV = glm::cross(plane.normal, plane.axisU);
    plane.side = side;
    plane.texels = texels;
    return plane;
}

// Where the camera ray through image-plane point (x, y) at distance 1 meets the plane.
glm::vec3 hit(const TexturedPlane& plane, float x, float y) {
    const glm::vec3 d = glm::normalize(glm::vec3(x, y, -1.0f));
    return d * (glm::dot(plane.centre, plane.normal) / glm::dot(d, plane.normal));
}

// The rasteriser's level: log2 of the longer of the texel-space derivatives along x and y,
// by central differences over one pixel `pixel` (in image-plane units).
float derivativeLod(const TexturedPlane& plane, float pixel) {
    auto texel = [&](float x, float y) { return plane.uv(hit(plane, x, y)) * plane.texels; };
    const glm::vec2 dx = (texel(pixel, 0) - texel(-pixel, 0)) * 0.5f;
    const glm::vec2 dy = (texel(0, pixel) - texel(0, -pixel)) * 0.5f;
    return std::log2(std::max(glm::length(dx), glm::length(dy)));
}

// The cone's level for the centre pixel: the quantities loadSurface and textureLod have.
float coneLod(const TexturedPlane& plane, float tanHalfFovY, uint32_t height, uint32_t levels) {
    const glm::vec3 p0 = plane.centre - 0.5f * plane.side * (plane.axisU + plane.axisV);
    const glm::vec3 p1 = p0 + plane.side * plane.axisU, p2 = p1 + plane.side * plane.axisV;
    const glm::vec2 t0 = plane.uv(p0), t1 = plane.uv(p1), t2 = plane.uv(p2);
    const glm::vec2 e1 = t1 - t0, e2 = t2 - t0;
    const float texelArea2 = std::abs(e1.x * e2.y - e1.y * e2.x) * plane.texels * plane.texels;
    const float worldArea2 = glm::length(glm::cross(p1 - p0, p2 - p0));
    const glm::vec3 at = hit(plane, 0.0f, 0.0f);
    const float width = coneWidthAt(gpu_types::cameraCone(tanHalfFovY, height), glm::length(at));
    const float cosTheta = glm::dot(plane.normal, -glm::normalize(at));
    return coneTextureLod(coneFootprint(width, cosTheta, worldArea2), texelArea2, levels);
}

TEST(RayCones, PlaneAtKnownDistanceAndTiltPicksTheRasterisersLevel) {
    const float tanHalfFovY = std::tan(0.4f);
    const uint32_t height = 64;
    const float pixel = 2.0f * tanHalfFovY / height;
    for (float distance : {2.0f, 10.0f, 40.0f}) {
        for (float tilt : {0.0f, 0.5f, 1.0f}) { // up to 57 degrees
            for (float texels : {256.0f, 2048.0f}) {
                const TexturedPlane plane = tiltedPlane(distance, tilt, 4.0f, texels);
                const float expected = derivativeLod(plane, pixel);
                if (expected < 0.5f || expected > 10.0f)
                    continue; // magnified or past the chain: clamped, checked below
                EXPECT_NEAR(coneLod(plane, tanHalfFovY, height, 12), expected, 0.5f)
                    << "distance " << distance << " tilt " << tilt << " texels " << texels;
                if (tilt == 0.0f) // facing the camera the two rules agree exactly
                    EXPECT_NEAR(coneLod(plane, tanHalfFovY, height, 12), expected, 0.01f);
            }
        }
    }
}

TEST(RayCones, LevelIsClampedToTheChainAndFinite) {
    const float tanHalfFovY = std::tan(0.4f);
    EXPECT_EQ(coneLod(tiltedPlane(0.01f, 0.0f, 4.0f, 64.0f), tanHalfFovY, 64, 7), 0.0f);
    EXPECT_EQ(coneLod(tiltedPlane(1e6f, 0.0f, 4.0f, 64.0f), tanHalfFovY, 64, 7), 6.0f);
    EXPECT_EQ(coneTextureLod(0.0f, 0.0f, 7), 0.0f);            // no width, no UV area
    EXPECT_EQ(coneTextureLod(INFINITY, 0.0f, 7), 0.0f);        // inf x 0: NaN
    EXPECT_EQ(coneTextureLod(NAN, 16.0f, 7), 0.0f);
    EXPECT_EQ(coneTextureLod(1.0f, INFINITY, 7), 6.0f);
    const float grazing = coneFootprint(1.0f, 0.0f, 1.0f);
    EXPECT_TRUE(std::isfinite(grazing));
}

TEST(RayCones, SpreadGrowsByTheSampledLobesWidth) {
    const glm::vec2 cone(0.0f, 0.01f);
    EXPECT_FLOAT_EQ(coneWidthAt(cone, 3.0f), 0.03f);
    // A Dirac bounce keeps the spread; the width carries on from the hit.
    EXPECT_EQ(coneAfterBounce(cone, 0.03f, 0.0f), glm::vec2(0.03f, 0.01f));
    // Near a GGX lobe's peak at normal incidence pdf = 1 / (4 pi alpha^2): about 4 alpha.
    for (float alpha : {0.01f, 0.05f, 0.1f}) {
        const float pdf = 1.0f / (4.0f * 3.14159265f * alpha * alpha);
        EXPECT_NEAR(coneAfterBounce(cone, 0.03f, pdf).y - cone.y, 4.0f * alpha, 1e-4f);
    }
    // Lambert at normal incidence (pdf 1 / pi) widens by 2 rad, capped at pi / 2.
    EXPECT_FLOAT_EQ(coneAfterBounce(cone, 0.03f, 1.0f / 3.14159265f).y, WF_MAX_CONE_SPREAD);
}

} // namespace
} // namespace wf
