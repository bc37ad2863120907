// A scene compressed by Debian's gltfpack (-cc: EXT_meshopt_compression over
// KHR_mesh_quantization, 14-bit positions) renders like the original: with the same seed its
// image is closer to the original's than an independent render (another seed) of the original
// is, so quantization moves nothing beyond noise; it compiles the original's shader variant. A
// scene less two triangles fails the same check, so the check can fail. Skipped where gltfpack
// is not installed (scripts/setup.sh --with-tests installs it).
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "image/error_metrics.h"
#include "render/scene_buffers.h"
#include "render/shader_variant.h"
#include "scene/gltf_loader.h"

namespace wf::test {
namespace {

namespace fs = std::filesystem;

RenderSettings settings(uint32_t seed) {
    RenderSettings s;
    s.width = 40;
    s.height = 40;
    s.samplesPerPixel = 64;
    s.maxDepth = 6;
    s.seed = seed;
    return s;
}

TEST(CompressedScenes, GltfpackCornellBoxRendersLikeTheOriginal) {
    if (std::system("gltfpack -v >/dev/null 2>&1") != 0) {
        GTEST_SKIP() << "gltfpack is not installed (scripts/setup.sh --with-tests)";
    }
    const fs::path dir = fs::temp_directory_path() / "wf_test_compressed_scenes";
    fs::create_directories(dir);
    const std::string source = std::string(WF_TEST_SCENE_DIR) + "/cornell_box.gltf";
    const std::string packed = (dir / "cornell_box_cc.glb").string();
    fs::remove(packed);
    const std::string command = "gltfpack -i '" + source + "' -o '" + packed + "' -cc >/dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;

    const Scene original = loadGltf(source);
    const Scene compressed = loadGltf(packed);
    ASSERT_EQ(compressed.triangles.size(), original.triangles.size());
    // Decoded in the loader: the same shader variant and vertex buffers as the original.
    EXPECT_EQ(chooseVariant(prepareScene(compressed), settings(1)).describe(),
              chooseVariant(prepareScene(original), settings(1)).describe());
    EXPECT_EQ(compressed.surface.normals.size(), original.surface.normals.size());
    EXPECT_EQ(compressed.surface.uv0.size(), original.surface.uv0.size());
    const std::vector<float> reference = renderScene(original, settings(1)).rgb;
    const std::vector<float> independent = renderScene(original, settings(2)).rgb;
    const RenderResult result = renderScene(compressed, settings(1));
    EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
    const ImageError noise = imageError(independent, reference);
    const ImageError error = imageError(result.rgb, reference);
    std::printf("relMSE against the original: gltfpack -cc %.3g, another seed %.3g\n",
                error.relMse, noise.relMse);
    EXPECT_LT(error.relMse, noise.relMse);
    const double mean = imageMean(reference).mean;
    EXPECT_LT(std::abs(error.bias), std::abs(noise.bias) + 0.01 * mean);

    // The control: the same scene less two triangles (a wall's half) is caught.
    Scene broken = compressed;
    broken.triangles.erase(broken.triangles.begin(), broken.triangles.begin() + 2);
    const ImageError control = imageError(renderScene(broken, settings(1)).rgb, reference);
    std::printf("relMSE of the scene less two triangles: %.3g\n", control.relMse);
    EXPECT_GT(control.relMse, noise.relMse);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
