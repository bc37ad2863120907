// --env FILE.exr: an equirectangular environment map (longitude along x, +Y up, top row first)
// in linear RGB. The header is checked for a sane size before a pixel is read; texels that are
// NaN, infinite or negative are zeroed with one warning (they would poison every image);
// maps over MAX_ENVIRONMENT_PIXELS are halved until they fit the GPU's buffers.
#pragma once
#include <cstddef>
#include <string>

#include "scene/scene.h"

namespace wf {

constexpr int MAX_ENVIRONMENT_SIDE = 32768;
constexpr size_t MAX_ENVIRONMENT_FILE_PIXELS = size_t(1) << 27; // refused above: 1.5 GiB RGB
constexpr size_t MAX_ENVIRONMENT_PIXELS = size_t(1) << 23;      // 4096 x 2048; halved above

// Throws InputError("<path>: <problem>") for unreadable files, missing R/G/B channels or
// absurd sizes.
Environment loadEnvironmentExr(const std::string& path);

} // namespace wf
