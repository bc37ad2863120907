// 8-bit sRGB PNG preview of a linear radiance image, for a quick look; the EXR is the result.
#pragma once
#include <string>
#include <vector>

#include "image/tonemap.h"

namespace wf {

// Exposure 1 (no scaling), then the tone curve (image/tonemap.h: Khronos PBR Neutral unless
// told; `linear` clamps each channel to [0, 1]), then the exact piecewise sRGB transfer
// function, rounded to 8 bits. A pixel with a non-finite channel becomes black, so a NaN
// stands out instead of being hidden by the curve.
// `linearRgb` holds width * height * 3 floats, row-major, top row first. Written atomically
// (see writeFileAtomically). Throws InputError if the folder does not exist, InternalError
// if writing fails or the arguments are inconsistent.
void writePngPreview(const std::string& path, int width, int height,
                     const std::vector<float>& linearRgb, Tonemap tonemap = kDefaultTonemap);

// One channel's linear value to its 8-bit sRGB code, as the preview does it.
unsigned char linearToSrgb8(float linear);

} // namespace wf
