// wavefront render's flags (render_flags.cpp): the command's spec, and what is derived from or
// checked on the parsed flags before the scene is loaded.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/cli.h"
#include "render/wavefront_renderer.h"

namespace wf {

inline constexpr uint32_t kRenderDefaultWidth = 512;
inline constexpr uint32_t kRenderDefaultMaxDepth = 16;

const CommandSpec& renderSpec();
// --spp-offset, --spp-total (after settings.samplesPerPixel).
void applySppRangeFlags(const ParsedArgs& parsed, RenderSettings& settings);
// --aov's names, each once, in a fixed set.
std::vector<std::string> parseAovList(const std::string& list);
// Everything that shapes the image but the seed and the sample range (their own attributes):
// parts merge only when this agrees (image/render_parts.h).
std::string renderSettingsKey(const RenderSettings& s, const ParsedArgs& parsed);
// --spectral, the one setting only scenes with KHR_materials_dispersion read: "hero" or
// "single" there (renderSettingsKey's " spectral NAME", an EXR attribute, a JSON field), ""
// in any other scene, whose image it leaves as it is.
std::string spectralSettingFor(const RenderSettings& s, const std::vector<Material>& materials);
// --target-error refuses what would need a sample range it does not have.
void checkAdaptiveFlags(const ParsedArgs& parsed, const RenderSettings& settings);

// What render's flags ask for before the scene is loaded (the size comes with the scene:
// applyImageSize), every refusal of a bad combination made. The CLI and the Python module
// (python/) both read the flags through here, so they refuse alike and render alike.
struct RenderRequest {
    RenderSettings settings;
    double targetError = 0.0;      // --target-error; 0: none
    std::vector<std::string> aovs; // --aov, in the order given
};
RenderRequest renderRequestFrom(const ParsedArgs& parsed);

} // namespace wf
