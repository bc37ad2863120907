// The frame loop of render --frames; one frame is the single render's plain path (load, build,
// render, write EXR + PNG) with the device, the compiler, the renderer and its pipelines, and
// (--frame-bvh refit) the tree kept between frames.
#include "app/render_loop/frame_sequence.h"

#include <chrono>
#include <cstdio>
#include <memory>

#include "app/render_options.h"
#include "errors.h"
#include "gpu/context.h"
#include "image/render_parts.h"
#include "render/film_error.h"
#include "render/gpu_scene/frame_scenes.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/wavefront_renderer.h"

namespace wf {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool parseUint(const std::string& text, uint32_t& out) {
    if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
        return false;
    out = uint32_t(std::stoul(text));
    return true;
}

} // namespace

std::vector<uint32_t> parseFrameRange(const std::string& text) {
    const std::string usage = "--frames " + text + ": expected A..B or A..B:STEP (frame numbers "
                                                   "A <= B, STEP >= 1)";
    const size_t dots = text.find("..");
    if (dots == std::string::npos)
        throw UsageError(usage);
    const size_t colon = text.find(':', dots);
    uint32_t first = 0, last = 0, step = 1;
    if (!parseUint(text.substr(0, dots), first) ||
        !parseUint(text.substr(dots + 2, colon == std::string::npos ? std::string::npos
                                                                    : colon - dots - 2),
                   last) ||
        (colon != std::string::npos && !parseUint(text.substr(colon + 1), step)) || step == 0 ||
        first > last)
        throw UsageError(usage);
    if ((last - first) / step >= 100000)
        throw UsageError("--frames " + text + ": more than 100,000 frames");
    std::vector<uint32_t> frames;
    for (uint64_t f = first; f <= last; f += step)
        frames.push_back(uint32_t(f));
    return frames;
}

std::string framePath(const std::string& pattern, uint32_t frame) {
    const std::string why = "-o " + pattern + ": with --frames the output names each frame "
                                              "with one %d or %0Nd, e.g. out/frame_%04d.exr";
    size_t at = std::string::npos;
    int width = 0;
    size_t end = 0;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%')
            continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') { // a literal percent
            ++i;
            continue;
        }
        if (at != std::string::npos)
            throw UsageError(why);
        size_t j = i + 1;
        if (j < pattern.size() && pattern[j] == '0') {
            ++j;
            if (j < pattern.size() && pattern[j] >= '1' && pattern[j] <= '9')
                width = pattern[j++] - '0';
            else
                throw UsageError(why);
        }
        if (j >= pattern.size() || pattern[j] != 'd')
            throw UsageError(why);
        at = i;
        end = j + 1;
    }
    if (at == std::string::npos)
        throw UsageError(why);
    std::string number = std::to_string(frame);
    if (number.size() < size_t(width))
        number.insert(0, size_t(width) - number.size(), '0');
    std::string out;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (i == at) {
            out += number;
            i = end - 1;
        } else {
            out += pattern[i];
            if (pattern[i] == '%')
                ++i; // "%%" is one percent sign
        }
    }
    return out;
}

void checkFrameFlags(const ParsedArgs& parsed) {
    for (const char* flag : {"--time", "--frame", "--resume", "--checkpoint", "--target-error",
                             "--json", "--aov"})
        if (parsed.has(flag))
            throw UsageError(std::string("--frames with ") + flag +
                             ": a sequence renders whole frames at frame / --fps seconds "
                             "(render one frame with --frame N for that)");
    framePath(*parsed.value("--output"), 0);
}

