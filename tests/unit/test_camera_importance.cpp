// The camera's importance and densities (shaders/bidir/camera_importance.h) against the rays
// wave/camera_ray.glsl issues: We integrates to 1 over lens and image, every camera ray maps
// back to the raster point it came from, the direction density fits the rays' distribution,
// points off the image are refused, and light tracing with the documented splat factor
// reproduces the path tracer's box-filtered pixel means.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "chi_square.h"
#include "shaders/bidir/camera_importance.h"

namespace {

using glm::uvec2;
using glm::vec2;
using glm::vec3;
using namespace wf::gpu_types;

using wf::test::uniform01;

// A tilted camera, 64x48 at 60 degrees vertical field: wide enough that cos^3 and cos^4 differ
// by a third at the corners. lensRadius 0 is the pinhole.
CameraGeometry testCamera(float lensRadius, uint width = 64u, uint height = 48u) {
    CameraGeometry c{};
    c.position = vec3(1.0f, 2.0f, 3.0f);
    c.forward = glm::normalize(vec3(0.3f, -0.2f, -1.0f));
    c.right = glm::normalize(glm::cross(c.forward, vec3(0.0f, 1.0f, 0.0f)));
    c.up = glm::cross(c.right, c.forward);
    c.tanHalfFovY = std::tan(float(M_PI) / 6.0f);
    c.width = width;
    c.height = height;
    c.aspect = float(width) / float(height);
    c.lensRadius = lensRadius;
    c.focusDistance = 4.0f;
    c.orthoHalfHeight = 0.0f;
    return c;
}

struct CameraRaySample {
    vec3 origin;
    vec3 direction;
};

// wave/camera_ray.glsl's few lines, replicated: jitter is the box filter's point in the pixel,
// uLens the WF_DIM_LENS sample.
CameraRaySample cameraRayReplica(const CameraGeometry& c, uvec2 pixel, vec2 jitter, vec2 uLens) {
    vec2 ndc = (vec2(pixel) + jitter) / vec2(c.width, c.height) * 2.0f - 1.0f;
    vec3 d = c.forward + c.right * (ndc.x * c.tanHalfFovY * c.aspect) -
             c.up * (ndc.y * c.tanHalfFovY);
    if (c.lensRadius <= 0.0f)
        return {c.position, glm::normalize(d)};
    vec2 lens = c.lensRadius * sampleConcentricDisk(uLens);
    vec3 origin = c.position + c.right * lens.x + c.up * lens.y;
    return {origin, glm::normalize(c.position + d * c.focusDistance - origin)};
}

// The world direction at (cos theta, phi) about the camera's forward axis.
vec3 cameraDirection(const CameraGeometry& c, double cosTheta, double phi) {
    vec3 l = wf::test::sphereDirection(cosTheta, phi);
    return glm::normalize(c.right * l.x + c.up * l.y + c.forward * l.z);
}

// Cosine of a cone about forward that holds every ray from any lens point to the image.
double coneCosine(const CameraGeometry& c) {
    double tanCorner = c.tanHalfFovY * std::sqrt(double(c.aspect) * c.aspect + 1.0);
    if (c.lensRadius > 0.0f)
        tanCorner += c.lensRadius / c.focusDistance;
    return 1.0 / std::sqrt(1.0 + 1.1 * 1.1 * tanCorner * tanCorner);
}

// Monte Carlo of the integral of We(p, w) cos(theta) over lens area and solid angle: uniform
// directions in the cone, uniform lens points. Returns {mean, standard error}.
std::pair<double, double> importanceIntegral(const CameraGeometry& c, int samples) {
    std::mt19937 rng(46u);
    const double cosMax = coneCosine(c), conePdf = 1.0 / (2.0 * M_PI * (1.0 - cosMax));
    double sum = 0.0, squares = 0.0;
    for (int i = 0; i < samples; ++i) {
        vec3 lensPoint = cameraLensPoint(c, vec2(uniform01(rng), uniform01(rng)));
        double cosTheta = 1.0 - uniform01(rng) * (1.0 - cosMax);
        vec3 w = cameraDirection(c, cosTheta, 2.0 * M_PI * uniform01(rng));
        double f = cameraImportance(c, lensPoint, w) * glm::dot(w, c.forward) /
                   (conePdf * cameraLensPdf(c));
        sum += f;
        squares += f * f;
    }
    double mean = sum / samples;
    return {mean, std::sqrt((squares / samples - mean * mean) / (samples - 1))};
}

TEST(CameraImportance, IntegratesToOneOverLensAndImage) {
    for (float lensRadius : {0.0f, 0.25f}) {
        auto [mean, se] = importanceIntegral(testCamera(lensRadius), 2000000);
        EXPECT_LT(se, 2e-3) << "lens " << lensRadius; // tight enough to tell cos^4 from cos^3
        EXPECT_NEAR(mean, 1.0, 5.0 * se) << "lens " << lensRadius;
    }
}

TEST(CameraImportance, CameraRaysMapBackToTheirRasterPoint) {
    std::mt19937 rng(7u);
    for (float lensRadius : {0.0f, 0.25f}) {
        const CameraGeometry c = testCamera(lensRadius);
        // Float precision of a raster coordinate near the image's far edge, with headroom for
        // the normalisations and dot products in between.
        const float tolerance = 16.0f * float(c.width) * 0x1p-23f;
        for (int i = 0; i < 20000; ++i) {
            uvec2 pixel(std::min(uint(uniform01(rng) * c.width), c.width - 1u),
                        std::min(uint(uniform01(rng) * c.height), c.height - 1u));
            vec2 jitter(uniform01(rng), uniform01(rng)), uLens(uniform01(rng), uniform01(rng));
            CameraRaySample ray = cameraRayReplica(c, pixel, jitter, uLens);
            vec2 expected = vec2(pixel) + jitter;
            EXPECT_LT(glm::length(cameraLensPoint(c, uLens) - ray.origin), 1e-6f);
            vec2 raster;
            ASSERT_TRUE(cameraRasterOfRay(c, ray.origin, ray.direction, raster));
            ASSERT_NEAR(raster.x, expected.x, tolerance) << "lens " << lensRadius;
            ASSERT_NEAR(raster.y, expected.y, tolerance) << "lens " << lensRadius;
            // A light vertex anywhere along the ray, nearer or farther than the plane in focus.
            float distance = 0.3f + 20.0f * uniform01(rng);
            vec3 w;
            float dist2;
            ASSERT_TRUE(cameraRasterOfPoint(c, ray.origin, ray.origin + ray.direction * distance,
                                            w, raster, dist2));
            ASSERT_NEAR(raster.x, expected.x, tolerance) << "lens " << lensRadius;
            ASSERT_NEAR(raster.y, expected.y, tolerance) << "lens " << lensRadius;
            ASSERT_NEAR(std::sqrt(dist2), distance, 1e-5f * distance);
            ASSERT_LT(glm::length(w - ray.direction), 1e-5f);
        }
    }
}

// Chi-square p-value of camera-ray directions from a fixed lens point (uniform raster points
// over the whole image) against cameraDirectionPdf, in (cos theta, phi) cells about forward.
double directionFit(const CameraGeometry& c, vec2 uLens, int samples) {
    const int cosBins = 16, phiBins = 32;
    const double cosMax = coneCosine(c);
    std::mt19937 rng(11u);
    std::vector<double> observed(cosBins * phiBins, 0.0), expected(observed.size(), 0.0);
    auto cellOf = [&](vec3 w) {
        double cosTheta = glm::dot(w, c.forward);
        double phi = std::atan2(double(glm::dot(w, c.up)), double(glm::dot(w, c.right)));
        phi = phi < 0.0 ? phi + 2.0 * M_PI : phi;
        int ci = std::clamp(int((cosTheta - cosMax) / (1.0 - cosMax) * cosBins), 0, cosBins - 1);
        int pi = std::clamp(int(phi / (2.0 * M_PI) * phiBins), 0, phiBins - 1);
        return ci * phiBins + pi;
    };
    for (int i = 0; i < samples; ++i) {
        vec2 raster(uniform01(rng) * c.width, uniform01(rng) * c.height);
        uvec2 pixel = glm::min(uvec2(raster), uvec2(c.width - 1u, c.height - 1u));
        CameraRaySample ray = cameraRayReplica(c, pixel, raster - vec2(pixel), uLens);
        observed[cellOf(ray.direction)] += 1.0;
    }
    const vec3 lensPoint = cameraLensPoint(c, uLens);
    wf::test::detail::Integrand pdf = [&](double cosTheta, double phi) {
        return double(cameraDirectionPdf(c, lensPoint, cameraDirection(c, cosTheta, phi)));
    };
    const double dc = (1.0 - cosMax) / cosBins, dp = 2.0 * M_PI / phiBins;
    for (int ci = 0; ci < cosBins; ++ci) {
        for (int pi = 0; pi < phiBins; ++pi) {
            double c0 = cosMax + ci * dc, p0 = pi * dp;
            double whole = wf::test::detail::simpson2(pdf, c0, c0 + dc, p0, p0 + dp);
            // The image's edges cut cells: refine to well under a sample per cell.
            expected[ci * phiBins + pi] =
                samples * wf::test::detail::adaptiveSimpson2(pdf, c0, c0 + dc, p0, p0 + dp, whole,
                                                             0.02 / samples, 10);
        }
    }
    return wf::test::chiSquarePValue(observed, expected);
}

TEST(CameraImportance, DirectionPdfFitsCameraRays) {
    EXPECT_GT(directionFit(testCamera(0.0f), vec2(0.5f), 1000000), 1e-3);
    // An off-centre lens point sees the plane in focus obliquely.
    EXPECT_GT(directionFit(testCamera(0.25f), vec2(0.9f, 0.2f), 1000000), 1e-3);
}

TEST(CameraImportance, RefusesPointsBehindOrOffTheImage) {
    for (float lensRadius : {0.0f, 0.25f}) {
        const CameraGeometry c = testCamera(lensRadius);
        const vec3 lensPoint = cameraLensPoint(c, vec2(0.5f));
        vec3 w;
        vec2 raster;
        float dist2;
        const vec3 ahead = c.position + 3.0f * c.forward;
        EXPECT_TRUE(cameraRasterOfPoint(c, lensPoint, ahead, w, raster, dist2));
        EXPECT_GT(cameraImportance(c, lensPoint, w), 0.0f);
        EXPECT_GT(cameraDirectionPdf(c, lensPoint, w), 0.0f);
        for (vec3 point : {c.position - 3.0f * c.forward,               // behind
                           c.position + 2.0f * c.right,                 // in the lens plane
                           c.position - 2.0f * c.forward + c.right,     // behind, off-axis
                           lensPoint}) {                                 // on the lens itself
            EXPECT_FALSE(cameraRasterOfPoint(c, lensPoint, point, w, raster, dist2));
            EXPECT_EQ(cameraImportance(c, lensPoint, w), 0.0f);
        }
        EXPECT_EQ(cameraImportance(c, lensPoint, -c.forward), 0.0f);
        EXPECT_EQ(cameraDirectionPdf(c, lensPoint, -c.forward), 0.0f);
        // Just past each edge of the image, at the plane in focus (where the lens point does
        // not matter), and just inside.
        const float x = c.tanHalfFovY * c.aspect * c.focusDistance;
        const float y = c.tanHalfFovY * c.focusDistance;
        const vec3 centre = c.position + c.forward * c.focusDistance;
        for (float s : {1.001f, 0.999f}) {
            for (vec3 edge : {c.right * x, -c.right * x, c.up * y, -c.up * y}) {
                bool on = cameraRasterOfPoint(c, lensPoint, centre + s * edge, w, raster, dist2);
                EXPECT_EQ(on, s < 1.0f) << "lens " << lensRadius << " scale " << s;
                EXPECT_EQ(cameraImportance(c, lensPoint, w) > 0.0f, s < 1.0f);
                EXPECT_EQ(cameraDirectionPdf(c, lensPoint, w) > 0.0f, s < 1.0f);
            }
        }
    }
    // Nearer than the plane in focus, a point just inside the right edge from the centre is
    // off the image through the lens's left rim: that ray keeps drifting right until in focus.
    const CameraGeometry c = testCamera(0.25f);
    const vec3 near = c.position + 2.0f * (c.forward + 0.95f * c.tanHalfFovY * c.aspect * c.right);
    vec3 w;
    vec2 raster;
    float dist2;
    EXPECT_TRUE(cameraRasterOfPoint(c, c.position + 0.25f * c.right, near, w, raster, dist2));
    EXPECT_FALSE(cameraRasterOfPoint(c, c.position - 0.25f * c.right, near, w, raster, dist2));
    EXPECT_EQ(cameraImportance(c, c.position - 0.25f * c.right, w), 0.0f);
}

TEST(CameraImportance, OnlyPerspectiveCamerasConnect) {
    CameraGeometry c = testCamera(0.0f);
    EXPECT_TRUE(cameraConnectable(c));
    EXPECT_TRUE(cameraConnectable(testCamera(0.25f)));
    c.orthoHalfHeight = 2.0f;
    EXPECT_FALSE(cameraConnectable(c));
}

// L(y) of a Lambertian emitter on the plane facing the camera at distance 5: smooth, varied.
float emitted(vec2 planePoint) {
    return 1.0f + 0.5f * std::sin(2.0f * planePoint.x) * std::cos(3.0f * planePoint.y);
}

// Light tracing of that emitter (uniform points on a rectangle larger than the view, one
// connection to a lens point each) splatted with cameraSplatScale into a film divided by the
// samples per pixel, against the path tracer's pixel means of the same scene.
TEST(CameraImportance, LightTracingSplatsReproducePixelMeans) {
    for (float lensRadius : {0.0f, 0.25f}) {
        const CameraGeometry c = testCamera(lensRadius, 8u, 6u);
        const uint pixels = c.width * c.height;
        const float depth = 5.0f, halfX = 5.0f, halfY = 4.0f; // holds the view, lens blur too
        const vec3 centre = c.position + depth * c.forward;
        auto planeOf = [&](vec3 p) {
            return vec2(glm::dot(p - centre, c.right), glm::dot(p - centre, c.up));
        };
        // The path tracer's film: each pixel's mean over a stratified grid of jitter x lens.
        std::vector<double> reference(pixels, 0.0);
        const int n = 12;
        for (uint p = 0; p < pixels; ++p)
            for (int a = 0; a < n * n; ++a)
                for (int b = 0; b < (lensRadius > 0.0f ? n * n : 1); ++b) {
                    vec2 jitter((a % n + 0.5f) / n, (a / n + 0.5f) / n);
                    vec2 uLens((b % n + 0.5f) / n, (b / n + 0.5f) / n);
                    auto ray = cameraRayReplica(c, uvec2(p % c.width, p / c.width), jitter, uLens);
                    float t = depth / glm::dot(ray.direction, c.forward) -
                              glm::dot(ray.origin - c.position, c.forward);
                    reference[p] += emitted(planeOf(ray.origin + t * ray.direction)) /
                                    (n * n * (lensRadius > 0.0f ? n * n : 1));
                }
        // Light tracing: passes of `pixels` light paths each, so cameraSplatScale is 1.
        const int passes = 20000;
        const float lightPdf = 1.0f / (4.0f * halfX * halfY);
        std::vector<double> sum(pixels, 0.0), squares(pixels, 0.0), pass(pixels);
        std::mt19937 rng(5u);
        for (int s = 0; s < passes; ++s) {
            std::fill(pass.begin(), pass.end(), 0.0);
            for (uint k = 0; k < pixels; ++k) {
                vec2 q((2.0f * uniform01(rng) - 1.0f) * halfX,
                       (2.0f * uniform01(rng) - 1.0f) * halfY);
                vec3 y = centre + c.right * q.x + c.up * q.y;
                vec3 lensPoint = cameraLensPoint(c, vec2(uniform01(rng), uniform01(rng)));
                vec3 w;
                vec2 raster;
                float dist2;
                if (!cameraRasterOfPoint(c, lensPoint, y, w, raster, dist2))
                    continue;
                float cosCamera = glm::dot(w, c.forward), cosLight = cosCamera; // planes parallel
                float splat = emitted(q) * cameraImportance(c, lensPoint, w) * cosCamera *
                              cosLight / dist2 / (lightPdf * cameraLensPdf(c)) *
                              cameraSplatScale(c, float(pixels));
                ASSERT_TRUE(raster.x >= 0.0f && raster.x < float(c.width) && raster.y >= 0.0f &&
                            raster.y < float(c.height));
                pass[uint(raster.y) * c.width + uint(raster.x)] += splat;
            }
            for (uint p = 0; p < pixels; ++p) {
                sum[p] += pass[p];
                squares[p] += pass[p] * pass[p];
            }
        }
        for (uint p = 0; p < pixels; ++p) {
            double mean = sum[p] / passes; // the film's splat sum over the samples per pixel
            double se = std::sqrt((squares[p] / passes - mean * mean) / (passes - 1));
            EXPECT_LT(se, 0.015 * reference[p]) << "pixel " << p;
            EXPECT_NEAR(mean, reference[p], 5.0 * se + 1e-3 * reference[p])
                << "pixel " << p << " lens " << lensRadius;
        }
    }
}

} // namespace
