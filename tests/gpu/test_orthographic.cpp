// An orthographic glTF camera (xmag = ymag = 1) looking at an unlit quad that covers exactly
// the left half of its view, far away: every pixel of the left half sees the quad, none of the
// right half (a perspective camera would see the far quad shrink towards the centre). Depth 1,
// nothing else in the scene, so the pixels are exactly 1 or 0.
#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "mini_gltf.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

TEST(Orthographic, ParallelRaysSeeTheQuadAtItsTrueSize) {
    TempDir dir;
    MiniGltf g;
    const int pos = g.addPositions({-1, -1, -20, 0, -1, -20, 0, 1, -20, -1, 1, -20});
    g.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1]},
        "extensions":{"KHR_materials_unlit":{}}})");
    g.addMesh(pos, g.addIndices<uint16_t>({0, 1, 2, 0, 2, 3}, U16), 0);
    g.cameras.push_back(R"({"type":"orthographic","orthographic":{"xmag":1,"ymag":1,"znear":0.1,"zfar":100}})");
    g.nodes = {R"({"mesh":0})", R"({"camera":0,"translation":[0,0,5]})"};
    g.scenes = R"([{"nodes":[0,1]}])";
    g.extra = R"(,"extensionsUsed":["KHR_materials_unlit"])";
    const Scene scene = loadGltf(g.write(dir));
    ASSERT_FLOAT_EQ(scene.camera.orthoHalfHeight, 1.0f);
    RenderSettings settings;
    settings.width = settings.height = 16;
    settings.samplesPerPixel = 4;
    settings.maxDepth = 1;
    const RenderResult r = renderScene(scene, settings);
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 0; x < 16; ++x)
            EXPECT_NEAR(r.rgb[3 * (y * 16 + x)], x < 8 ? 1.0f : 0.0f, 1e-6f) << x << "," << y;
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
