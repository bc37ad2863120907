// Mip chains for texture filtering with ray cones: each level half the size of the one above
// (rounded down, at least 1), down to 1x1, each texel the exact box average of the area it
// covers in the level above. For odd sizes that area is not a whole number of texels, so the
// texels it cuts count by the fraction it covers: every level keeps the mean of the image.
// Colour data is averaged as linear values (sRGB-decoded, then encoded again), as hardware
// sRGB mipmaps are; other data as stored.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/surface_data.h"

namespace wf {

// Levels in the chain of a width x height image, level 0 included: 1 + floor(log2(max side)).
uint32_t mipLevelCount(uint32_t width, uint32_t height);
// Texels of all levels together.
uint64_t mipChainTexels(uint32_t width, uint32_t height);

// Levels 1 .. mipLevelCount - 1 of `base` (level 0 is the image itself). Each level is
// filtered from the level above kept in float, so rounding to 8 bits does not accumulate.
std::vector<TextureImage> buildMipChain(const TextureImage& base, bool srgb);

// The box average of `above` (floats, 4 channels a texel) over the area that texel (x, y) of a
// level of size (width, height) covers: the filter buildMipChain applies, exposed for tests.
void boxFilterLevel(const std::vector<float>& above, uint32_t aboveWidth, uint32_t aboveHeight,
                    std::vector<float>& out, uint32_t width, uint32_t height);

float srgbToLinear(float c);
float linearToSrgb(float c);

} // namespace wf
