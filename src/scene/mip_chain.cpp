#include "scene/mip_chain.h"

#include <algorithm>
#include <cmath>

namespace wf {
namespace {

// Weights of the source texels a destination texel covers along one axis: texel i of n covers
// [i s, (i + 1) s) of the m source texels, s = m / n; a source texel counts by its overlap.
struct Span {
    uint32_t first = 0;
    std::vector<float> weight; // sums to 1
};

std::vector<Span> spans(uint32_t m, uint32_t n) {
    std::vector<Span> out(n);
    const double scale = double(m) / double(n);
    for (uint32_t i = 0; i < n; ++i) {
        const double lo = i * scale, hi = (i + 1) * scale;
        Span& s = out[i];
        s.first = uint32_t(std::floor(lo));
        const uint32_t last = std::min<uint32_t>(m - 1, uint32_t(std::ceil(hi)) - 1);
        for (uint32_t j = s.first; j <= last; ++j) {
            const double overlap = std::min(hi, double(j + 1)) - std::max(lo, double(j));
            s.weight.push_back(float(overlap / scale));
        }
    }
    return out;
}

// The box filter over any source: `read(texel, channel)` gives the value above.
template <typename Read>
void boxFilter(const Read& read, uint32_t aboveWidth, uint32_t aboveHeight,
               std::vector<float>& out, uint32_t width, uint32_t height) {
    const std::vector<Span> xs = spans(aboveWidth, width), ys = spans(aboveHeight, height);
    out.assign(size_t(width) * height * 4, 0.0f);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            float* o = &out[(size_t(y) * width + x) * 4];
            for (size_t j = 0; j < ys[y].weight.size(); ++j) {
                const size_t row = size_t(ys[y].first + j) * aboveWidth;
                for (size_t i = 0; i < xs[x].weight.size(); ++i) {
                    const float w = ys[y].weight[j] * xs[x].weight[i];
                    const size_t texel = row + xs[x].first + i;
                    for (int c = 0; c < 4; ++c)
                        o[c] += w * read(texel, c);
                }
            }
        }
    }
}

TextureImage encode(const std::vector<float>& values, uint32_t width, uint32_t height, bool srgb) {
    TextureImage image;
    image.width = width;
    image.height = height;
    image.rgba.resize(size_t(width) * height);
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        uint32_t texel = 0;
        for (int c = 0; c < 4; ++c) {
            float v = values[4 * i + c];
            v = srgb && c < 3 ? linearToSrgb(v) : v;
            const uint32_t byte = uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
            texel |= byte << (8 * c);
        }
        image.rgba[i] = texel;
    }
    return image;
}

} // namespace

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

uint32_t mipLevelCount(uint32_t width, uint32_t height) {
    uint32_t levels = 1;
    for (uint32_t side = std::max(width, height); side > 1; side /= 2)
        ++levels;
    return levels;
}

uint64_t mipChainTexels(uint32_t width, uint32_t height) {
    uint64_t texels = 0;
    for (uint32_t level = 0; level < mipLevelCount(width, height); ++level)
        texels += uint64_t(std::max(1u, width >> level)) * std::max(1u, height >> level);
    return texels;
}

void boxFilterLevel(const std::vector<float>& above, uint32_t aboveWidth, uint32_t aboveHeight,
                    std::vector<float>& out, uint32_t width, uint32_t height) {
    boxFilter([&](size_t texel, int c) { return above[texel * 4 + c]; }, aboveWidth,
              aboveHeight, out, width, height);
}

std::vector<TextureImage> buildMipChain(const TextureImage& base, bool srgb) {
    std::vector<TextureImage> levels;
    if (mipLevelCount(base.width, base.height) < 2)
        return levels;
    // Level 1 straight from the bytes (a float copy of a 64-Mpixel level 0 would be 1 GiB).
    float table[256];
    for (int i = 0; i < 256; ++i)
        table[i] = srgb ? srgbToLinear(float(i) / 255.0f) : float(i) / 255.0f;
    auto byte = [&](size_t texel, int c) { return base.rgba[texel] >> (8 * c) & 0xffu; };
    std::vector<float> above, next;
    uint32_t w = std::max(1u, base.width / 2), h = std::max(1u, base.height / 2);
    boxFilter([&](size_t texel, int c) { return c < 3 ? table[byte(texel, c)]
                                                      : float(byte(texel, c)) / 255.0f; },
              base.width, base.height, above, w, h);
    levels.push_back(encode(above, w, h, srgb));
    for (uint32_t level = 2; level < mipLevelCount(base.width, base.height); ++level) {
        const uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
        boxFilterLevel(above, w, h, next, nw, nh);
        levels.push_back(encode(next, nw, nh, srgb));
        above.swap(next);
        w = nw;
        h = nh;
    }
    for (TextureImage& level : levels)
        level.name = base.name;
    return levels;
}

} // namespace wf
