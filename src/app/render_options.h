// The flags that render, view, bench and converge share, declared once: their OptionSpecs
// (the help text each command shows) and their parsing into RenderSettings and ContextOptions,
// the scene load that --camera and --env change, and the image size that --width, --height and
// the camera's aspect ratio give. A command lists the groups it offers in its CommandSpec
// (joinOptions) and reads them with the functions below; a flag a command does not declare
// cannot be given (parseArgs refuses it), so reading it yields its default.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/cli.h"
#include "gpu/context.h"
#include "image/tonemap.h"
#include "render/guiding/guiding_schedule.h"
#include "render/wavefront_renderer.h"
#include "scene/scene.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/scene_summary.h"

namespace wf {

// Declarations, each group in the order --help lists it.
std::vector<OptionSpec> imageSizeOptions(uint32_t defaultWidth); // --width, --height
std::vector<OptionSpec> depthOptions(uint32_t defaultMaxDepth);  // --max-depth, --rr-depth
// --light-sampling, --triangle-sampling, --sphere-sampling, --min-throughput, --clamp, --seed,
// --sampler.
std::vector<OptionSpec> samplingOptions();
OptionSpec noRandomizeOption(); // --no-randomize
OptionSpec deviceOption();      // --device
OptionSpec traversalOption();   // --traversal
// --traversal as what the context should enable.
RayTracingRequest traversalRequest(const ParsedArgs& parsed);
// What the renderers of this context trace with.
Traversal traversalFor(const Context& context);
OptionSpec quietOption();       // --quiet, -q: no progress lines
OptionSpec cameraOption();      // --camera: one of the file's cameras
OptionSpec envOption();
OptionSpec instancingOption(); // --instancing auto|on|off         // --env
OptionSpec variantOption();    // --variant: one of the file's KHR_materials_variants
std::vector<OptionSpec> lensOptions(); // --aperture, --focus-distance
// --time, --frame, --fps, --animation, --shutter; without `withTime` no --time (converge's
// --time is its render budget: its scene time is --frame N / --fps).
std::vector<OptionSpec> animationOptions(bool withTime = true);

// The scene's time in seconds from --time, or --frame / --fps (UsageError when both are given).
// --shutter OPEN:CLOSE (frames, at --fps) around options.time: the shutter's interval in
// seconds, and options.time moved to its centre (UsageError on a malformed interval).
void applyShutter(const ParsedArgs& parsed, GltfOptions& options);
double sceneTimeFrom(const ParsedArgs& parsed);

// depthOptions, samplingOptions and --no-randomize into `settings` (UsageError on a bad value).
void applyRenderFlags(const ParsedArgs& parsed, uint32_t defaultMaxDepth,
                      RenderSettings& settings);

// --guiding auto: decides settings.guiding for `scene` (guiding_schedule.h's rule) and
// clears guidingAuto; off and on are kept. The decision's reason is for --verbose.
guiding::GuidingDecision resolveGuiding(RenderSettings& settings, const PreparedScene& scene);

// --tonemap: the PNG preview's tone curve (the default where not given).
Tonemap previewTonemapFrom(const ParsedArgs& parsed);

// --device, --quiet and --traversal.
ContextOptions contextOptionsFrom(const ParsedArgs& parsed);

// Loads the glTF file at `path`, takes the file's camera that --camera names and the
// environment map --env names, prints the loader's warnings once those are accepted, then
// frames the scene when it has no camera and sets its lens from --aperture and
// --focus-distance. `summary`, when given, describes the scene as loaded
// (before framing) and how long loading took. The scene is posed at `time` seconds when given,
// else at sceneTimeFrom(parsed), playing --animation's choice (a sequence prints the loader's
// warnings for its first frame only: printWarnings). Throws InputError for a bad
// file, camera or map.
Scene loadSceneWithFlags(const ParsedArgs& parsed, const std::string& path,
                         SceneSummary* summary = nullptr,
                         std::optional<double> time = std::nullopt, bool printWarnings = true);

// How a command sizes its image from --width, --height and the camera's aspect ratio.
struct ImageSizeRule {
    uint32_t width = 512;           // without --width
    std::optional<uint32_t> height; // with neither flag (else: width / aspect)
    bool widthFollowsHeight = true; // with --height alone: width = height x aspect
};

// Sets settings.width and settings.height (each 1 .. 16384; UsageError otherwise).
void applyImageSize(const ParsedArgs& parsed, const Camera& camera, const ImageSizeRule& rule,
                    RenderSettings& settings);

} // namespace wf
