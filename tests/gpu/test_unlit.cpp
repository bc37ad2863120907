// KHR_materials_unlit: a surface that shows its base colour whatever lights it. Seen head-on
// by a camera whose view it fills, with nothing else in the scene, every pixel is the base
// colour (factor x the sRGB-decoded texture would be the same path), at any depth: the
// surface reflects nothing.
#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "mini_gltf.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

TEST(Unlit, EveryPixelIsTheBaseColour) {
    TempDir dir;
    MiniGltf g;
    const int pos = g.addPositions({-50, -50, 0, 50, -50, 0, 50, 50, 0, -50, 50, 0});
    g.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorFactor":[0.2,0.4,0.6,1]},
        "extensions":{"KHR_materials_unlit":{}}})");
    g.addMesh(pos, g.addIndices<uint16_t>({0, 1, 2, 0, 2, 3}, U16), 0);
    g.cameras.push_back(R"({"type":"perspective","perspective":{"yfov":0.5,"aspectRatio":1,"znear":0.1}})");
    g.nodes = {R"({"mesh":0})", R"({"camera":0,"translation":[0,0,5]})"};
    g.scenes = R"([{"nodes":[0,1]}])";
    g.extra = R"(,"extensionsUsed":["KHR_materials_unlit"],"extensionsRequired":["KHR_materials_unlit"])";
    const Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_FLOAT_EQ(scene.materials[0].emission.y, 0.4f);
    EXPECT_FLOAT_EQ(scene.materials[0].baseColor.x, 0.0f);
    for (uint32_t depth : {1u, 4u}) {
        RenderSettings settings;
        settings.width = settings.height = 8;
        settings.samplesPerPixel = 4;
        settings.maxDepth = depth;
        const RenderResult r = renderScene(scene, settings);
        for (size_t i = 0; i < r.rgb.size(); i += 3) {
            EXPECT_NEAR(r.rgb[i], 0.2f, 1e-5f) << i;
            EXPECT_NEAR(r.rgb[i + 1], 0.4f, 1e-5f) << i;
            EXPECT_NEAR(r.rgb[i + 2], 0.6f, 1e-5f) << i;
        }
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
