// wavefront merge's checks and arithmetic on parts made in code: the sample-weighted mean,
// ranges and gaps, and the refusals (another scene, settings, seed, size; overlapping ranges).
#include <gtest/gtest.h>

#include "errors.h"
#include "image/exr_io.h"
#include "image/render_parts.h"

namespace wf {
namespace {

RenderPart part(const std::string& name, uint32_t offset, uint32_t spp, float value) {
    RenderPart p;
    p.path = name;
    p.width = 2;
    p.height = 1;
    p.rgb.assign(6, value);
    p.sceneHash = "00ff";
    p.renderSettings = "2x1 depth 8";
    p.scene = "scene.gltf";
    p.sampler = "sobol";
    p.sppOffset = offset;
    p.spp = spp;
    p.renderSeconds = 1.5;
    return p;
}

TEST(RenderParts, SampleWeightedMeanOverContiguousRanges) {
    MergedRender m = mergeRenderParts({part("b", 64, 192, 2.0f), part("a", 0, 64, 1.0f)});
    EXPECT_EQ(m.image.spp, 256u);
    EXPECT_EQ(m.image.sppOffset, 0u);
    EXPECT_EQ(m.ranges, "0-255");
    EXPECT_TRUE(m.gaps.empty());
    EXPECT_DOUBLE_EQ(m.image.renderSeconds, 3.0);
    for (float v : m.image.rgb)
        EXPECT_FLOAT_EQ(v, (64.0f * 1.0f + 192.0f * 2.0f) / 256.0f);
}

TEST(RenderParts, GapsAreReportedOverlapsRefused) {
    MergedRender m = mergeRenderParts({part("a", 0, 8, 1.0f), part("c", 16, 8, 3.0f)});
    EXPECT_EQ(m.ranges, "0-7,16-23");
    ASSERT_EQ(m.gaps.size(), 1u);
    EXPECT_EQ(m.gaps[0], "8-15");
    EXPECT_THROW(mergeRenderParts({part("a", 0, 8, 1.0f), part("b", 4, 8, 1.0f)}), InputError);
    EXPECT_THROW(mergeRenderParts({part("a", 0, 8, 1.0f), part("a", 0, 8, 1.0f)}), InputError);
}

TEST(RenderParts, PartsOfAnotherRenderAreRefused) {
    const RenderPart a = part("a", 0, 8, 1.0f);
    RenderPart b = part("b", 8, 8, 1.0f);
    b.sceneHash = "0100";
    EXPECT_THROW(mergeRenderParts({a, b}), InputError);
    b = part("b", 8, 8, 1.0f);
    b.seed = 3;
    EXPECT_THROW(mergeRenderParts({a, b}), InputError);
    b = part("b", 8, 8, 1.0f);
    b.renderSettings = "2x1 depth 4";
    EXPECT_THROW(mergeRenderParts({a, b}), InputError);
    b = part("b", 8, 8, 1.0f);
    b.width = 1;
    b.height = 2;
    EXPECT_THROW(mergeRenderParts({a, b}), InputError);
    // A finite set's size matters; a progressive sampler's does not.
    b = part("b", 8, 8, 1.0f);
    b.sppTotal = 16;
    EXPECT_NO_THROW(mergeRenderParts({a, b}));
    RenderPart s = a, t = b;
    s.sampler = t.sampler = "stratified";
    EXPECT_THROW(mergeRenderParts({s, t}), InputError);
}

TEST(RenderParts, AnExrWithoutTheAttributesIsNoPart) {
    const std::string path = ::testing::TempDir() + "not_a_part.exr";
    writeExr(path, 1, 1, {0.5f, 0.5f, 0.5f});
    EXPECT_THROW(readRenderPart(path), InputError);
}

} // namespace
} // namespace wf