int runFrameSequence(const ParsedArgs& parsed, const RenderRequest& request) {
    checkFrameFlags(parsed);
    const std::vector<uint32_t> frames = parseFrameRange(*parsed.value("--frames"));
    const std::string pattern = *parsed.value("--output");
    const std::string scenePath = parsed.positional.front();
    const double fps = parsed.floatValue("--fps", 24.0f, 1e-3f, 1e6f);
    const bool quiet = parsed.has("--quiet");
    std::string sceneHash = fileHash(scenePath);
    if (auto env = parsed.value("--env"))
        sceneHash += "+" + fileHash(*env);

    const FrameBvh bvhMode = parseFrameBvh(parsed.value("--frame-bvh").value_or("auto"));

    const auto setupStart = std::chrono::steady_clock::now();
    Context context(contextOptionsFrom(parsed));
    ShaderCompiler compiler;
    const double setupSeconds = secondsSince(setupStart);
    // One renderer for the whole sequence while the frames need the same shaders and image
    // size: each frame's tables replace the last one's under the same pipelines.
    FrameScenes scenes(bvhMode);
    std::unique_ptr<WavefrontRenderer> renderer;
    RenderSettings rendererSettings;
    double firstSeconds = 0.0, restSeconds = 0.0;
    uint32_t refits = 0, newRenderers = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
        const uint32_t frame = frames[i];
        const double time = double(frame) / fps;
        const auto start = std::chrono::steady_clock::now();
        Scene scene = loadSceneWithFlags(parsed, scenePath, nullptr, time, i == 0);
        RenderSettings settings = request.settings;
        settings.traversal = traversalFor(context); // as render's: rt where the context has it
        applyImageSize(parsed, scene.camera,
                       {.width = kRenderDefaultWidth, .widthFollowsHeight = true}, settings);
        const double loadSeconds = secondsSince(start);
        const PreparedScene& prepared = scenes.prepare(std::move(scene));
        refits += scenes.refitted() ? 1 : 0;
        resolveGuiding(settings, prepared); // --guiding auto, per frame's scene
        const double buildSeconds = secondsSince(start) - loadSeconds;
        const bool sameImage = renderer && settings.width == rendererSettings.width &&
                               settings.height == rendererSettings.height &&
                               settings.guiding == rendererSettings.guiding;
        const bool reused = sameImage && renderer->setScene(prepared);
        if (!reused) {
            renderer.reset(); // its buffers go before the next renderer's are made
            renderer = std::make_unique<WavefrontRenderer>(context, prepared, settings, compiler);
            rendererSettings = settings;
            ++newRenderers;
        }
        const double setup = secondsSince(start) - loadSeconds - buildSeconds;
        renderer->render();
        scenes.rendered(renderer->stats().seconds);
        RenderPart part;
        part.width = int(settings.width);
        part.height = int(settings.height);
        part.scene = scenePath;
        part.sceneHash = sceneHash;
        const std::string spectral = spectralSettingFor(settings, prepared.materials);
        part.renderSettings = renderSettingsKey(settings, parsed) +
                              (spectral.empty() ? "" : " spectral " + spectral) + " frame " +
                              std::to_string(frame) + " fps " + std::to_string(fps);
        part.sampler = samplerName(settings.sampler);
        part.seed = int(settings.seed);
        part.maxDepth = int(settings.maxDepth);
        part.sppOffset = settings.sppOffset;
        part.sppTotal = settings.sampleSetSize;
        part.previewTonemap = previewTonemapFrom(parsed);
        part.spp = renderer->samplesDone();
        part.rgb = renderer->readImage();
        part.renderSeconds = renderer->stats().seconds;
        const std::string out = framePath(pattern, frame);
        char timeText[32];
        std::snprintf(timeText, sizeof timeText, "%.9g", time);
        writeRenderPart(out, part, {{"sceneTime", timeText}, {"frame", std::to_string(frame)}},
                        true);
        const double seconds = secondsSince(start);
        (i == 0 ? firstSeconds : restSeconds) += seconds;
        if (!quiet)
            std::fprintf(stderr,
                         "wavefront: frame %u (t = %.4g s) %.3f s: load and pose %.3f, BVH %.3f "
                         "(%s, cost %.2fx built), %s %.3f, render %.3f; wrote %s\n",
                         frame, time, seconds, loadSeconds, buildSeconds,
                         scenes.refitted() ? "refit" : "built", scenes.costRatio(),
                         reused ? "upload (pipelines kept)" : "pipelines and upload", setup,
                         renderer->stats().seconds, out.c_str());
    }
    if (!quiet)
        std::fprintf(stderr,
                     "wavefront: %zu frames: device %.3f s, first frame %.3f s, the others "
                     "%.3f s each on average; %u refit, %u with new pipelines\n",
                     frames.size(), setupSeconds, firstSeconds,
                     frames.size() > 1 ? restSeconds / double(frames.size() - 1) : 0.0, refits,
                     newRenderers);
    if (context.validationMessageCount() != 0) {
        std::fprintf(stderr, "wavefront: %u validation message(s)\n",
                     context.validationMessageCount());
        return 1;
    }
    return 0;
}

} // namespace wf
