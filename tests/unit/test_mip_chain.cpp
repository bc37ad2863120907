// Mip chains: level sizes (odd ones included), each level the exact box average of the level
// above over the area it covers (checked against replication to a common multiple of the
// sizes, an independent way to the same integral), means kept, colour averaged as linear light.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scene/mip_chain.h"

namespace wf {
namespace {

TextureImage randomImage(uint32_t width, uint32_t height, uint32_t seed) {
    std::mt19937 rng(seed);
    TextureImage image;
    image.width = width;
    image.height = height;
    image.rgba.resize(size_t(width) * height);
    for (uint32_t& texel : image.rgba)
        texel = rng();
    return image;
}

float channel(const TextureImage& image, size_t texel, int c) {
    return float(image.rgba[texel] >> (8 * c) & 0xffu) / 255.0f;
}

// The box average over destination texel (x, y) by replication: each source texel becomes a
// w x h block, after which every destination texel covers exactly W x H of them.
float replicatedAverage(const std::vector<float>& above, uint32_t aw, uint32_t ah, uint32_t w,
                        uint32_t h, uint32_t x, uint32_t y, int c) {
    double sum = 0.0;
    for (uint32_t j = y * ah; j < (y + 1) * ah; ++j)
        for (uint32_t i = x * aw; i < (x + 1) * aw; ++i)
            sum += above[(size_t(j / h) * aw + i / w) * 4 + c];
    return float(sum / (double(aw) * ah));
}

TEST(MipChain, LevelSizesHalveDownToOneTexel) {
    EXPECT_EQ(mipLevelCount(1, 1), 1u);
    EXPECT_EQ(mipLevelCount(256, 256), 9u);
    EXPECT_EQ(mipLevelCount(5, 3), 3u);   // 5x3, 2x1, 1x1
    EXPECT_EQ(mipLevelCount(1, 300), 9u); // 1x300 ... 1x1
    EXPECT_EQ(mipChainTexels(5, 3), 15u + 2u + 1u);
    EXPECT_EQ(mipChainTexels(4, 4), 16u + 4u + 1u);
    const std::vector<TextureImage> levels = buildMipChain(randomImage(7, 5, 1), false);
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_EQ(levels[0].width, 3u);
    EXPECT_EQ(levels[0].height, 2u);
    EXPECT_EQ(levels[1].width, 1u);
    EXPECT_EQ(levels[1].height, 1u);
}

TEST(MipChain, BoxFilterIsTheExactAverageOverTheCoveredArea) {
    for (auto [w, h] : {std::pair{7u, 5u}, {8u, 8u}, {9u, 2u}, {3u, 1u}, {13u, 11u}}) {
        std::mt19937 rng(w * 31 + h);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        std::vector<float> above(size_t(w) * h * 4), out;
        for (float& v : above)
            v = uniform(rng);
        const uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
        boxFilterLevel(above, w, h, out, nw, nh);
        double meanAbove = 0.0, meanOut = 0.0;
        for (uint32_t y = 0; y < nh; ++y)
            for (uint32_t x = 0; x < nw; ++x)
                for (int c = 0; c < 4; ++c) {
                    EXPECT_NEAR(out[(size_t(y) * nw + x) * 4 + c],
                                replicatedAverage(above, w, h, nw, nh, x, y, c), 1e-5f)
                        << w << "x" << h << " at " << x << "," << y;
                    meanOut += out[(size_t(y) * nw + x) * 4 + c];
                }
        for (float v : above)
            meanAbove += v;
        EXPECT_NEAR(meanOut / (nw * nh), meanAbove / (w * h), 1e-4) << w << "x" << h;
    }
}

TEST(MipChain, StoredLevelsAreBoxAveragesOfTheLevelAbove) {
    // Within one 8-bit step: each level is filtered from the float level above and rounded once.
    const TextureImage base = randomImage(13, 7, 2);
    const std::vector<TextureImage> levels = buildMipChain(base, false);
    const TextureImage* above = &base;
    for (const TextureImage& level : levels) {
        std::vector<float> values(above->rgba.size() * 4);
        for (size_t i = 0; i < above->rgba.size(); ++i)
            for (int c = 0; c < 4; ++c)
                values[4 * i + c] = channel(*above, i, c);
        for (uint32_t y = 0; y < level.height; ++y)
            for (uint32_t x = 0; x < level.width; ++x)
                for (int c = 0; c < 4; ++c)
                    EXPECT_NEAR(channel(level, size_t(y) * level.width + x, c),
                                replicatedAverage(values, above->width, above->height,
                                                  level.width, level.height, x, y, c),
                                1.01f / 255.0f);
        above = &level;
    }
}

TEST(MipChain, ColourIsAveragedAsLinearLight) {
    TextureImage image;
    image.width = 2;
    image.height = 1;
    image.rgba = {0xff000000u, 0x00ffffffu}; // sRGB black opaque, white transparent
    const TextureImage srgb = buildMipChain(image, true)[0];
    const TextureImage data = buildMipChain(image, false)[0];
    const uint32_t half = uint32_t(std::lround(linearToSrgb(0.5f) * 255.0f)); // 188, not 128
    EXPECT_EQ(srgb.rgba[0] & 0xffu, half);
    EXPECT_EQ(srgb.rgba[0] >> 24, 128u); // alpha is data either way
    EXPECT_EQ(data.rgba[0] & 0xffu, 128u);
    EXPECT_NEAR(srgbToLinear(linearToSrgb(0.3f)), 0.3f, 1e-6f);
}

} // namespace
} // namespace wf
