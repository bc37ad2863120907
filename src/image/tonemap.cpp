#include "image/tonemap.h"

#include <cmath>

#include "errors.h"
#include "image/png_writer.h"
#include "shaders/types/display_types.h"

namespace wf {

const char* tonemapName(Tonemap tonemap) {
    switch (tonemap) {
    case Tonemap::Aces:
        return "aces";
    case Tonemap::Neutral:
        return "neutral";
    case Tonemap::Linear:
        break;
    }
    return "linear";
}

Tonemap parseTonemap(const std::string& name) {
    if (name == "linear")
        return Tonemap::Linear;
    if (name == "aces")
        return Tonemap::Aces;
    if (name == "neutral")
        return Tonemap::Neutral;
    throw UsageError("--tonemap: '" + name + "' is not a tone curve (neutral, aces or linear)");
}

const char* tonemapHelp() {
    return "tone curve of what a person looks at: neutral (Khronos PBR Neutral, as glTF viewers "
           "show a file; default), aces (filmic) or linear (clamp)";
}

void tonemapToSrgb8(const float* rgb, Tonemap tonemap, unsigned char* out) {
    if (!std::isfinite(rgb[0]) || !std::isfinite(rgb[1]) || !std::isfinite(rgb[2])) {
        out[0] = out[1] = out[2] = 0;
        return;
    }
    if (tonemap == Tonemap::Linear) { // the exact clamp and encoding the preview always had
        for (int c = 0; c < 3; ++c)
            out[c] = linearToSrgb8(rgb[c]);
        return;
    }
    using namespace gpu_types;
    const vec3 radiance = max(vec3(rgb[0], rgb[1], rgb[2]), vec3(0.0f));
    const vec3 mapped = tonemapRadiance(radiance, static_cast<uint32_t>(tonemap));
    for (int c = 0; c < 3; ++c)
        out[c] = linearToSrgb8(mapped[c]);
}

} // namespace wf
