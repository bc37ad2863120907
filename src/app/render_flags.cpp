// wavefront render's flags: the table behind --help and parsing, and the checks and keys
// made from them before anything is loaded.
#include "app/render_flags.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "app/commands.h"
#include "app/render_options.h"
#include "errors.h"
#include "render/samplers/samplers.h"

namespace wf {

const CommandSpec& renderSpec() {
    static const CommandSpec spec{
        "render",
        "wavefront render SCENE.gltf -o OUT.exr [options]",
        "Path traces SCENE (.gltf or .glb) and writes linear radiance to OUT.exr (float32 RGB,\n"
        "with spp, seed and render time as header attributes) and a tonemapped sRGB preview\n"
        "beside it (OUT.png).",
        joinOptions({
            {
                {"--output", "-o", "OUT.exr", "output OpenEXR file (required; must end in .exr)"},
                {"--frames", "", "A..B[:STEP]", "a sequence: frames A to B (every STEP-th), each "
                                               "posed at frame / --fps seconds and written to "
                                               "-o's pattern (e.g. out/frame_%04d.exr); the "
                                               "device, pipelines and tree are kept between "
                                               "frames"},
                {"--frame-bvh", "", "MODE", "with --frames: auto (default: refit the last "
                                            "built tree to the moved triangles while the "
                                            "slower tracing it brings costs less than a "
                                            "build), refit (always, until its cost grows "
                                            "1.5x) or rebuild (a new tree every frame)"},
                {"--spp", "", "N", "samples per pixel (default 64); with --target-error, the "
                                  "most any pixel gets (default 1024)"},
                {"--time-limit", "", "SECONDS", "stop before the sample pass that would end past "
                                                "SECONDS of rendering (at least one pass; the EXR's "
                                                "spp says how many were done; not with the "
                                                "finite-set samplers); with --target-error, "
                                                "whichever comes first"},
                {"--target-error", "", "R", "adaptive sampling: a pilot pass, then per-pixel "
                                            "sample counts that bring the image's estimated "
                                            "relMSE to R, in rounds (each image the next one's "
                                            "pilot) until the image's own error estimate is "
                                            "reliable and at most R, --spp caps every pixel or "
                                            "the time limit comes; --spp the most any pixel gets "
                                            "(default then 1024); unbiased (only the last round "
                                            "is in the image); the EXR and JSON say targetMet "
                                            "and why it stopped; not with --checkpoint, "
                                            "--resume, --spp-offset or the finite-set samplers"},
                {"--checkpoint", "", "FILE.exr", "write the image so far there every "
                                                 "--checkpoint-every seconds and on SIGINT or "
                                                 "SIGTERM (which then end the render, exit 130 or "
                                                 "143)"},
                {"--checkpoint-every", "", "SECONDS", "seconds between checkpoints (default 60)"},
                {"--aov", "", "LIST", "extra EXR layers, comma-separated: albedo, normal (the "
                                      "camera ray's first hit, as denoisers want them), depth, "
                                      "variance (of each pixel's estimate), samples (each "
                                      "pixel's sample count)"},
                {"--tonemap", "", "MODE", tonemapHelp()},
                {"--resume", "", "FILE.exr", "continue that checkpoint of this very render "
                                             "(scene, size, settings, seed) to --spp: the image "
                                             "of an uninterrupted run"},
            },
            imageSizeOptions(kRenderDefaultWidth),
            depthOptions(kRenderDefaultMaxDepth),
            lensOptions(),
            samplingOptions(),
            {
                noRandomizeOption(),
                {"--spp-offset", "", "N", "first sample index: renders samples N .. N+spp-1, so "
                                          "partial renders merge (default 0)"},
                {"--spp-total", "", "N", "stratified, multijitter, hammersley: samples in the "
                                         "whole set that this part belongs to (default offset + "
                                         "spp)"},
                {"--json", "", "STATS.json", "write statistics: spp, seconds, paths/s, rays/s"},
                deviceOption(),
                traversalOption(),
                quietOption(),
                cameraOption(),
                envOption(),
                instancingOption(),
                variantOption(),
            },
            animationOptions(),
            {
                {"--verbose", "-v", "",
                 "print the scene summary and load time, BVH build, shader variant, GPU and "
                 "peak host memory"},
            },
        }),
        "Environment:\n"
        "  WAVEFRONT_DEVICE=N        Vulkan device index, as --device\n"
        "  WAVEFRONT_VALIDATION=1    enable the Khronos validation layer (messages to stderr)\n"
        "  WAVEFRONT_SHADER_DIR=DIR  GLSL sources (default: next to the binary, else the source "
        "tree)\n"
        "  WAVEFRONT_CACHE_DIR=DIR   SPIR-V cache (default ~/.cache/wavefront; empty: none)\n"
        "  LP_NUM_THREADS=N          lavapipe's threads (default here: twice the CPU cores)\n"
        "\n"
        "Exit codes: 0 done, 2 bad usage or bad input, 1 internal or device failure; with\n"
        "--checkpoint, 130 or 143 after SIGINT or SIGTERM (the checkpoint written).\n"};
    return spec;
}

std::string renderHelp() { return helpText(renderSpec()); }

// --spp-offset, --spp-total (after settings.samplesPerPixel).
void applySppRangeFlags(const ParsedArgs& parsed, RenderSettings& settings) {
    settings.sppOffset = parsed.uintValue("--spp-offset", 0, 0, 1u << 30);
    const uint32_t total = settings.sppOffset + settings.samplesPerPixel;
    settings.sampleSetSize = parsed.uintValue("--spp-total", total, 1, 1u << 31);
    if (settings.sampleSetSize < total)
        throw UsageError("--spp-total " + std::to_string(settings.sampleSetSize) +
                         " is less than --spp-offset + --spp = " + std::to_string(total));
}

// --aov's names, each once, in a fixed set.
std::vector<std::string> parseAovList(const std::string& list) {
    std::vector<std::string> names;
    std::stringstream words(list);
    for (std::string word; std::getline(words, word, ',');) {
        if (word != "albedo" && word != "normal" && word != "depth" && word != "variance" &&
            word != "samples")
            throw UsageError("--aov: unknown layer '" + word +
                             "' (layers: albedo, normal, depth, variance, samples)");
        if (std::find(names.begin(), names.end(), word) != names.end())
            throw UsageError("--aov names '" + word + "' twice");
        names.push_back(word);
    }
    if (!list.empty() && names.empty())
        throw UsageError("--aov needs at least one layer");
    return names;
}

// Everything that shapes the image but the seed and the sample range (their own attributes):
// parts merge only when this agrees (image/render_parts.h).
std::string renderSettingsKey(const RenderSettings& s, const ParsedArgs& parsed) {
    char numbers[160];
    std::snprintf(numbers, sizeof numbers,
                  "%ux%u depth %u rr %u min-throughput %g clamp %g", s.width, s.height,
                  s.maxDepth, s.rrDepth, s.minThroughput, s.clampRadiance);
    return std::string(numbers) + " " +
           (s.integrator == Integrator::Path ? "" : std::string("integrator ") +
                                                        integratorName(s.integrator) + " ") +
           (s.bdptBalance ? "balance " : "") +
           (s.integrator == Integrator::Vcm ? "vcm-radius " + std::to_string(s.vcmRadius) + " "
                                            : std::string()) +
           (s.integrator != Integrator::Path && s.lightShare > 0
                ? "light-share " + std::to_string(s.lightShare) + " "
                : std::string()) +
           lightSamplingName(s.lightSampling) + " " +
           lightSelectionName(s.lightSelection) + " triangle " +
           (s.triangleSolidAngle ? "solid-angle" : "area") + " sphere " +
           (s.sphereSolidAngle ? "solid-angle" : "area") + " " + samplerName(s.sampler) +
           (s.randomizeSamples ? "" : " no-randomize") +
           // Replicates are sequences of their own: parts of another count are another render.
           (errorReplicatesFor(s) > 1 ? " replicates " + std::to_string(errorReplicatesFor(s))
                                      : "") +
           (s.textureLod ? "" : " texture-filter none") + " camera " +
           parsed.value("--camera").value_or("default") +
           (parsed.has("--aperture") ? " aperture " + *parsed.value("--aperture") : "") +
           (parsed.has("--focus-distance") ? " focus " + *parsed.value("--focus-distance") : "") +
           (parsed.has("--target-error") ? " target-error " + *parsed.value("--target-error")
                                         : "") +
           // Parts of different times or animations are different renders.
           (parsed.has("--time") ? " time " + *parsed.value("--time") : "") +
           (parsed.has("--frame") ? " frame " + *parsed.value("--frame") + " fps " +
                                        parsed.value("--fps").value_or("24")
                                  : "") +
           (parsed.has("--animation") ? " animation " + *parsed.value("--animation") : "") +
           (parsed.has("--variant") ? " variant " + *parsed.value("--variant") : "") +
           (parsed.has("--shutter") ? " shutter " + *parsed.value("--shutter") + " fps " +
                                          parsed.value("--fps").value_or("24")
                                    : "");
}

std::string spectralSettingFor(const RenderSettings& s, const std::vector<Material>& materials) {
    const bool disperses = std::any_of(materials.begin(), materials.end(),
                                       [](const Material& m) {
                                           return gpu_types::materialDisperses(m);
                                       });
    return disperses ? spectralSamplingName(s.spectral) : "";
}

// --target-error refuses what would need a sample range it does not have.
void checkAdaptiveFlags(const ParsedArgs& parsed, const RenderSettings& settings) {
    for (const char* flag : {"--checkpoint", "--resume", "--spp-offset", "--spp-total"})
        if (parsed.has(flag))
            throw UsageError(std::string("--target-error with ") + flag +
                             ": adaptive renders are whole renders (their sample counts differ "
                             "per pixel)");
    if (samplerIsFiniteSet(settings.sampler))
        throw UsageError(std::string("--target-error: the ") + samplerName(settings.sampler) +
                         " sampler's set is no stratification when a pixel takes part of it "
                         "(pick sobol, halton, independent or bluenoise)");
    if (settings.samplesPerPixel < 8)
        throw UsageError("--target-error needs --spp (the most samples a pixel gets) of at "
                         "least 8");
}

RenderRequest renderRequestFrom(const ParsedArgs& parsed) {
    RenderRequest request;
    RenderSettings& settings = request.settings;
    const bool adaptive = parsed.has("--target-error");
    settings.samplesPerPixel = parsed.uintValue("--spp", adaptive ? 1024 : 64, 1, 1u << 20);
    applyRenderFlags(parsed, kRenderDefaultMaxDepth, settings);
    applySppRangeFlags(parsed, settings);
    request.targetError = parsed.floatValue("--target-error", 0.0f, 1e-12f, 1e6f);
    if (adaptive) {
        checkAdaptiveFlags(parsed, settings);
        settings.pixelList = true;
    }
    settings.timeLimitSeconds = parsed.floatValue("--time-limit", 0.0f, 1e-3f, 1e9f);
    if (settings.timeLimitSeconds > 0.0 && samplerIsFiniteSet(settings.sampler))
        throw UsageError(std::string("--time-limit: the ") + samplerName(settings.sampler) +
                         " sampler's set is no stratification when cut short (pick sobol, "
                         "halton, independent or bluenoise)");
    request.aovs = parseAovList(parsed.value("--aov").value_or(""));
    // "samples" alone needs no first hits.
    settings.aov = std::any_of(request.aovs.begin(), request.aovs.end(),
                               [](const std::string& name) { return name != "samples"; });
    if (settings.aov && parsed.has("--resume"))
        throw UsageError("--aov with --resume: the layers would cover this run's samples only");
    return request;
}

} // namespace wf
