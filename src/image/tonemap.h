// The tone curves a person looks at (--tonemap): the PNG preview beside every EXR and the
// viewer's window. The EXR itself stays linear radiance. The curves are shared with the
// display shader (shaders/types/display_types.h), so the preview and the window agree.
#pragma once
#include <cstdint>
#include <string>

namespace wf {

// Values of WF_TONEMAP_* (display_types.h).
enum class Tonemap : uint32_t { Linear = 0, Aces = 1, Neutral = 2 };

// Khronos PBR Neutral: what glTF viewers show, so a file looks as its author saw it.
inline constexpr Tonemap kDefaultTonemap = Tonemap::Neutral;

const char* tonemapName(Tonemap tonemap);          // "linear", "aces", "neutral"
Tonemap parseTonemap(const std::string& name);     // UsageError on another name
// --tonemap's help: "neutral (Khronos PBR Neutral; default), aces (filmic) or linear (clamp)".
const char* tonemapHelp();

// Linear radiance (one pixel's RGB, exposure applied) to 8-bit sRGB by `tonemap`; a pixel with
// a non-finite channel is black, so that a NaN stands out.
void tonemapToSrgb8(const float* rgb, Tonemap tonemap, unsigned char* out);

} // namespace wf
