// --light-share (shaders/bidir/light_share.h): the pixels of an image dealt out to the light
// subpaths of a sample index. Every pixel gets a subpath that is traced, every subpath serves
// the same number of pixels give or take one, and the pixels sharing one are not neighbours.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "shaders/bidir/light_share.h"

namespace wf::gpu_types {
namespace {

TEST(LightShare, EverySubpathServesTheSameNumberOfPixels) {
    for (uint32_t pixels : {1u, 2u, 7u, 64u, 1000u, 4096u, 65536u, 1920u * 1080u})
        for (uint32_t share : {1u, 2u, 3u, 8u, 32u}) {
            const uint32_t lightPaths = (pixels + share - 1) / share;
            std::vector<uint32_t> served(lightPaths, 0);
            for (uint32_t p = 0; p < pixels; ++p) {
                const uint32_t subpath = lightSubpathOfPixel(p, pixels, lightPaths);
                ASSERT_LT(subpath, lightPaths) << pixels << " " << share;
                ++served[subpath];
            }
            const auto [least, most] = std::minmax_element(served.begin(), served.end());
            EXPECT_LE(*most - *least, 1u) << pixels << " pixels, share " << share;
            EXPECT_GE(*least, 1u) << pixels << " pixels, share " << share;
        }
}

TEST(LightShare, NeighboursDoNotShare) {
    // 64x64 pixels, 8 to a subpath: a pixel's right and lower neighbours rarely share its.
    const uint32_t width = 64, pixels = 64 * 64, lightPaths = pixels / 8;
    uint32_t shared = 0;
    for (uint32_t p = 0; p + width < pixels; ++p) {
        const uint32_t mine = lightSubpathOfPixel(p, pixels, lightPaths);
        shared += mine == lightSubpathOfPixel(p + 1, pixels, lightPaths);
        shared += mine == lightSubpathOfPixel(p + width, pixels, lightPaths);
    }
    // By chance: 2 (pixels - width) 7 / (pixels - 1), about 14.
    EXPECT_LT(shared, 40u);
}

} // namespace
} // namespace wf::gpu_types
