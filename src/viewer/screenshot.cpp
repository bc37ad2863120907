#include "viewer/screenshot.h"

#include <stb_image_write.h>

#include <cstdio>
#include <filesystem>

#include "errors.h"
#include "image/atomic_file.h"
#include "image/exr_io.h"
#include "render/wavefront_renderer.h"

namespace fs = std::filesystem;

namespace wf {

std::string writeScreenshot(const std::string& exrPath, const ScreenshotData& data) {
    const std::string pngPath = fs::path(exrPath).replace_extension(".png").string();
    writeExr(exrPath, int(data.width), int(data.height), data.radiance,
             {{"software", "Wavefront view"}, {"scene", data.scenePath}},
             {{"renderSeconds", data.stats ? float(data.stats->seconds) : 0.0f}},
             {{"spp", data.stats ? int(data.stats->samplesPerPixel) : 0},
              {"seed", int(data.seed)},
              {"maxDepth", int(data.maxDepth)}});
    const size_t pixels = size_t(data.shownWidth) * data.shownHeight;
    if (data.shownRgba.size() < pixels * 4)
        throw InternalError("screenshot: " + std::to_string(data.shownRgba.size()) +
                            " bytes for a " + std::to_string(data.shownWidth) + "x" +
                            std::to_string(data.shownHeight) + " frame");
    // The window is opaque: drop alpha rather than store a channel of 255s.
    std::vector<uint8_t> rgb(pixels * 3);
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = data.shownRgba[4 * i + c];
    writeFileAtomically(pngPath, [&](const std::string& tmpPath) {
        if (!stbi_write_png(tmpPath.c_str(), int(data.shownWidth), int(data.shownHeight), 3,
                            rgb.data(), int(data.shownWidth) * 3))
            throw InternalError("cannot write " + pngPath + ": stbi_write_png failed");
    });
    return pngPath;
}

std::string nextScreenshotPath(const std::string& stem) {
    for (int n = 1; n < 100000; ++n) {
        char suffix[16];
        std::snprintf(suffix, sizeof suffix, "-%03d", n);
        const std::string exr = stem + suffix + ".exr";
        if (!fs::exists(exr) && !fs::exists(stem + suffix + ".png"))
            return exr;
    }
    throw InputError("no free screenshot name " + stem + "-NNN.exr in the working folder");
}

} // namespace wf
