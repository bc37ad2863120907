// The triangle and BVH tables spread over several buffers (pages) where one would pass the
// device's limit. A small scene made to spread over 2-8 pages of each (RenderSettings::
// tablePageBytes) renders the image it renders from single buffers, bit for bit, in the
// wavefront and in the megakernel; a scene past the most pages is refused naming the limit.
#include <gtest/gtest.h>

#include "errors.h"
#include <random>

#include "analytic_scenes.h"
#include "gpu_test_util.h"
#include "render/scene_buffers.h"

namespace wf::test {
namespace {

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
    for (bool megakernel : {false, true}) {
        RenderSettings settings;
        settings.width = settings.height = 24;
        settings.samplesPerPixel = 2;
        settings.maxDepth = 4;
        settings.megakernel = megakernel;
        const RenderResult single = renderScene(scene, settings);
        settings.tablePageBytes = pageBytes;
        const RenderResult paged = renderScene(scene, settings);
        EXPECT_EQ(paged.rgb, single.rgb) << trianglePages << " triangle pages, " << bvhPages
                                         << " BVH pages, megakernel " << megakernel;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
