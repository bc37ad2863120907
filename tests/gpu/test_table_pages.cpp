// The triangle and BVH tables spread over several buffers (pages) where one would pass the
// device's limit, and so may a two-level scene's instances. A small scene made to spread over
// 2-8 pages of each (RenderSettings::tablePageBytes) renders the image it renders from single
// buffers, bit for bit, in the wavefront and in the megakernel; a scene past the most pages is
// refused naming the limit.
#include <gtest/gtest.h>

#include "errors.h"
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "analytic_scenes.h"
#include "gpu_test_util.h"
#include "instanced_scene.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

// The scene rendered from single buffers and from pages of at most `pageBytes`, bit for bit
// the same; lit, so that the comparison means something. `what` names the case.
void expectPagedRendersAlike(const Scene& scene, uint64_t pageBytes, bool megakernel,
                             uint32_t width, uint32_t height, const std::string& what) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.samplesPerPixel = 2;
    settings.maxDepth = 4;
    settings.megakernel = megakernel;
    const RenderResult single = renderScene(scene, settings);
    settings.tablePageBytes = pageBytes;
    const RenderResult paged = renderScene(scene, settings);
    EXPECT_EQ(paged.rgb, single.rgb) << what << (megakernel ? ", megakernel" : ", wavefront");
    EXPECT_GT(imageMean(paged.rgb).mean, 0.01) << what << ": the scene is lit";
}

TEST(TablePages, PagingRule) {
    EXPECT_EQ(tablePaging(1000, 48, 1 << 20, "triangles"), TablePages{});
    const TablePages pages = tablePaging(1000, 48, 48 * 300, "triangles");
    EXPECT_EQ(pages.entriesPerPage(), 256u); // the largest power of two that fits
    EXPECT_EQ(pages.count, 4u);
    try {
        tablePaging(1000, 48, 48 * 100, "triangles");
        FAIL() << "sixteen pages accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("triangles"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("device's limit"), std::string::npos) << e.what();
    }
}

TEST(TablePages, PagedTablesRenderTheSameImage) {
    // A floor under a sphere light, with 3000 small triangles scattered above it: leaves of one
    // or two triangles, so both tables are of a size.
    Scene scene = floorScene(0.7f);
    scene.lights.push_back(sphereLight({0.0f, 3.0f, 0.0f}, 0.3f, glm::vec3(20.0f)));
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 c(u(rng), 0.6f + 0.5f * u(rng), u(rng));
        const glm::vec3 e1(0.03f * u(rng), 0.03f * u(rng), 0.03f * u(rng));
        const glm::vec3 e2(0.03f * u(rng), 0.03f * u(rng), 0.03f * u(rng));
        scene.triangles.push_back(Triangle{c, 0, c + e1, WF_NO_EMITTER, c + e2, 0});
    }
    const PreparedScene prepared = prepareScene(scene);
    // A page size at which both tables take 2 to 8 pages.
    auto pagesAt = [&](uint64_t bytes) -> std::pair<uint32_t, uint32_t> {
        try {
            return {tablePaging(prepared.triangles.size(), sizeof(Triangle), bytes, "triangles")
                        .count,
                    tablePaging(prepared.bvhPairs.size(), sizeof(BvhPair), bytes, "BVH nodes")
                        .count};
        } catch (const InputError&) {
            return {0, 0};
        }
    };
    uint64_t pageBytes = 64;
    for (; pageBytes < (1u << 24); pageBytes += 64) {
        const auto [t, b] = pagesAt(pageBytes);
        if (t >= 2 && b >= 2)
            break;
    }
    const auto [trianglePages, bvhPages] = pagesAt(pageBytes);
    ASSERT_GE(trianglePages, 2u);
    ASSERT_GE(bvhPages, 2u);
    for (bool megakernel : {false, true})
        expectPagedRendersAlike(scene, pageBytes, megakernel, 24, 24,
                                std::to_string(trianglePages) + " triangle pages, " +
                                    std::to_string(bvhPages) + " BVH pages");
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(TablePages, PagedInstancesRenderTheSameImage) {
    // A floor and a sphere light in world space, and one small tetrahedron placed 15 times in a
    // ring, each turned and scaled differently: 16 instances, the world's included.
    Scene scene = floorScene(0.7f);
    scene.lights.push_back(sphereLight({0.0f, 3.0f, 0.0f}, 0.3f, glm::vec3(20.0f)));
    const glm::vec3 corners[4] = {{0.0f, 0.0f, 0.0f}, {0.3f, 0.0f, 0.0f}, {0.0f, 0.3f, 0.0f},
                                  {0.0f, 0.0f, 0.3f}};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    scene.meshes.push_back(MeshRange{uint32_t(scene.triangles.size()), 4});
    for (const auto& f : faces)
        scene.triangles.push_back(
            Triangle{corners[f[0]], 0, corners[f[1]], WF_NO_EMITTER, corners[f[2]], 0});
    for (int i = 0; i < 15; ++i) {
        const float angle = 2.0f * float(M_PI) * float(i) / 15.0f;
        glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(0.7f * std::cos(angle), 0.3f,
                                                                0.7f * std::sin(angle)));
        m = glm::rotate(m, angle, glm::vec3(0.3f, 1.0f, 0.2f));
        m = glm::scale(m, glm::vec3(1.0f + 0.05f * float(i), 1.0f, i % 3 == 0 ? -1.0f : 1.0f));
        scene.placements.push_back(MeshPlacement{m, 0});
    }
    const PreparedScene prepared = prepareScene(scene);
    ASSERT_EQ(prepared.instances.size(), 16u);
    // Pages of 4 instances: 4 of them, while the triangles and the BVH fit in 8 pages or fewer.
    const uint64_t pageBytes = 4 * sizeof(Instance);
    ASSERT_EQ(tablePaging(prepared.instances.size(), sizeof(Instance), pageBytes, "instances").count,
              4u);
    for (bool megakernel : {false, true})
        expectPagedRendersAlike(scene, pageBytes, megakernel, 24, 24, "4 instance pages");
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(TablePages, PagedAttributesRenderTheSameImage) {
    // Smooth normals, MikkTSpace tangents and UVs (a normal map) follow the triangles' pages.
    TempDir dir;
    std::vector<std::string> warnings;
    GltfOptions options;
    options.instancing = Instancing::Off;
    const Scene scene = loadGltf(writeNormalMappedInstancedScene(dir), &warnings, options);
    ASSERT_FALSE(scene.surface.normals.empty());
    ASSERT_FALSE(scene.surface.tangents.empty());
    ASSERT_FALSE(scene.surface.uv0.empty());
    const PreparedScene prepared = prepareScene(scene);
    const uint64_t pageBytes = 128 * sizeof(Triangle);
    const uint32_t trianglePages =
        tablePaging(prepared.triangles.size(), sizeof(Triangle), pageBytes, "triangles").count;
    ASSERT_GE(trianglePages, 2u);
    ASSERT_LE(tablePaging(prepared.bvhPairs.size(), sizeof(BvhPair), pageBytes, "BVH").count,
              8u);
    // The wavefront only: the megakernel reads the tables through the same functions.
    expectPagedRendersAlike(scene, pageBytes, false, 32, 24,
                            std::to_string(trianglePages) + " triangle pages");
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
