// Per-scene specialisation: a scene without emitters compiles the no-NEE variant and binds no
// emitter table or shadow-queue buffers, and still renders (to black).
#include <algorithm>

#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "render/gpu_scene/scene_buffers.h"

namespace wf::test {
namespace {

TEST(Variants, SceneWithoutEmittersHasNoLightCodeOrBuffers) {
    Scene scene = furnaceBox(0.5f, 0.0f);
    PreparedScene prepared = prepareScene(scene);
    RenderSettings settings;
    settings.width = 16;
    settings.height = 16;
    settings.samplesPerPixel = 2;
    ShaderCompiler compiler;
    WavefrontRenderer renderer(gpuContext(), prepared, settings, compiler);
    const auto& defines = renderer.shaderDefines();
    EXPECT_NE(std::find(defines.begin(), defines.end(),
                        std::pair<std::string, std::string>{"WF_HAS_EMITTERS", "0"}),
              defines.end());
    for (const auto& [name, bytes] : renderer.memoryReport()) {
        EXPECT_EQ(name.find("emitter"), std::string::npos) << name;
        EXPECT_EQ(name.find("shadow"), std::string::npos) << name;
    }
    renderer.render();
    for (float v : renderer.readImage())
        ASSERT_EQ(v, 0.0f);
    EXPECT_EQ(renderer.stats().shadowRays, 0u);
    EXPECT_GT(renderer.stats().extensionRays, 0u);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Variants, SceneWithEmittersBindsTheLightTable) {
    PreparedScene prepared = prepareScene(furnaceBox(0.5f, 1.0f));
    RenderSettings settings;
    settings.width = 8;
    settings.height = 8;
    settings.samplesPerPixel = 1;
    ShaderCompiler compiler;
    WavefrontRenderer renderer(gpuContext(), prepared, settings, compiler);
    auto report = renderer.memoryReport();
    EXPECT_TRUE(std::any_of(report.begin(), report.end(),
                            [](const auto& entry) { return entry.first == "emitters"; }));
    EXPECT_TRUE(std::any_of(report.begin(), report.end(),
                            [](const auto& entry) { return entry.first == "shadow origins"; }));
}

} // namespace
} // namespace wf::test
