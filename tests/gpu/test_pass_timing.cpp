// RenderSettings.timePasses: renders that read no pass times (a plain render, converge) time
// only their waves, one timestamp at each end instead of one per pass (gpu/timestamp_timer.h);
// the image is the same bit for bit and the waves' GPU time is still there.
#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

TEST(PassTiming, WavesTimedAloneGiveTheSameImage) {
    Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/cornell_box.gltf");
    RenderSettings settings;
    settings.width = 16;
    settings.height = 16;
    settings.samplesPerPixel = 8;
    settings.maxDepth = 6;
    settings.seed = 3;
    const RenderResult perPass = renderScene(scene, settings);
    settings.timePasses = false;
    const RenderResult waves = renderScene(scene, settings);
    EXPECT_EQ(waves.rgb, perPass.rgb);
    EXPECT_GT(perPass.stats.passMilliseconds.count("intersect"), 0u);
    EXPECT_GT(perPass.stats.passMilliseconds.count("shade"), 0u);
    ASSERT_EQ(waves.stats.passMilliseconds.size(), 1u);
    EXPECT_GT(waves.stats.passMilliseconds.at("waves"), 0.0);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
