// The layers' and volume's textures on the GPU (issue 48), each through a 2x1 nearest texture
// whose left texel holds 0 in the channel read and whose right one holds 1 (the other channels
// the opposite, so reading the wrong one fails): the left half of the image is the render with
// that factor at 0, the right half the factor-only render. Under a sky lit above the horizon
// only, a black base shows the layers alone: a mirror coat leaves the image's lower half black.
// And the coat's own normal map tilts the coat's reflection only where it is tilted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analytic_scenes.h"
#include "gpu_test_util.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_materials.h"
#include "scene/gltf/gltf_primitives.h"

namespace wf::test {
namespace {

constexpr uint32_t SIZE = 16;

RenderSettings settings(uint32_t spp) {
    RenderSettings s;
    s.width = s.height = SIZE;
    s.samplesPerPixel = spp;
    s.maxDepth = 2; // camera, surface, sky
    return s;
}

float skyAboveHorizon(uint32_t row) { return row < 16 ? 1.0f : 0.0f; }

// Channels set in `zeroLeft` are 0 in the left texel and 1 in the right one; the others the
// opposite. ABGR in memory: R is the low byte.
TextureImage halves(uint32_t zeroLeft) {
    uint32_t left = 0, right = 0;
    for (uint32_t k = 0; k < 4; ++k)
        ((zeroLeft >> k & 1u) ? right : left) |= 0xffu << (8 * k);
    TextureImage image;
    image.width = 2;
    image.height = 1;
    image.rgba = {left, right};
    return image;
}
constexpr uint32_t R = 1, G = 2, B = 4, A = 8;

// Adds `image` with one nearest reference to it (sRGB or not); returns the reference.
uint32_t addTexture(Scene& scene, const TextureImage& image, bool srgb = false) {
    scene.surface.images.push_back(image);
    TextureRef ref{};
    ref.uRow = glm::vec3(1, 0, 0);
    ref.vRow = glm::vec3(0, 1, 0);
    ref.flags = WF_TEXTURE_NEAREST | (srgb ? WF_TEXTURE_SRGB : 0u);
    scene.surface.textureRefs.push_back(ref);
    scene.surface.refImage.push_back(uint32_t(scene.surface.images.size() - 1));
    return uint32_t(scene.surface.textureRefs.size() - 1);
}

// A quad filling the view at z = -1, u from 0 (left) to 1 (right), with vertex normals and a
// tangent frame along +x (for normal maps), under the sky lit above the horizon.
Scene quadScene(const Material& m) {
    Scene scene;
    scene.materials.push_back(m);
    const glm::vec3 a(-0.5f, -0.5f, -1.0f), b(0.5f, -0.5f, -1.0f), c(0.5f, 0.5f, -1.0f),
        d(-0.5f, 0.5f, -1.0f);
    scene.triangles.push_back({a, 0, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, 0, c, WF_NO_EMITTER, d, 0});
    scene.surface.uv0.push_back({{0, 1}, {1, 1}, {1, 0}});
    scene.surface.uv0.push_back({{0, 1}, {1, 0}, {0, 0}});
    const uint32_t n = gltf::octEncode(glm::vec3(0, 0, 1)), t = gltf::octEncode({1, 0, 0});
    for (int i = 0; i < 2; ++i) {
        scene.surface.normals.push_back({n, n, n, 0u});
        scene.surface.tangents.push_back({t, t, t, 0u});
    }
    scene.environment = rowEnvironment(4, 32, skyAboveHorizon);
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.forward = glm::vec3(0, 0, -1);
    scene.camera.up = glm::vec3(0, 1, 0);
    scene.camera.yfov = 2.0f * std::atan(0.5f);
    scene.hasCamera = true;
    return scene;
}

// A black surface that reflects nothing of its own: only the layers show.
Material blackBase() {
    Material m = gltf::defaultMaterial();
    m.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    m.specular = 0.0f;
    return m;
}

// Mean of one channel over the quarter (left or right half; top or bottom half, or both),
// one pixel in from the edges and the middle.
double quarter(const RenderResult& r, bool right, int rows, int channel = 0) {
    double sum = 0.0;
    int n = 0;
    for (uint32_t y = 1; y < SIZE - 1; ++y) {
        const bool top = y < SIZE / 2;
        if ((rows == 0 && !top) || (rows == 1 && top) || y == SIZE / 2 - 1 || y == SIZE / 2)
            continue;
        for (uint32_t x = right ? SIZE / 2 + 1 : 1; x < (right ? SIZE - 1 : SIZE / 2 - 1); ++x) {
            sum += r.rgb[3 * (y * SIZE + x) + channel];
            ++n;
        }
    }
    return sum / n;
}
constexpr int TOP = 0, BOTTOM = 1, BOTH = 2;

// The largest value in the half, one pixel in from the image's edges.
double largest(const RenderResult& r, bool right) {
    double m = 0.0;
    for (uint32_t y = 1; y < SIZE - 1; ++y)
        for (uint32_t x = right ? SIZE / 2 : 1; x < (right ? SIZE - 1 : SIZE / 2); ++x)
            for (int k = 0; k < 3; ++k)
                m = std::max(m, double(r.rgb[3 * (y * SIZE + x) + k]));
    return m;
}

// The textured render's half equals the reference's there, within `tolerance` of its value;
// and the two references differ by far more in `rows` (so the check can fail).
void expectHalvesMatch(const char* what, const RenderResult& textured, const RenderResult& zero,
                       const RenderResult& factor, int rows, int channel = 0) {
    const double left = quarter(textured, false, rows, channel);
    const double right = quarter(textured, true, rows, channel);
    const double zeroLeft = quarter(zero, false, rows, channel);
    const double factorRight = quarter(factor, true, rows, channel);
    const double zeroRight = quarter(zero, true, rows, channel);
    std::printf("%s: left %.5f (factor 0: %.5f), right %.5f (factor only: %.5f; factor 0 there "
                "%.5f)\n",
                what, left, zeroLeft, right, factorRight, zeroRight);
    const double tolerance = 0.03 * std::max(zeroLeft, factorRight) + 1e-5;
    EXPECT_NEAR(left, zeroLeft, tolerance) << what;
    EXPECT_NEAR(right, factorRight, tolerance) << what;
    EXPECT_GT(std::abs(factorRight - zeroRight), 5.0 * tolerance) << what << ": no contrast";
}

TEST(LayerTextures, ClearcoatTextureScalesTheCoat) {
    Material coat = blackBase();
    coat.clearcoat = 1.0f;
    coat.clearcoatRoughness = 0.3f;
    Scene scene = quadScene(coat);
    scene.materials[0].clearcoatTexture = addTexture(scene, halves(R));
    const RenderSettings s = settings(16);
    const RenderResult textured = renderScene(scene, s);
    EXPECT_EQ(largest(textured, false), 0.0) << "clearcoatTexture R = 0 leaves no coat";
    Material none = blackBase();
    const RenderResult zero = renderScene(quadScene(none), s);
    const RenderResult factor = renderScene(quadScene(coat), s);
    expectHalvesMatch("clearcoatTexture", textured, zero, factor, BOTH);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// G = 0 makes the coat a mirror: the sky below the horizon is black, so is the lower left.
TEST(LayerTextures, ClearcoatRoughnessTextureScalesTheRoughness) {
    Material coat = blackBase();
    coat.clearcoat = 1.0f;
    coat.clearcoatRoughness = 0.6f;
    Scene scene = quadScene(coat);
    scene.materials[0].clearcoatRoughnessTexture = addTexture(scene, halves(G));
    const RenderSettings s = settings(16);
    const RenderResult textured = renderScene(scene, s);
    Material mirror = coat;
    mirror.clearcoatRoughness = 0.0f;
    const RenderResult zero = renderScene(quadScene(mirror), s);
    const RenderResult factor = renderScene(quadScene(coat), s);
    EXPECT_EQ(quarter(textured, false, BOTTOM), 0.0) << "a mirror coat under a dark lower sky";
    expectHalvesMatch("clearcoatRoughnessTexture (bottom)", textured, zero, factor, BOTTOM);
    expectHalvesMatch("clearcoatRoughnessTexture (top)", textured, zero, factor, TOP);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// sRGB colour: 0 on the left (no sheen at all), white on the right (the factor's colour).
TEST(LayerTextures, SheenColorTextureScalesTheColor) {
    Material sheen = blackBase();
    sheen.sheenColor = glm::vec3(1.0f, 0.5f, 0.25f);
    sheen.sheenRoughness = 0.5f;
    Scene scene = quadScene(sheen);
    scene.materials[0].sheenColorTexture = addTexture(scene, halves(R | G | B), true);
    const RenderSettings s = settings(16);
    const RenderResult textured = renderScene(scene, s);
    EXPECT_EQ(largest(textured, false), 0.0) << "sheenColorTexture 0 leaves no sheen";
    const RenderResult zero = renderScene(quadScene(blackBase()), s);
    const RenderResult factor = renderScene(quadScene(sheen), s);
    for (int k = 0; k < 3; ++k)
        expectHalvesMatch("sheenColorTexture", textured, zero, factor, BOTH, k);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(LayerTextures, SheenRoughnessTextureScalesTheRoughness) {
    Material sheen = blackBase();
    sheen.sheenColor = glm::vec3(1.0f);
    sheen.sheenRoughness = 0.8f;
    Scene scene = quadScene(sheen);
    scene.materials[0].sheenRoughnessTexture = addTexture(scene, halves(A));
    const RenderSettings s = settings(16);
    const RenderResult textured = renderScene(scene, s);
    Material smooth = sheen;
    smooth.sheenRoughness = 0.0f;
    const RenderResult zero = renderScene(quadScene(smooth), s);
    const RenderResult factor = renderScene(quadScene(sheen), s);
    expectHalvesMatch("sheenRoughnessTexture", textured, zero, factor, BOTH);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// An index-matched absorbing box (test_material_layers' Beer-Lambert case), the thickness
// texture read where rays leave it: G = 0 is thin-walled (no absorption, exactly), G = 1 the
// factor's absorption.
Scene absorbingSlab(const Material& glass) {
    Scene scene;
    scene.materials.push_back(glass);
    const float h = 0.5f;
    // Six faces, counter-clockwise from outside, u = x + 0.5 and v = 0.5 - y everywhere.
    auto uv = [&](glm::vec3 p) { return glm::vec2(p.x + h, h - p.y); };
    auto face = [&](glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
        scene.triangles.push_back({p0, 0, p1, WF_NO_EMITTER, p2, 0});
        scene.triangles.push_back({p0, 0, p2, WF_NO_EMITTER, p3, 0});
        scene.surface.uv0.push_back({uv(p0), uv(p1), uv(p2)});
        scene.surface.uv0.push_back({uv(p0), uv(p2), uv(p3)});
    };
    const glm::vec3 lo(-h), hi(h);
    face({lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}); // +z
    face({hi.x, lo.y, lo.z}, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}); // -z
    face({hi.x, lo.y, hi.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}); // +x
    face({lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z}); // -x
    face({lo.x, hi.y, hi.z}, {hi.x, hi.y, hi.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z}); // +y
    face({lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}); // -y
    scene.environment = rowEnvironment(1, 1, nullptr);
    scene.environment.rgb = {1.0f, 1.0f, 1.0f};
    scene.camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
    scene.camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.camera.yfov = 0.1f; // every ray crosses the front and back faces
    scene.hasCamera = true;
    return scene;
}

TEST(LayerTextures, ThicknessTextureSwitchesAbsorption) {
    Material glass = gltf::defaultMaterial();
    glass.baseColor = glm::vec4(1.0f);
    glass.roughness = 0.0f;
    glass.transmission = 1.0f;
    glass.ior = 1.0f;
    glass.specular = 0.0f;
    glass.attenuation = glm::vec3(-std::log(0.5f), -std::log(0.25f), -std::log(0.8f));
    glass.thickness = 1.0f;
    Scene scene = absorbingSlab(glass);
    scene.materials[0].thicknessTexture = addTexture(scene, halves(G));
    RenderSettings s = settings(4);
    s.maxDepth = 5;
    const RenderResult textured = renderScene(scene, s);
    EXPECT_EQ(textured.stats.nonFiniteSamples, 0u);
    Material thin = glass;
    thin.thickness = 0.0f;
    const RenderResult zero = renderScene(absorbingSlab(thin), s);
    const RenderResult factor = renderScene(absorbingSlab(glass), s);
    for (int k = 0; k < 3; ++k)
        expectHalvesMatch("thicknessTexture", textured, zero, factor, BOTH, k);
    for (uint32_t y = 0; y < SIZE; ++y)
        for (uint32_t x = 0; x < SIZE / 2; ++x)
            EXPECT_NEAR(textured.rgb[3 * (y * SIZE + x) + 1], 1.0f, 1e-4f) << x << ", " << y;
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// A smooth coat over a black base mirrors the sky: without a map of its own, the lower half of
// the image sees the dark lower sky. The coat's normal map, flat on the left and tilted 30
// degrees up on the right, leaves the left as it was and turns the right's mirror upwards, to
// the lit sky: the lower right lights up.
TEST(LayerTextures, ClearcoatNormalTextureTiltsTheCoat) {
    Material coat = blackBase();
    coat.clearcoat = 1.0f;
    coat.clearcoatRoughness = 0.0f;
    Scene scene = quadScene(coat);
    TextureImage map = halves(0);
    map.rgba = {0xffff8080u, 0xffeebf80u}; // (128, 128, 255) | (128, 191, 238): m.y 0.5
    scene.materials[0].clearcoatNormalTexture = addTexture(scene, map);
    const RenderSettings s = settings(8);
    const RenderResult textured = renderScene(scene, s);
    const RenderResult factor = renderScene(quadScene(coat), s);
    const double left[2] = {quarter(textured, false, TOP), quarter(textured, false, BOTTOM)};
    const double plain[2] = {quarter(factor, false, TOP), quarter(factor, false, BOTTOM)};
    const double right = quarter(textured, true, BOTTOM), plainRight = quarter(factor, true, BOTTOM);
    std::printf("coat normal map: left %.5f %.5f (plain %.5f %.5f), lower right %.5f (plain "
                "%.5f)\n",
                left[0], left[1], plain[0], plain[1], right, plainRight);
    EXPECT_NEAR(left[0], plain[0], 0.02 * plain[0]);
    EXPECT_EQ(left[1], 0.0);
    EXPECT_EQ(plainRight, 0.0);
    // Schlick(0.04) at the tilted mirror's cos 30 degrees, the sky's 1 above.
    EXPECT_NEAR(right, 0.04 + 0.96 * std::pow(1.0 - std::cos(0.5236), 5.0), 0.004);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
