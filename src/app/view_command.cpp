// wavefront view: command line -> ViewerOptions -> the progressive viewer (src/viewer/).
#include <cstdio>
#include <filesystem>

#include "app/cli.h"
#include "app/commands.h"
#include "app/render_options.h"
#include "errors.h"
#include "viewer/overlay.h"
#include "viewer/viewer.h"

namespace fs = std::filesystem;

namespace wf {
namespace {

constexpr uint32_t kDefaultMaxDepth = 16;

const CommandSpec& viewSpec() {
    static const CommandSpec spec{
        "view",
        "wavefront view SCENE.gltf [options]",
        "Opens a window on SCENE (.gltf or .glb) and path traces it progressively: the image\n"
        "refines while you look, and restarts whenever the camera or a render setting changes.\n"
        "The first view is the one `wavefront render` renders.",
        joinOptions({
            {
                {"--width", "", "W", "initial window width in screen coordinates (default 512)"},
                {"--height", "", "H", "initial window height (default: width / the camera's "
                                      "aspect)"},
                {"--spp", "", "N", "stop refining at N samples per pixel (default: never; a "
                                   "finite-set sampler: 256)"},
            },
            depthOptions(kDefaultMaxDepth),
            samplingOptions(),
            {
                envOption(),
                instancingOption(),
                variantOption(),
            },
            animationOptions(),
            {
                {"--play", "", "", "start playing the animation (T plays and pauses; the "
                                   "overlay's slider sets the time)"},
            },
            {
                {"--exposure", "", "EV", "display exposure in stops: radiance x 2^EV (default 0)"},
                {"--tonemap", "", "MODE", tonemapHelp()},
                {"--target-ms", "", "MS", "path tracing per frame aims at MS ms (default 33)"},
                // The viewer's cameras: the file's, then the framing one (viewer/camera_list.h).
                {"--camera", "", "NAME|INDEX", "the file's camera, or the framing one after them "
                                               "(default: render's)"},
                {"--no-overlay", "", "", "start with the overlay hidden (H shows it)"},
                deviceOption(),
                traversalOption(),
                {"--frames", "", "N", "quit after N frames (scripts, tests)"},
                {"--until-done", "", "", "quit once the image reaches its --spp (after any "
                                         "--resize-at), however many frames that takes "
                                         "(scripts, tests)"},
                {"--screenshot", "", "FILE.exr", "on quit, write the radiance (and FILE.png, as "
                                                 "shown)"},
                {"--resize-at", "", "F:WxH", "after frame F, resize the window to W x H (tests)"},
                {"--orbit", "", "DEG", "orbit DEG degrees per frame, as a drag would (benchmarks)"},
                {"--quiet", "-q", "", "print nothing but errors"},
            },
        }),
        std::string("Mouse and keys:\n") + kViewerControlsHelp +
            "\n"
            "Environment: as for render (WAVEFRONT_DEVICE, WAVEFRONT_VALIDATION=1, "
            "WAVEFRONT_SHADER_DIR,\n"
            "WAVEFRONT_CACHE_DIR). A display is needed: on a headless machine use xvfb-run.\n"
            "\n"
            "Exit codes: 0 quit (Esc, closing the window, SIGINT/SIGTERM, --frames or "
            "--until-done), 2 bad usage or\n"
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
    std::optional<ParsedArgs> maybeParsed = parseSceneCommand(viewSpec(), args);
    if (!maybeParsed)
        return 0; // --help
    const ParsedArgs& parsed = *maybeParsed;

    ViewerOptions options;
    options.scenePath = parsed.positional.front();
    options.windowWidth = int(parsed.uintValue("--width", 0, 1, 16384));
    options.windowHeight = int(parsed.uintValue("--height", 0, 1, 16384));
    ViewSettings& settings = options.settings;
    settings.sppLimit = parsed.uintValue("--spp", 0, 1, 1u << 20);
    applyRenderFlags(parsed, kDefaultMaxDepth, settings.render);
    settings.exposure = parsed.floatValue("--exposure", 0.0f, -64.0f, 64.0f);
    settings.tonemap = parseTonemap(
        parsed.choiceValue("--tonemap", tonemapName(kDefaultTonemap), {"neutral", "aces", "linear"}));
    settings.targetMs = parsed.floatValue("--target-ms", 33.0f, 1.0f, 60000.0f);
    options.camera = parsed.value("--camera");
    options.environmentPath = parsed.value("--env").value_or("");
    if (auto mode = parsed.value("--instancing"))
        options.instancing = parseInstancing(*mode);
    options.time = sceneTimeFrom(parsed);
    if (parsed.has("--shutter"))
        throw UsageError("--shutter: the viewer shows one time (render, bench and converge "
                         "blur motion)");
    options.animation = parsed.value("--animation").value_or("");
    options.variant = parsed.value("--variant").value_or("");
    options.fps = parsed.floatValue("--fps", 24.0f, 1e-3f, 1e6f);
    options.play = parsed.has("--play");
    options.overlay = !parsed.has("--no-overlay");
    options.device = contextOptionsFrom(parsed).deviceIndex;
    options.rayTracing = traversalRequest(parsed);
    options.frames = parsed.uintValue("--frames", 0, 1, 1u << 30);
    options.untilDone = parsed.has("--until-done");
    if (options.untilDone && settings.effectiveSppLimit() == 0)
        throw UsageError("--until-done needs a sample limit: --spp N (or a finite-set sampler)");
    if (options.untilDone && options.play)
        throw UsageError("--until-done: a playing animation never finishes refining; use "
                         "--frames with --play");
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
