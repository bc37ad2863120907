#include "render/convergence.h"

#include <algorithm>
#include <set>
#include <sstream>

#include "errors.h"
#include "render/adaptive_sampling.h"
#include "render/film_error.h"

namespace wf {

void ConvergenceMethod::applyTo(RenderSettings& settings) const {
    settings.sampler = sampler;
    settings.lightSampling = lightSampling;
    settings.integrator = integrator;
    settings.randomizeSamples = randomize;
    settings.triangleSolidAngle = triangleSolidAngle;
    settings.sphereSolidAngle = sphereSolidAngle;
    settings.lightSelection = lightSelection;
    settings.pixelList = adaptive;
    settings.guiding = guided;
    settings.errorReplicates = replicates || adaptive ? kTargetErrorReplicates : 1;
}

std::string methodWords() {
    std::string words;
    for (const std::string& name : samplerNames())
        words += name + ", ";
    return words + "bsdf, nee, mis, light, bdpt, vcm, uniform, power, tree, no-randomize, "
                   "triangle-area, "
                   "sphere-area, adaptive, guided, replicates";
}

ConvergenceMethod parseMethod(const std::string& text) {
    ConvergenceMethod method;
    std::set<std::string> seen;
    bool samplerSet = false, estimatorSet = false, selectionSet = false;
    std::stringstream words(text);
    for (std::string word; std::getline(words, word, '+');) {
        const bool isSampler = [&] {
            for (const std::string& name : samplerNames())
                if (word == name)
                    return true;
            return false;
        }();
        // The integrator replaces the path tracer's estimator: one word of the two.
        const bool isEstimator =
            word == "bsdf" || word == "nee" || word == "mis" || word == "light" ||
            word == "bdpt" || word == "vcm";
        const bool isSelection = word == "uniform" || word == "power" || word == "tree";
        if (!seen.insert(word).second || (isSampler && samplerSet) ||
            (isEstimator && estimatorSet) || (isSelection && selectionSet))
            throw UsageError("--methods: '" + text + "' names a sampler, an estimator, a "
                             "light selection or a switch twice");
        if (isSampler) {
            method.sampler = parseSampler(word, "--methods");
            samplerSet = true;
        } else if (word == "light" || word == "bdpt" || word == "vcm") {
            method.integrator = parseIntegrator(word);
            estimatorSet = true;
        } else if (isEstimator) {
            method.lightSampling = parseLightSampling(word);
            estimatorSet = true;
        } else if (isSelection) {
            method.lightSelection = parseLightSelection(word);
            selectionSet = true;
        } else if (word == "no-randomize") {
            method.randomize = false;
        } else if (word == "triangle-area") {
            method.triangleSolidAngle = false;
        } else if (word == "sphere-area") {
            method.sphereSolidAngle = false;
        } else if (word == "adaptive") {
            method.adaptive = true;
        } else if (word == "guided") {
            method.guided = true;
        } else if (word == "replicates") {
            method.replicates = true;
        } else {
            throw UsageError("--methods: unknown word '" + word + "' in '" + text +
                             "' (words: " + methodWords() + ")");
        }
    }
    if (!method.randomize && method.sampler == SamplerKind::Independent)
        throw UsageError("--methods: independent has no randomization to remove ('" + text +
                         "')");
    if (method.adaptive && samplerIsFiniteSet(method.sampler))
        throw UsageError("--methods: adaptive gives pixels parts of a finite set ('" + text +
                         "'); pick sobol, halton, independent or bluenoise");
    if (method.integrator != Integrator::Path && (method.adaptive || method.guided))
        throw UsageError("--methods: light tracing takes neither adaptive nor guided ('" + text +
                         "')");
    method.name = std::string(samplerName(method.sampler)) + "+" +
                  (method.integrator != Integrator::Path
                       ? integratorName(method.integrator)
                       : lightSamplingName(method.lightSampling)) +
                  (method.randomize ? "" : "+no-randomize") +
                  (method.triangleSolidAngle ? "" : "+triangle-area") +
                  (method.sphereSolidAngle ? "" : "+sphere-area") +
                  (method.lightSelection == LightSelection::Auto
                       ? ""
                       : std::string("+") + lightSelectionName(method.lightSelection)) +
                  (method.adaptive ? "+adaptive" : "") + (method.guided ? "+guided" : "") +
                  (method.replicates ? "+replicates" : "");
    return method;
}

std::vector<ConvergenceMethod> parseMethods(const std::string& list) {
    std::vector<ConvergenceMethod> methods;
    std::set<std::string> names;
    std::stringstream items(list);
    for (std::string item; std::getline(items, item, ',');) {
        if (item.empty())
            continue;
        methods.push_back(parseMethod(item));
        if (!names.insert(methods.back().name).second)
            throw UsageError("--methods lists " + methods.back().name + " twice");
    }
    if (methods.empty())
        throw UsageError("--methods needs at least one method (words: " + methodWords() + ")");
    return methods;
}

std::vector<ConvergenceMethod> defaultMethods() {
    std::string list;
    for (SamplerKind kind : allSamplers())
        list += std::string(samplerName(kind)) + ",";
    const std::string fallback = samplerName(kDefaultSampler);
    return parseMethods(list + fallback + "+bsdf," + fallback + "+nee");
}

namespace {

Checkpoint measure(uint32_t spp, const RenderStats& stats, std::vector<float> image,
                   ErrorEstimate estimate, const std::vector<float>& reference,
                   std::vector<float>* keep) {
    Checkpoint checkpoint;
    checkpoint.estimate = std::move(estimate);
    checkpoint.spp = spp;
    for (const auto& [pass, ms] : stats.passMilliseconds)
        checkpoint.gpuSeconds += ms / 1000.0;
    checkpoint.wallSeconds = stats.seconds;
    checkpoint.error = imageError(image, reference);
    if (keep)
        *keep = std::move(image);
    return checkpoint;
}

} // namespace

MethodRun runConvergence(const Context& context, const PreparedScene& scene,
                         const ShaderCompiler& compiler, const RenderSettings& base,
                         const ConvergenceMethod& method, const ConvergenceOptions& options,
                         const std::vector<float>& reference,
                         const std::function<void(uint32_t, const Checkpoint&)>& onCheckpoint) {
    if (options.seeds.empty())
        throw InternalError("convergence: no seeds");
    RenderSettings settings = base;
    settings.timePasses = false; // gpu_seconds needs the waves' GPU time only
    method.applyTo(settings);
    settings.samplesPerPixel = options.fixedCheckpoints.empty() ? options.maxSpp
                                                                : options.fixedCheckpoints.back();
    WavefrontRenderer renderer(context, scene, settings, compiler);
    // Warm-up: a device's first dispatches of fresh pipelines carry one-time costs (lavapipe
    // finishes compiling them), which would land on the first checkpoint's time.
    if (method.adaptive)
        renderer.renderPixelList({0}, 0, 1);
    else if (method.guided)
        renderer.renderGuided(std::min(4u, settings.samplesPerPixel)); // trains too
    else
        renderer.renderSamples(1);
    const bool finiteSet = samplerIsFiniteSet(method.sampler);

    MethodRun run;
    run.method = method;
    run.defines = renderer.shaderDefines();
    run.checkpoints = options.fixedCheckpoints;
    for (size_t s = 0; s < options.seeds.size(); ++s) {
        const uint32_t seed = options.seeds[s];
        const bool decide = s == 0 && options.fixedCheckpoints.empty();
        std::vector<Checkpoint> points;
        renderer.restart(seed, 0, 0);
        for (size_t c = 0;; ++c) {
            // The first seed sets the checkpoints: doubling until the time budget is spent.
            const uint32_t spp = decide ? (c == 0 ? 1u : run.checkpoints.back() * 2)
                                        : run.checkpoints[c];
            std::vector<float>* keep = nullptr;
            if (s == 0 && options.keepFirstSeedImages)
                keep = &run.firstSeedImages.emplace_back();
            if (method.adaptive) {
                AdaptiveSettings adaptive;
                adaptive.meanSpp = spp;
                adaptive.maxSpp = std::min(settings.samplesPerPixel, 16 * spp);
                AdaptiveResult result = renderAdaptive(renderer, seed, adaptive, settings.width,
                                                       settings.height);
                points.push_back(
                    measure(spp, result.stats, std::move(result.rgb),
                            std::move(result.estimate), reference, keep));
            } else if (method.guided) {
                // Not progressive: the schedule depends on the budget, so each checkpoint
                // trains its own guide from scratch, and its time includes the training.
                renderer.restart(seed, 0, finiteSet ? spp : 0);
                renderer.renderGuided(spp);
                points.push_back(measure(
                    spp, renderer.stats(), renderer.readImage(),
                    estimateFilmError(renderer.readMoments(), settings.sampler), reference, keep));
            } else {
                if (finiteSet)
                    renderer.restart(seed, 0, spp);
                renderer.renderSamples(spp - renderer.samplesDone());
                points.push_back(measure(
                    renderer.samplesDone(), renderer.stats(), renderer.readImage(),
                    estimateFilmError(renderer.readMoments(), settings.sampler), reference, keep));
            }
            if (onCheckpoint)
                onCheckpoint(seed, points.back());
            if (decide) {
                run.checkpoints.push_back(spp);
                if (points.back().wallSeconds >= options.timeBudget || spp * 2 > options.maxSpp)
                    break;
            } else if (c + 1 == run.checkpoints.size()) {
                break;
            }
        }
        run.perSeed.push_back(std::move(points));
    }
    return run;
}

} // namespace wf
