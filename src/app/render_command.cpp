// wavefront render: load, build, trace all samples in waves, write EXR + PNG (+ JSON stats).
// Its flags and their checks are render_flags.cpp's; this file is the run.
#include <chrono>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/cli.h"
#include "app/reports/host_memory.h"
#include "app/commands.h"
#include "app/render_loop/frame_sequence.h"
#include "app/render_loop/progress_line.h"
#include "app/render_flags.h"
#include "app/render_options.h"
#include "app/render_loop/signal_stop.h"
#include "app/reports/stats_json.h"
#include "errors.h"
#include "gpu/context.h"
#include "image/render_parts.h"
#include "render/adaptive_sampling.h"
#include "render/film_error.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/guiding/guiding_schedule.h"
#include "render/guiding/sd_tree.h"
#include "render/integrator_support.h"
#include "render/wavefront_renderer.h"
#include "scene/scene_summary.h"

namespace fs = std::filesystem;

namespace wf {
namespace {

constexpr const char* kVcmEstimatorNote =
    "consistent, not unbiased: vertex merging blurs light over mergeRadius, which shrinks as "
    "samples grow (r (i + 1)^-1/8 at sample i)";
constexpr const char* kVcmErrorNote =
    "variance only: merging's bias is not included";

// The layers as Cycles names its passes, one channel each.
std::vector<ExrChannel> aovChannels(const std::vector<std::string>& names, const AovImages& aov,
                                    const std::vector<float>& sampleCounts) {
    std::vector<ExrChannel> channels;
    auto add = [&](const std::string& layer, const char* suffixes, const std::vector<float>& data,
                   int stride) {
        for (int c = 0; suffixes[c] != '\0'; ++c) {
            ExrChannel channel{layer + "." + suffixes[c], {}};
            channel.values.resize(data.size() / stride);
            for (size_t i = 0; i < channel.values.size(); ++i)
                channel.values[i] = data[i * stride + c];
            channels.push_back(std::move(channel));
        }
    };
    for (const std::string& name : names) {
        if (name == "albedo")
            add("Denoising Albedo", "RGB", aov.albedo, 3);
        else if (name == "normal")
            add("Denoising Normal", "XYZ", aov.normal, 3);
        else if (name == "depth")
            add("Depth", "Z", aov.depth, 1);
        else if (name == "variance")
            add("Denoising Variance", "RGB", aov.variance, 3);
        else
            add("Sample Count", "Y", sampleCounts, 1);
    }
    return channels;
}

void printVerbose(const PreparedScene& scene, const WavefrontRenderer& renderer,
                  const Context& context, const SceneSummary& summary) {
    std::fprintf(stderr, "wavefront: device %s (%s), subgroup size %u\n",
                 context.deviceName().c_str(), context.driverInfo().c_str(),
                 context.subgroupSize());
    std::fprintf(stderr, "wavefront: scene loaded in %.3f s: %s\n", summary.loadSeconds,
                 describe(summary).c_str());
    const BvhBuildStats& bvh = scene.bvhStats;
    std::fprintf(stderr,
                 "wavefront: %zu triangles, %zu materials, %zu emitters; BVH %u nodes, depth %u, "
                 "traversal cost %g, SAH cost %.2f, built in %.3f s (%.3g M triangles/s on %u "
                 "threads)\n",
                 scene.triangles.size(), scene.materials.size(), scene.lights.emitters.size(),
                 bvh.nodeCount, bvh.maxDepth, bvh.traversalCost, bvh.sahCost, bvh.buildSeconds,
                 scene.triangles.size() / std::max(bvh.buildSeconds, 1e-9) / 1e6, bvh.threads);
    if (!scene.instances.empty())
        std::fprintf(stderr,
                     "wavefront: two-level BVH: %zu instances of %u meshes and the world "
                     "geometry, %llu triangles as placed\n",
                     scene.instances.size(), scene.meshCount,
                     static_cast<unsigned long long>(scene.instancedTriangles));
    std::fprintf(stderr, "wavefront: traversal: %s\n", describeTraversal(renderer).c_str());
    std::fprintf(stderr, "wavefront: light selection: %s\n",
                 describeLightSelection(scene, renderer.variant()).c_str());
    std::fprintf(stderr, "wavefront: shader variant: %s; up to %u paths per wave\n",
                 renderer.variant().describe().c_str(), renderer.pathCapacity());
    uint64_t total = 0;
    for (const auto& [name, bytes] : renderer.memoryReport()) {
        std::fprintf(stderr, "wavefront:   %-18s %10.2f KiB\n", name.c_str(), bytes / 1024.0);
        total += bytes;
    }
    std::fprintf(stderr, "wavefront:   %-18s %10.2f MiB\n", "total GPU memory",
                 total / (1024.0 * 1024.0));
}

// Peak host memory, once the render is done: --verbose prints it, --json records it.
void reportPeakHostMemory(bool verbose, StatsContext& statsContext) {
    const uint64_t peak = peakHostMemoryBytes();
    if (verbose)
        std::fprintf(stderr, "wavefront: peak host memory %.1f MiB\n", peak / (1024.0 * 1024.0));
    statsContext.extraFields.push_back({"peakHostMemoryBytes", std::to_string(peak)});
}

// 1 (and a line saying so) when the validation layer spoke, else 0.
int validationExitCode(const Context& context) {
    if (context.validationMessageCount() == 0)
        return 0;
    std::fprintf(stderr, "wavefront: %u validation message(s)\n",
                 context.validationMessageCount());
    return 1;
}

// --guiding: one --verbose line per training iteration, and the JSON's "guiding" object.
void reportGuiding(bool verbose, const RenderStats& stats, StatsContext& statsContext) {
    std::string iterations;
    double training = 0.0;
    for (size_t i = 0; i < stats.guideIterations.size(); ++i) {
        const auto& it = stats.guideIterations[i];
        training += it.seconds + it.rebuildSeconds;
        if (verbose)
            std::fprintf(stderr, "wavefront: guiding iteration %zu: %u spp, %llu spatial leaves, "
                                 "%llu directional nodes, BSDF share %.2f (%llu leaves sample "
                                 "the guide, %llu pay), %.3f s render + %.3f s rebuild\n",
                         i, it.samplesPerPixel, static_cast<unsigned long long>(it.spatialLeaves),
                         static_cast<unsigned long long>(it.directionalNodes),
                         it.meanBsdfFraction, static_cast<unsigned long long>(it.guidedLeaves),
                         static_cast<unsigned long long>(it.payingLeaves), it.seconds,
                         it.rebuildSeconds);
        iterations += std::string(i ? ", " : "") + "{\"spp\": " +
                      std::to_string(it.samplesPerPixel) + ", \"spatialLeaves\": " +
                      std::to_string(it.spatialLeaves) + ", \"directionalNodes\": " +
                      std::to_string(it.directionalNodes) + ", \"bsdfFraction\": " +
                      jsonNumber(it.meanBsdfFraction) + ", \"guidedLeaves\": " +
                      std::to_string(it.guidedLeaves) + ", \"payingLeaves\": " +
                      std::to_string(it.payingLeaves) + ", \"seconds\": " +
                      jsonNumber(it.seconds) + ", \"rebuildSeconds\": " +
                      jsonNumber(it.rebuildSeconds) + "}";
    }
    std::string weights;
    for (size_t i = 0; i < stats.guideWeights.size(); ++i)
        weights += std::string(i ? ", " : "") + jsonNumber(stats.guideWeights[i]);
    if (verbose && stats.guideStoppedUnused)
        std::fprintf(stderr, "wavefront: guiding: training stopped: in %u iterations in a row "
                             "no leaf learnt a share that pays (one that cuts %.0f%% of its "
                             "paths' variance); the rest samples the BSDF alone\n",
                     guiding::kUnusedIterationsToStop, 100.0 * guiding::kMinVarianceCut);
    if (verbose)
        std::fprintf(stderr, "wavefront: guiding: %.3f s training, the image from %u spp (%s)\n",
                     training, stats.guideFinalSamples,
                     weights.empty() ? "the last iteration"
                                     : ("iterations weighted " + weights).c_str());
    statsContext.extraFields.push_back(
        {"guiding", "{\"iterations\": [" + iterations + "], \"trainingSeconds\": " +
                        jsonNumber(training) + ", \"stoppedUnused\": " +
                        (stats.guideStoppedUnused ? "true" : "false") +
                        ", \"weights\": [" + weights + "]" +
                        ", \"imageSpp\": " +
                        std::to_string(stats.guideFinalSamples) + ", \"memoryBytes\": " +
                        std::to_string(stats.guideBytes) + "}"});
}

struct OutputRequest {
    std::string exr;
    std::optional<std::string> json;
    std::vector<std::string> aovs;
    bool quiet = false;
};

// The --target-error render: pilot, allocation, rounds (render/adaptive_sampling.h).
void renderAdaptively(WavefrontRenderer& renderer, const RenderSettings& settings,
                      double targetError, RenderPart run, bool verbose,
                      const OutputRequest& output, StatsContext statsContext) {
    AdaptiveSettings adaptive;
    adaptive.targetError = targetError;
    adaptive.maxSpp = settings.samplesPerPixel;
    adaptive.timeLimitSeconds = settings.timeLimitSeconds;
    ProgressLine progress(!output.quiet, settings.timeLimitSeconds);
    const AdaptiveResult result = renderAdaptive(
        renderer, settings.seed, adaptive, settings.width, settings.height,
        [&](const AdaptiveProgress& round) { progress.update(round, targetError); });
    const SampleAllocation& allocation = result.allocation;
    run.path = "this render";
    run.spp = static_cast<uint32_t>(std::lround(result.meanSpp));
    run.rgb = result.rgb;
    run.renderSeconds = result.stats.seconds;
    run.errorEstimate = result.estimate;
    std::vector<std::pair<std::string, std::string>> attributes;
    if (settings.guiding) {
        attributes = {{"guiding", "on"},
                      {"guidingIterations", std::to_string(result.stats.guideIterations.size())},
                      {"guidingImageSpp", std::to_string(result.stats.guideFinalSamples)}};
        reportGuiding(verbose, result.stats, statsContext);
    }
    char numbers[4][32];
    std::snprintf(numbers[0], sizeof numbers[0], "%g", targetError);
    std::snprintf(numbers[1], sizeof numbers[1], "%.6g", allocation.predictedRelMse);
    std::snprintf(numbers[2], sizeof numbers[2], "%.6g", result.meanSpp);
    std::snprintf(numbers[3], sizeof numbers[3], "%u", result.pilotSpp);
    attributes.insert(attributes.end(),
                      {{"targetError", numbers[0]},
                       {"targetMet", result.targetMet ? "true" : "false"},
                       {"stoppedBy", result.stoppedBy}, {"predictedRelMse", numbers[1]},
                       {"meanSpp", numbers[2]}, {"pilotSpp", numbers[3]},
                       {"imageRounds", std::to_string(result.imageRounds)},
                       {"minSpp", std::to_string(allocation.levels.front())},
                       {"maxSpp", std::to_string(settings.samplesPerPixel)}});
    writeRenderPart(output.exr, run, attributes, true,
                    output.aovs.empty()
                        ? std::vector<ExrChannel>{}
                        : aovChannels(output.aovs,
                                      settings.aov ? renderer.readAovs() : AovImages{},
                                      result.sampleCounts));
    reportPeakHostMemory(verbose, statsContext);
    if (output.json) {
        StatsContext& context = statsContext;
        context.extraFields.push_back({"errorEstimate", errorEstimateJson(result.estimate)});
        context.extraFields.push_back(
            adaptiveStatsField(result, targetError, settings.samplesPerPixel));
        RenderStats stats = result.stats;
        stats.samplesPerPixel = run.spp;
        writeStatsJson(*output.json, stats, context);
    }
    if (!result.targetMet) {
        const std::string why =
            result.stoppedBy == "time-limit" ? "the time limit came"
            : result.stoppedBy == "rounds"   ? "the rounds ran out"
                                             : "every pixel reached --spp " +
                                                 std::to_string(settings.samplesPerPixel);
        std::fprintf(stderr,
                     "wavefront: warning: target relMSE %g not met: %s after %u image round%s "
                     "(%.1f spp on average in the image, %llu paths in all); the image's "
                     "estimated relMSE is %s%s\n",
                     targetError, why.c_str(), result.imageRounds,
                     result.imageRounds == 1 ? "" : "s", result.meanSpp,
                     static_cast<unsigned long long>(result.stats.paths),
                     describeErrorEstimate(result.estimate).c_str(),
                     result.estimate.reliable ? "" : (": " + result.estimate.reason).c_str());
    }
    if (!output.quiet)
        std::fprintf(stderr, "wavefront: wrote %s and %s (adaptive: %.1f spp on average, %u to "
                             "%u, %u image round%s; estimated relMSE %s for a target of %g; "
                             "%.0f paths/s)\n",
                     output.exr.c_str(), previewPathFor(output.exr).c_str(), result.meanSpp,
                     allocation.levels.front(), settings.samplesPerPixel, result.imageRounds,
                     result.imageRounds == 1 ? "" : "s",
                     describeErrorEstimate(result.estimate).c_str(), targetError,
                     result.stats.paths / std::max(result.stats.seconds, 1e-9));
}

} // namespace

int runRenderCommand(const std::vector<std::string>& args) {
    std::optional<ParsedArgs> maybeParsed = parseSceneCommand(renderSpec(), args);
    if (!maybeParsed)
        return 0; // --help
    const ParsedArgs& parsed = *maybeParsed;
    auto output = parsed.value("--output");
    if (!output || output->empty())
        throw UsageError("render needs -o OUT.exr (see wavefront render --help)");
    if (fs::path(*output).extension() != ".exr")
        throw UsageError("output file must end in .exr, got '" + *output + "'");
    const fs::path outputDir = fs::path(*output).parent_path();
    if (!outputDir.empty() && !fs::is_directory(outputDir))
        throw InputError("cannot write " + *output + ": folder " + outputDir.string() +
                         " does not exist");

    RenderRequest request = renderRequestFrom(parsed);
    if (parsed.has("--frames"))
        return runFrameSequence(parsed, request);
    if (parsed.has("--frame-bvh"))
        throw UsageError("--frame-bvh applies to --frames");
    RenderSettings& settings = request.settings;
    const bool adaptive = request.targetError > 0.0;
    const double targetError = request.targetError;
    const std::vector<std::string>& aovs = request.aovs;
    const bool quiet = parsed.has("--quiet");
    const bool verbose = parsed.has("--verbose");

    const std::string scenePath = parsed.positional.front();
    SceneSummary summary;
    Scene scene = loadSceneWithFlags(parsed, scenePath, &summary);
    applyImageSize(parsed, scene.camera, {.width = kRenderDefaultWidth, .widthFollowsHeight = true},
                   settings);

    // What this render is, as its parts and checkpoints say it (image/render_parts.h).
    RenderPart run;
    run.width = static_cast<int>(settings.width);
    run.height = static_cast<int>(settings.height);
    run.scene = scenePath;
    run.sceneHash = fileHash(scenePath);
    if (auto env = parsed.value("--env"))
        run.sceneHash += "+" + fileHash(*env);
    run.renderSettings = renderSettingsKey(settings, parsed);
    const std::string spectral = spectralSettingFor(settings, scene.materials);
    if (!spectral.empty())
        run.renderSettings += " spectral " + spectral;
    run.sampler = samplerName(settings.sampler);
    run.seed = static_cast<int>(settings.seed);
    run.maxDepth = static_cast<int>(settings.maxDepth);
    run.sppOffset = settings.sppOffset;
    run.sppTotal = settings.sampleSetSize;
    run.previewTonemap = previewTonemapFrom(parsed);

    // --resume: the checkpoint holds samples [offset, offset + done); render the rest.
    std::optional<RenderPart> resumed;
    if (auto path = parsed.value("--resume")) {
        resumed = readRenderPart(*path);
        RenderPart rest = run;
        rest.path = "this render";
        checkSameRender({*resumed, rest});
        if (resumed->sppOffset != settings.sppOffset)
            throw InputError(*path + ": a checkpoint of samples from " +
                             std::to_string(resumed->sppOffset) + ", this render starts at " +
                             std::to_string(settings.sppOffset) + " (--spp-offset)");
        if (resumed->spp >= settings.samplesPerPixel)
            throw InputError(*path + ": already holds " + std::to_string(resumed->spp) +
                             " samples per pixel, --spp asks for " +
                             std::to_string(settings.samplesPerPixel));
    }
    // --guiding with --checkpoint and --resume: the guide is not saved; a resumed render
    // trains its own over the samples it renders (each part unbiased, merged by sample count).
    const uint32_t resumedSpp = resumed ? resumed->spp : 0u;
    RenderSettings rest = settings;
    rest.timePasses = parsed.has("--json"); // only the JSON reads the pass times
    rest.sppOffset += resumedSpp;
    rest.samplesPerPixel -= resumedSpp;

    Context context(contextOptionsFrom(parsed));
    settings.traversal = rest.traversal = traversalFor(context);
    ShaderCompiler compiler;
    PreparedScene prepared = prepareScene(std::move(scene));
    const guiding::GuidingDecision guideDecision = resolveGuiding(settings, prepared);
    rest.guiding = settings.guiding;
    rest.guidingAuto = false;
    WavefrontRenderer renderer(context, prepared, rest, compiler);
    if (verbose) {
        printVerbose(prepared, renderer, context, summary);
        std::fprintf(stderr, "wavefront: guiding %s\n", guideDecision.reason.c_str());
    }
    StatsContext statsContext{scenePath,       context.deviceName(), settings.width,
                              settings.height, settings.maxDepth,    settings.seed, {}};
    statsContext.extraFields = sceneStatsFields(prepared);
    statsContext.extraFields.push_back({"loadSeconds", jsonNumber(summary.loadSeconds)});
    statsContext.extraFields.push_back(traversalStatsField(renderer));
    statsContext.extraFields.push_back({"guidingDecision", jsonQuoted(guideDecision.reason)});
    if (!spectral.empty())
        statsContext.extraFields.push_back({"spectral", jsonQuoted(spectral)});
    if (settings.integrator != Integrator::Path) {
        // Light subpaths reuse the camera paths' state; what they add is the light film (and
        // with bdpt the kept light vertices and a wider shadow queue).
        const uint64_t waveBytes = renderer.lightSubpathBytes();
        const uint64_t pathBytes = waveBytes / renderer.pathCapacity();
        statsContext.extraFields.push_back(
            {"integrator", jsonQuoted(integratorName(settings.integrator))});
        statsContext.extraFields.push_back(
            {"lightSubpathMemory", "{\"bytesPerPath\": " + std::to_string(pathBytes) +
                                       ", \"bytesPerWave\": " + std::to_string(waveBytes) + "}"});
        const uint32_t share = renderer.variant().lightShare;
        statsContext.extraFields.push_back({"lightShare", std::to_string(share)});
        if (verbose)
            std::fprintf(stderr, "wavefront: %s: one light subpath per %u pixel%s and sample; "
                                 "light subpaths reuse the path state and add %llu bytes per "
                                 "path, %.1f MiB per wave of %u paths\n",
                         integratorName(settings.integrator), share, share == 1 ? "" : "s",
                         (unsigned long long)pathBytes, double(waveBytes) / 1048576.0,
                         renderer.pathCapacity());
    }
    if (adaptive) {
        renderAdaptively(renderer, settings, targetError, run, verbose,
                         {*output, parsed.value("--json"), aovs, quiet}, statsContext);
        return validationExitCode(context);
    }

    // The image so far: the resumed samples and this run's, by sample count.
    auto imageSoFar = [&]() {
        RenderPart part = run;
        part.path = "this render";
        part.sppOffset = rest.sppOffset;
        part.spp = renderer.samplesDone();
        part.rgb = renderer.readImage();
        part.renderSeconds = renderer.stats().seconds;
        if (part.spp > 0)
            part.errorEstimate = estimateFilmError(renderer.readMoments(), settings.sampler);
        if (!resumed)
            return part;
        if (part.spp == 0)
            return *resumed;
        return mergeRenderParts({*resumed, part}).image;
    };
    const auto checkpointPath = parsed.value("--checkpoint");
    const double checkpointEvery = parsed.floatValue("--checkpoint-every", 60.0f, 0.01f, 1e9f);
    std::optional<SignalStop> signals;
    if (checkpointPath)
        signals.emplace();
    auto writeCheckpoint = [&]() {
        RenderPart part = imageSoFar();
        writeRenderPart(*checkpointPath, part,
                        {{"checkpointOfSpp", std::to_string(settings.samplesPerPixel)}}, false);
    };

    ProgressLine progress(!quiet, settings.timeLimitSeconds);
    progress.showEstimate(
        [&]() { return estimateFilmError(renderer.readMoments(), settings.sampler); });
    WaveProgress last{};
    double lastCheckpoint = 0.0;
    renderer.render(
        [&](const WaveProgress& wave) {
            WaveProgress shown = wave;
            shown.samplesDone += resumedSpp;
            shown.samplesTotal += resumedSpp;
            progress.update(shown);
            last = shown;
            if (checkpointPath && wave.secondsElapsed - lastCheckpoint >= checkpointEvery) {
                writeCheckpoint();
                lastCheckpoint = wave.secondsElapsed;
            }
        },
        signals ? &signals->requested() : nullptr);
    if (signals && signals->signal() != 0) {
        writeCheckpoint();
        std::fprintf(stderr, "\nwavefront: stopped by signal %d after %u spp; wrote %s (resume "
                             "with --resume %s)\n",
                     signals->signal(), resumedSpp + renderer.samplesDone(),
                     checkpointPath->c_str(), checkpointPath->c_str());
        return 128 + signals->signal();
    }
    if (last.samplesDone < settings.samplesPerPixel)
        progress.update(last, true);
    const RenderStats& stats = renderer.stats();
    RenderPart finished = imageSoFar();
    finished.sppOffset = settings.sppOffset;
    const std::vector<float> counts(size_t(settings.width) * settings.height,
                                    float(finished.spp));
    std::vector<std::pair<std::string, std::string>> guideAttributes;
    if (settings.guiding) {
        guideAttributes = {{"guiding", "on"},
                           {"guidingIterations", std::to_string(stats.guideIterations.size())},
                           {"guidingImageSpp", std::to_string(stats.guideFinalSamples)}};
        reportGuiding(verbose, stats, statsContext);
    }
    if (!spectral.empty())
        guideAttributes.push_back({"spectral", spectral});
    if (settings.integrator != Integrator::Path) {
        // One light subpath per --light-share pixels and sample: both counts, so that a reader
        // can normalise.
        const uint32_t pixels = settings.width * settings.height;
        const uint64_t samples = uint64_t(pixels) * finished.spp;
        const uint64_t lightPaths =
            uint64_t(lightSubpathsPerSample(renderer.variant().lightShare, pixels)) *
            finished.spp;
        guideAttributes.insert(guideAttributes.end(),
                               {{"integrator", integratorName(settings.integrator)},
                                {"cameraSamples", std::to_string(samples)},
                                {"lightPaths", std::to_string(lightPaths)}});
        statsContext.extraFields.push_back({"cameraSamples", std::to_string(samples)});
        statsContext.extraFields.push_back({"lightPaths", std::to_string(lightPaths)});
    }
    if (settings.integrator == Integrator::Vcm) {
        // Merging is consistent, not unbiased: say so beside the image and its error figure.
        const std::string radius = std::to_string(settings.vcmRadius);
        const std::string mergeRadius =
            std::to_string(settings.vcmRadius * prepared.bounds.radius);
        guideAttributes.insert(guideAttributes.end(),
                               {{"estimator", kVcmEstimatorNote},
                                {"vcmRadius", radius},
                                {"mergeRadius", mergeRadius},
                                {"errorEstimateMeasures", kVcmErrorNote}});
        statsContext.extraFields.push_back({"estimator", jsonQuoted(kVcmEstimatorNote)});
        statsContext.extraFields.push_back({"unbiased", "false"});
        statsContext.extraFields.push_back({"vcmRadius", radius});
        statsContext.extraFields.push_back({"mergeRadius", mergeRadius});
        statsContext.extraFields.push_back({"errorEstimateMeasures", jsonQuoted(kVcmErrorNote)});
    }
    writeRenderPart(*output, finished, guideAttributes, true,
                    aovs.empty() ? std::vector<ExrChannel>{}
                                 : aovChannels(aovs, settings.aov ? renderer.readAovs()
                                                                  : AovImages{},
                                               counts));
    if (checkpointPath)
        writeCheckpoint();
    reportPeakHostMemory(verbose, statsContext);
    const ErrorEstimate estimate = finished.errorEstimate.value_or(ErrorEstimate{
        .reliable = false, .reason = "the checkpoint resumed carries no error estimate"});
    if (auto json = parsed.value("--json")) {
        statsContext.extraFields.push_back({"errorEstimate", errorEstimateJson(estimate)});
        writeStatsJson(*json, stats, statsContext);
    }
    if (!quiet)
        std::fprintf(stderr, "wavefront: wrote %s and %s (%u spp, %.0f paths/s, estimated "
                             "relMSE %s%s)\n",
                     output->c_str(), previewPathFor(*output).c_str(), finished.spp,
                     stats.paths / std::max(stats.seconds, 1e-9),
                     describeErrorEstimate(estimate).c_str(),
                     estimate.reliable ? "" : (": " + estimate.reason).c_str());
    if (!quiet && settings.integrator == Integrator::Vcm)
        std::fprintf(stderr, "wavefront: vcm is consistent, not unbiased: that estimate "
                             "measures variance, not merging's bias\n");
    return validationExitCode(context);
}

} // namespace wf
