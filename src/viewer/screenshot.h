// Viewer screenshots: the accumulated radiance as EXR (as `wavefront render` writes it, with
// the same header attributes) and the frame as shown, overlay included, as PNG beside it. Both
// go through writeFileAtomically, so quitting or killing the viewer never leaves half a file.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace wf {

struct RenderStats;

struct ScreenshotData {
    std::string scenePath;
    uint32_t width = 0; // of the radiance image
    uint32_t height = 0;
    std::vector<float> radiance; // RGB, top row first
    const RenderStats* stats = nullptr;
    uint32_t seed = 0;
    uint32_t maxDepth = 0;
    uint32_t shownWidth = 0; // of the shown frame
    uint32_t shownHeight = 0;
    std::vector<uint8_t> shownRgba; // RGBA8 sRGB, top row first
};

// Writes `exrPath` and the PNG beside it (same name, .png); returns the PNG's path.
std::string writeScreenshot(const std::string& exrPath, const ScreenshotData& data);

// "<stem>-NNN.exr" in the working folder, NNN the first number whose .exr and .png are free.
std::string nextScreenshotPath(const std::string& stem);

} // namespace wf
