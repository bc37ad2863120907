// Frame sequences reuse one renderer (WavefrontRenderer::setScene: the pipelines stay, the
// tables are replaced) and refit the last built tree (FrameScenes). Held against the fresh
// path, a new prepareScene and a new renderer per frame, over a scene whose every kind of
// motion matters: a deforming box (a skin or morph target's effect), an emissive panel gliding
// overhead (the light table changes, and with a refit its triangles keep the first frame's
// order) and a static floor.
//  - rebuild: every frame bit for bit the fresh render (same tree, same shaders, same seed);
//  - refit: every later frame refit, each 8x8 region within 5 standard errors of a fresh
//    reference (the refit tree orders triangles, and so the emitter table, differently);
//  - a frame that needs other shaders (a point light appears) is refused by setScene.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu/context.h"
#include "gpu_test_util.h"
#include "render/gpu_scene/frame_scenes.h"

namespace wf::test {
namespace {

Material lambert(glm::vec3 color, glm::vec3 emission = glm::vec3(0.0f)) {
    Material m{};
    m.baseColor = glm::vec4(color, 1.0f);
    m.emission = emission;
    m.roughness = 1.0f;
    m.ior = 1.5f;
    m.specular = 0.0f;
    m.specularColor = glm::vec3(1.0f);
    return m;
}

void addQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t mat) {
    scene.triangles.push_back({a, mat, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, mat, c, WF_NO_EMITTER, d, 0});
}

// The scene at time t in [0, 1].
Scene sceneAt(double t) {
    Scene scene;
    scene.materials = {lambert(glm::vec3(0.7f)), lambert(glm::vec3(0.8f, 0.3f, 0.2f)),
                       lambert(glm::vec3(0.0f), glm::vec3(6.0f))};
    addQuad(scene, {-3, 0, -3}, {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, 0);
    // The box stretches upwards and leans over as t grows (its corners move differently).
    const float h = 0.5f + float(t), lean = 0.6f * float(t);
    const glm::vec3 c[8] = {{-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {0.5f, 0, 0.5f},
                            {-0.5f, 0, 0.5f},  {-0.5f + lean, h, -0.5f}, {0.5f + lean, h, -0.5f},
                            {0.5f + lean, h, 0.5f}, {-0.5f + lean, h, 0.5f}};
    const int faces[6][4] = {{0, 1, 2, 3}, {7, 6, 5, 4}, {0, 4, 5, 1},
                             {1, 5, 6, 2}, {2, 6, 7, 3}, {3, 7, 4, 0}};
    for (const auto& f : faces)
        addQuad(scene, c[f[0]], c[f[1]], c[f[2]], c[f[3]], 1);
    // The panel faces down (counter-clockwise seen from below) and glides along x.
    const float x = -1.0f + 2.0f * float(t);
    addQuad(scene, {x - 0.4f, 2.5f, -0.4f}, {x + 0.4f, 2.5f, -0.4f}, {x + 0.4f, 2.5f, 0.4f},
            {x - 0.4f, 2.5f, 0.4f}, 2);
    scene.camera.position = glm::vec3(0.0f, 1.5f, 5.0f);
    scene.camera.forward = glm::normalize(glm::vec3(0.0f, -0.25f, -1.0f));
    scene.camera.up = glm::normalize(
        glm::cross(glm::cross(scene.camera.forward, glm::vec3(0, 1, 0)), scene.camera.forward));
    scene.camera.yfov = 0.8f;
    scene.hasCamera = true;
    return scene;
}

const double kTimes[] = {0.0, 0.3, 0.6, 0.9};

RenderSettings frameSettings() {
    RenderSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.maxDepth = 3;
    settings.samplesPerPixel = 16;
    settings.seed = 5;
    return settings;
}

TEST(FrameReuse, RebuildIsTheFreshRenderBitForBit) {
    static ShaderCompiler compiler;
    const RenderSettings settings = frameSettings();
    FrameScenes scenes(FrameBvh::Rebuild);
    std::unique_ptr<WavefrontRenderer> renderer;
    for (double t : kTimes) {
        const PreparedScene& prepared = scenes.prepare(sceneAt(t));
        EXPECT_FALSE(scenes.refitted());
        if (!renderer)
            renderer = std::make_unique<WavefrontRenderer>(gpuContext(), prepared, settings,
                                                           compiler);
        else
            ASSERT_TRUE(renderer->setScene(prepared)) << "t = " << t;
        renderer->render();
        const std::vector<float> reused = renderer->readImage();
        const std::vector<float> fresh = renderScene(sceneAt(t), settings).rgb;
        EXPECT_EQ(reused, fresh) << "t = " << t;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(FrameReuse, RefitAgreesWithFreshRendersWithinNoise) {
    static ShaderCompiler compiler;
    RenderSettings settings = frameSettings();
    settings.samplesPerPixel = 64;
    FrameScenes scenes(FrameBvh::Refit, 1e9); // refit every frame, however worn
    std::unique_ptr<WavefrontRenderer> renderer;
    std::vector<float> first;
    for (size_t k = 0; k < std::size(kTimes); ++k) {
        const double t = kTimes[k];
        const PreparedScene& prepared = scenes.prepare(sceneAt(t));
        EXPECT_EQ(scenes.refitted(), k > 0) << "t = " << t;
        // Independent seeds per frame image, as the reference's are its own.
        std::vector<std::vector<float>> images;
        for (uint32_t seed = 1; seed <= 3; ++seed) {
            RenderSettings s = settings;
            s.seed = seed;
            if (!renderer) {
                renderer = std::make_unique<WavefrontRenderer>(gpuContext(), prepared, s,
                                                               compiler);
            } else {
                if (seed == 1)
                    ASSERT_TRUE(renderer->setScene(prepared)) << "t = " << t;
                renderer->restart(seed, 0);
            }
            renderer->render();
            images.push_back(renderer->readImage());
        }
        if (k == 0)
            first = images[0];
        RenderSettings reference = settings;
        reference.samplesPerPixel = 256;
        reference.aov = true;
        reference.seed = 99;
        const RenderResult fresh = renderScene(sceneAt(t), reference);
        const int checked =
            expectRegionsUnbiased(images, fresh.rgb, fresh.aov.variance, settings.width,
                                  settings.height, 8, "refit frame at t = " + std::to_string(t));
        EXPECT_EQ(checked, 24);
    }
    // The frames differ (the scene moved), so agreeing with each frame's own reference means
    // something.
    EXPECT_NE(first, renderer->readImage());
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(FrameReuse, OtherShadersAreRefused) {
    static ShaderCompiler compiler;
    const RenderSettings settings = frameSettings();
    const PreparedScene first = prepareScene(sceneAt(0.0));
    WavefrontRenderer renderer(gpuContext(), first, settings, compiler);
    Scene lit = sceneAt(0.5);
    PunctualLight point{};
    point.position = glm::vec3(0.0f, 2.0f, 1.0f);
    point.intensity = glm::vec3(10.0f);
    point.type = WF_LIGHT_POINT;
    lit.lights.push_back(point);
    const PreparedScene other = prepareScene(std::move(lit));
    EXPECT_FALSE(renderer.setScene(other)); // a point light needs other shaders
    // Refused without change: it still renders its own scene, as a fresh renderer does.
    renderer.render();
    EXPECT_EQ(renderer.readImage(), renderScene(sceneAt(0.0), settings).rgb);
}

} // namespace
} // namespace wf::test
