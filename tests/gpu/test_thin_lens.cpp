// The thin-lens camera (--aperture, --focus-distance): a tiny sphere light off the plane in
// focus images to a disc of the radius geometric optics gives, R |1 - f / z| on the focal plane
// (R the lens radius, f the focus distance, z the light's distance), with the flux of the
// pinhole image; in focus it stays as sharp as the pinhole's. Without an aperture the variant
// has no lens code, so pinhole images keep their sample numbering.
#include <cmath>

#include <gtest/gtest.h>

#include "analytic_scenes.h"
#include "gpu_test_util.h"

namespace wf::test {
namespace {

constexpr uint32_t kSize = 64;
constexpr float kYfov = 0.2f;

Scene pointOfLight(float distance, float aperture, float focus) {
    Scene scene = floorScene(0.0f); // a black floor below: only the light shows
    scene.lights.clear();
    scene.lights.push_back(sphereLight({0.0f, 1.0f, -distance}, 0.02f, glm::vec3(1.0f)));
    scene.camera = Camera{};
    scene.camera.position = {0.0f, 1.0f, 0.0f};
    scene.camera.forward = {0.0f, 0.0f, -1.0f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.yfov = kYfov;
    scene.camera.aspect = 1.0f;
    scene.camera.aperture = aperture;
    scene.camera.focusDistance = focus;
    scene.hasCamera = true;
    return scene;
}

struct Spot {
    double flux = 0.0;     // the image's sum (channels averaged)
    double meanR2 = 0.0;   // flux-weighted mean squared distance from the image centre, px^2
};

Spot measure(const Scene& scene) {
    RenderSettings settings;
    settings.width = settings.height = kSize;
    settings.samplesPerPixel = 512;
    settings.maxDepth = 1;
    const RenderResult r = renderScene(scene, settings);
    Spot spot;
    double weighted = 0.0;
    for (uint32_t y = 0; y < kSize; ++y)
        for (uint32_t x = 0; x < kSize; ++x) {
            const size_t i = size_t(y) * kSize + x;
            const double v = (r.rgb[3 * i] + r.rgb[3 * i + 1] + r.rgb[3 * i + 2]) / 3.0;
            const double dx = x + 0.5 - kSize / 2.0, dy = y + 0.5 - kSize / 2.0;
            spot.flux += v;
            weighted += v * (dx * dx + dy * dy);
        }
    spot.meanR2 = weighted / spot.flux;
    EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
    return spot;
}

TEST(ThinLens, DefocusDiscMatchesTheCircleOfConfusion) {
    const float distance = 4.0f, focus = 2.0f, aperture = 0.2f;
    const Spot pinhole = measure(pointOfLight(distance, 0.0f, 0.0f));
    const Spot lens = measure(pointOfLight(distance, aperture, focus));
    // On the focal plane the disc has radius R |1 - f / z|; that plane spans 2 f tan(fov / 2)
    // over the image's height.
    const double pixelsPerUnit = kSize / (2.0 * focus * std::tan(0.5 * kYfov));
    const double rho = 0.5 * aperture * std::abs(1.0 - focus / distance) * pixelsPerUnit;
    // A uniform disc's mean r^2 is rho^2 / 2; the pinhole image's own spread (the pixel box,
    // the sphere's size) adds to it.
    const double expected = 0.5 * rho * rho + pinhole.meanR2;
    std::printf("disc radius %.2f px: mean r^2 %.3f (expected %.3f), flux %.5f (pinhole %.5f)\n",
                rho, lens.meanR2, expected, lens.flux, pinhole.flux);
    ASSERT_GT(rho, 5.0); // the test means something: the disc spans pixels
    EXPECT_NEAR(lens.meanR2 / expected, 1.0, 0.03);
    EXPECT_NEAR(lens.flux / pinhole.flux, 1.0, 0.03);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(ThinLens, InFocusStaysSharp) {
    const float distance = 4.0f;
    const Spot pinhole = measure(pointOfLight(distance, 0.0f, 0.0f));
    const Spot lens = measure(pointOfLight(distance, 0.2f, distance));
    EXPECT_LT(lens.meanR2, 1.2 * pinhole.meanR2 + 0.05)
        << "in focus " << lens.meanR2 << ", pinhole " << pinhole.meanR2;
    EXPECT_NEAR(lens.flux / pinhole.flux, 1.0, 0.03);
}

} // namespace
} // namespace wf::test
