// A scene rendered with its thrice-placed mesh instanced (a two-level BVH, WF_HAS_INSTANCES)
// and flattened into world space must give the same image within noise, in the wavefront and
// in the megakernel: the placements rotate, mirror and scale non-uniformly, and the mesh is
// smooth-shaded and lopsided, so a wrong transform of a point, a normal or a front face moves
// whole regions of the image.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_test_util.h"
#include "gpu_instanced_scene.h"
#include "instanced_scene.h"
#include "render/gpu_scene/scene_buffers.h"
#include "image/png_writer.h"
#include "render/shader_variant.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

Scene load(const std::string& path, Instancing mode) {
    GltfOptions options;
    options.instancing = mode;
    std::vector<std::string> warnings;
    return loadGltf(path, &warnings, options);
}

// Each block x block region's mean (channels averaged) and its standard error from the
// pixels' variances of the mean (--aov variance); channels are taken as fully correlated,
// which bounds the error from above.
std::vector<MeanAndError> regionMeans(const std::vector<float>& rgb,
                                      const std::vector<float>& variance, uint32_t width,
                                      uint32_t height, uint32_t block) {
    std::vector<MeanAndError> regions;
    for (uint32_t by = 0; by + block <= height; by += block)
        for (uint32_t bx = 0; bx + block <= width; bx += block) {
            double sum = 0.0, varianceSum = 0.0;
            for (uint32_t y = by; y < by + block; ++y)
                for (uint32_t x = bx; x < bx + block; ++x) {
                    const size_t i = 3 * (size_t(y) * width + x);
                    sum += (rgb[i] + rgb[i + 1] + rgb[i + 2]) / 3.0;
                    const double sd = (std::sqrt(double(variance[i])) +
                                       std::sqrt(double(variance[i + 1])) +
                                       std::sqrt(double(variance[i + 2]))) / 3.0;
                    varianceSum += sd * sd;
                }
            const double n = double(block) * block;
            regions.push_back({sum / n, std::sqrt(varianceSum) / n});
        }
    return regions;
}

void expectAlike(const std::string& path, bool withMegakernel);

TEST(Instancing, InstancedAndFlattenedScenesRenderAlike) {
    TempDir dir;
    expectAlike(writeInstancedScene(dir), true);
}

// Rough glass: which side is the front decides the refraction, so a front face lost under the
// mirroring placement shows.
TEST(Instancing, InstancedAndFlattenedGlassRendersAlike) {
    TempDir dir;
    expectAlike(writeInstancedScene(dir, R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],
        "metallicFactor":0,"roughnessFactor":0.3},"extensions":{"KHR_materials_transmission":
        {"transmissionFactor":1}}})"), false);
}

// A normal map that tilts every normal along the tangent frame's bitangent: a frame whose
// handedness a mirroring placement fails to flip tilts the other way.
TEST(Instancing, InstancedAndFlattenedNormalMapsRenderAlike) {
    TempDir dir;
    expectAlike(writeNormalMappedInstancedScene(dir), false);
}

void expectAlike(const std::string& path, bool withMegakernel) {
    const Scene flat = load(path, Instancing::Off);
    const Scene instanced = load(path, Instancing::On);
    ASSERT_EQ(instanced.placements.size(), 3u);
    {
        RenderSettings settings;
        const PreparedScene prepared = prepareScene(instanced);
        EXPECT_TRUE(chooseVariant(prepared, settings).instances);
        EXPECT_FALSE(chooseVariant(prepareScene(flat), settings).instances);
    }
    // The megakernel has no AOVs: its images take the wavefront's variances (same estimator,
    // same sample count).
    std::vector<float> varianceFlat, varianceInstanced;
    for (bool megakernel : {false, true}) {
        if (megakernel && !withMegakernel)
            continue;
        RenderSettings settings;
        settings.width = 48;
        settings.height = 32;
        settings.samplesPerPixel = 64;
        settings.maxDepth = 4;
        settings.megakernel = megakernel;
        settings.aov = !megakernel;
        settings.seed = 1;
        const RenderResult a = renderScene(flat, settings);
        settings.seed = 2; // independent samples: the comparison is statistical
        const RenderResult b = renderScene(instanced, settings);
        if (!megakernel) {
            varianceFlat = a.aov.variance;
            varianceInstanced = b.aov.variance;
        }
        const auto ra = regionMeans(a.rgb, varianceFlat, settings.width, settings.height, 8);
        const auto rb = regionMeans(b.rgb, varianceInstanced, settings.width, settings.height, 8);
        ASSERT_EQ(ra.size(), rb.size());
        double worst = 0.0;
        for (size_t i = 0; i < ra.size(); ++i) {
            const double se = std::hypot(ra[i].standardError, rb[i].standardError);
            const double z = std::abs(ra[i].mean - rb[i].mean) / std::max(se, 1e-9);
            worst = std::max(worst, z);
            EXPECT_LT(z, 5.0) << "region " << i << ": flattened " << ra[i].mean << " +- "
                              << ra[i].standardError << ", instanced " << rb[i].mean << " +- "
                              << rb[i].standardError << (megakernel ? " (megakernel)" : "");
        }
        EXPECT_GT(imageMean(b.rgb).mean, 0.01) << "the scene is lit";
        std::printf("megakernel %d: worst region |z| = %.2f over %zu regions\n", megakernel, worst,
                    ra.size());
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// EXT_mesh_gpu_instancing (issue 48): a node's instances load into the same scene as one child
// node per instance, so with the same seed the two files render the same image, bit for bit,
// instanced and flattened alike.
TEST(Instancing, GpuInstancingExtensionRendersAsOneNodePerInstance) {
    TempDir dir;
    GpuInstancingCase c = gpuInstancingCase(5);
    c.camera = true;
    const std::string gpu = gpuInstancingScene(c, true).g.write(dir, "gpu.gltf");
    const std::string nodes = gpuInstancingScene(c, false).g.write(dir, "nodes.gltf");
    for (Instancing mode : {Instancing::On, Instancing::Off}) {
        RenderSettings settings;
        settings.width = 32;
        settings.height = 24;
        settings.samplesPerPixel = 4;
        settings.maxDepth = 3;
        settings.seed = 7;
        const RenderResult a = renderScene(load(gpu, mode), settings);
        const RenderResult b = renderScene(load(nodes, mode), settings);
        ASSERT_EQ(a.rgb.size(), b.rgb.size());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < a.rgb.size(); ++i)
            differ += a.rgb[i] != b.rgb[i];
        EXPECT_EQ(differ, 0u) << instancingName(mode);
        EXPECT_GT(imageMean(a.rgb).mean, 0.01);
        double spread = 0.0; // the blobs are in view: the image is not the flat sky
        for (std::size_t i = 3; i < a.rgb.size(); ++i)
            spread = std::max(spread, double(std::abs(a.rgb[i] - a.rgb[i % 3])));
        EXPECT_GT(spread, 0.05) << instancingName(mode);
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
