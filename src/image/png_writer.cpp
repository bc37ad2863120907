// PNG via stb_image_write; its implementation lives in Debian's libstb.so, so this file only
// includes the declarations.
#include "image/png_writer.h"

#include <stb_image_write.h>

#include <climits>
#include <cmath>

#include "errors.h"
#include "image/atomic_file.h"

namespace wf {

unsigned char linearToSrgb8(float linear) {
    if (!std::isfinite(linear)) {
        return 0;
    }
    const double v = std::fmin(std::fmax(static_cast<double>(linear), 0.0), 1.0);
    // IEC 61966-2-1: the linear segment below 0.0031308 avoids an infinite slope at 0.
    const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    return static_cast<unsigned char>(std::lround(encoded * 255.0));
}

void writePngPreview(const std::string& path, int width, int height,
                     const std::vector<float>& linearRgb, Tonemap tonemap) {
    // stb takes the row stride as an int, hence the tighter limit than size_t would allow.
    if (width <= 0 || height <= 0 || width > INT_MAX / 3 ||
        linearRgb.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3) {
        throw InternalError("writePngPreview(" + path + "): " + std::to_string(width) + "x" +
                            std::to_string(height) + " image with " +
                            std::to_string(linearRgb.size()) + " floats");
    }
    std::vector<unsigned char> bytes(linearRgb.size());
    for (size_t i = 0; i < linearRgb.size(); i += 3) {
        tonemapToSrgb8(&linearRgb[i], tonemap, &bytes[i]);
    }
    writeFileAtomically(path, [&](const std::string& tmpPath) {
        if (!stbi_write_png(tmpPath.c_str(), width, height, 3, bytes.data(), width * 3)) {
            throw InternalError("cannot write " + path + ": stbi_write_png failed");
        }
    });
}

} // namespace wf
