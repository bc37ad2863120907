// wavefront view: command line -> ViewerOptions -> the progressive viewer (src/viewer/).
#include <cstdio>
#include <filesystem>

#include "app/cli.h"
#include "app/commands.h"
#include "errors.h"
#include "render/samplers.h"
#include "viewer/overlay.h"
#include "viewer/viewer.h"

namespace fs = std::filesystem;

namespace wf {
namespace {

const CommandSpec& viewSpec() {
    static const CommandSpec spec{
        "view",
        "wavefront view SCENE.gltf [options]",
        "Opens a window on SCENE (.gltf or .glb) and path traces it progressively: the image\n"
        "refines while you look, and restarts whenever the camera or a render setting changes.\n"
        "The first view is the one `wavefront render` renders.",
        {
            {"--width", "", "W", "initial window width in screen coordinates (default 512)"},
            {"--height", "", "H", "initial window height (default: width / the camera's aspect)"},
            {"--spp", "", "N", "stop refining at N samples per pixel (default: never)"},
            {"--max-depth", "", "D", "path segments from the camera (default 16)"},
            {"--rr-depth", "", "N", "Russian roulette from bounce N on (default 3)"},
            {"--sampler", "", "NAME", "sample pattern as for render; finite sets stop at --spp "
                                      "or 256"},
            {"--light-sampling", "", "MODE", "bsdf, nee or mis, as for render (default mis)"},
            {"--triangle-sampling", "", "MODE", "area or solid-angle, as for render (default "
                                                "solid-angle)"},
            {"--sphere-sampling", "", "MODE", "area or solid-angle, as for render (default "
                                              "solid-angle)"},
            {"--min-throughput", "", "T", "end paths below throughput T (biased; default 0: "
                                          "off)"},
            {"--clamp", "", "X", "clamp each contribution to X (biased; default 0: off)"},
            {"--env", "", "FILE.exr", "equirectangular environment map, as for render"},
            {"--seed", "", "S", "random seed, as for render (default 0)"},
            {"--exposure", "", "EV", "display exposure in stops: radiance x 2^EV (default 0)"},
            {"--tonemap", "", "MODE", "linear (clamp, as render's PNG) or aces (filmic) "
                                      "(default linear)"},
            {"--target-ms", "", "MS", "path tracing per frame aims at MS ms (default 33)"},
            {"--camera", "", "NAME|INDEX", "the file's camera, or the framing one after them "
                                           "(default: render's)"},
            {"--no-overlay", "", "", "start with the overlay hidden (H shows it)"},
            {"--device", "", "N", "Vulkan device index (default: WAVEFRONT_DEVICE, else the "
                                  "first GPU)"},
            {"--frames", "", "N", "quit after N frames (scripts, tests)"},
            {"--screenshot", "", "FILE.exr", "on quit, write the radiance (and FILE.png, as "
                                             "shown)"},
            {"--resize-at", "", "F:WxH", "after frame F, resize the window to W x H (tests)"},
            {"--orbit", "", "DEG", "orbit DEG degrees per frame, as a drag would (benchmarks)"},
            {"--quiet", "-q", "", "print nothing but errors"},
        },
        std::string("Mouse and keys:\n") + kViewerControlsHelp +
            "\n"
            "Environment: as for render (WAVEFRONT_DEVICE, WAVEFRONT_VALIDATION=1, "
            "WAVEFRONT_SHADER_DIR,\n"
            "WAVEFRONT_CACHE_DIR). A display is needed: on a headless machine use xvfb-run.\n"
            "\n"
            "Exit codes: 0 quit (Esc, closing the window, SIGINT/SIGTERM or --frames), 2 bad "
            "usage or\n"
            "bad input, 1 internal or device failure, or validation messages were counted.\n"};
    return spec;
}

ResizeAt parseResizeAt(const std::string& text) {
    unsigned frame = 0, width = 0, height = 0;
    char end = 0;
    if (std::sscanf(text.c_str(), "%u:%ux%u%c", &frame, &width, &height, &end) != 3 ||
        frame == 0 || width == 0 || height == 0 || width > 16384 || height > 16384)
        throw UsageError("--resize-at expects FRAME:WIDTHxHEIGHT (e.g. 3:160x120), got '" +
                         text + "'");
    return {frame, int(width), int(height)};
}

} // namespace

std::string viewHelp() { return helpText(viewSpec()); }

int runViewCommand(const std::vector<std::string>& args) {
    ParsedArgs parsed = parseArgs(viewSpec(), args);
    if (parsed.has("--help")) {
        std::fputs(viewHelp().c_str(), stdout);
        return 0;
    }
    if (parsed.positional.size() != 1)
        throw UsageError("view needs exactly one scene file (see wavefront view --help)");

    ViewerOptions options;
    options.scenePath = parsed.positional.front();
    options.windowWidth = int(parsed.uintValue("--width", 0, 1, 16384));
    options.windowHeight = int(parsed.uintValue("--height", 0, 1, 16384));
    ViewSettings& settings = options.settings;
    settings.sppLimit = parsed.uintValue("--spp", 0, 1, 1u << 20);
    settings.render.maxDepth = parsed.uintValue("--max-depth", 16, 1, 1024);
    settings.render.rrDepth = parsed.uintValue("--rr-depth", 3, 0, 1024);
    settings.render.seed = parsed.uintValue("--seed", 0, 0, 0xffffffffu);
    settings.render.sampler = parseSampler(
        parsed.choiceValue("--sampler", samplerName(kDefaultSampler), samplerNames()));
    settings.render.lightSampling =
        parseLightSampling(parsed.choiceValue("--light-sampling", "mis", {"bsdf", "nee", "mis"}));
    settings.render.triangleSolidAngle = parsed.choiceValue("--triangle-sampling", "solid-angle",
                                                            {"area", "solid-angle"}) ==
                                         "solid-angle";
    settings.render.sphereSolidAngle = parsed.choiceValue("--sphere-sampling", "solid-angle",
                                                          {"area", "solid-angle"}) ==
                                       "solid-angle";
    settings.render.minThroughput = parsed.floatValue("--min-throughput", 0.0f, 0.0f, 1e30f);
    settings.render.clampRadiance = parsed.floatValue("--clamp", 0.0f, 0.0f, 1e30f);
    settings.exposure = parsed.floatValue("--exposure", 0.0f, -64.0f, 64.0f);
    settings.tonemap = parsed.choiceValue("--tonemap", "linear", {"linear", "aces"}) == "aces"
                           ? Tonemap::Aces
                           : Tonemap::Linear;
    settings.targetMs = parsed.floatValue("--target-ms", 33.0f, 1.0f, 60000.0f);
    options.camera = parsed.value("--camera");
    options.environmentPath = parsed.value("--env").value_or("");
    options.overlay = !parsed.has("--no-overlay");
    if (parsed.has("--device"))
        options.device = static_cast<int>(parsed.uintValue("--device", 0, 0, 64));
    options.frames = parsed.uintValue("--frames", 0, 1, 1u << 30);
    if (auto screenshot = parsed.value("--screenshot")) {
        if (fs::path(*screenshot).extension() != ".exr")
            throw UsageError("--screenshot must end in .exr, got '" + *screenshot + "'");
        const fs::path folder = fs::path(*screenshot).parent_path();
        if (!folder.empty() && !fs::is_directory(folder))
            throw InputError("cannot write " + *screenshot + ": folder " + folder.string() +
                             " does not exist");
        options.screenshot = *screenshot;
    }
    if (auto resize = parsed.value("--resize-at"))
        options.resizeAt = parseResizeAt(*resize);
    options.orbitDegrees = parsed.floatValue("--orbit", 0.0f, -180.0f, 180.0f);
    options.quiet = parsed.has("--quiet");
    return runViewer(options);
}

} // namespace wf
