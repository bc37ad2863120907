#include "renderer.h"

#include <atomic>
#include <chrono>
#include <cmath>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "app/cli.h"
#include "app/reports/host_memory.h"
#include "app/render_flags.h"
#include "app/render_options.h"
#include "app/reports/stats_json.h"
#include "errors.h"
#include "module_support.h"
#include "render/adaptive_sampling.h"
#include "render/convergence.h"
#include "render/film_error.h"

namespace wf::py {
namespace {

// Thrown out of a core loop's callback when Python has an exception waiting (Ctrl-C, or the
// progress callable raised); the loop unwinds and the exception is raised once the GIL is back.
struct Interrupted {};

// Python's exception from a callback, or KeyboardInterrupt from PyErr_CheckSignals, kept
// until the render has stopped. Call with the GIL held.
bool checkPython(const pyb::object& progress, std::optional<pyb::error_already_set>& pending,
                 const pyb::tuple& args) {
    if (PyErr_CheckSignals() != 0) {
        pending.emplace();
        return false;
    }
    if (progress.is_none())
        return true;
    try {
        progress(*args);
    } catch (pyb::error_already_set& error) {
        pending.emplace(std::move(error));
        return false;
    }
    return true;
}

pyb::array_t<float> toArray(std::vector<float> data, std::vector<pyb::ssize_t> shape) {
    auto* owned = new std::vector<float>(std::move(data));
    pyb::capsule owner(owned, [](void* p) { delete static_cast<std::vector<float>*>(p); });
    return pyb::array_t<float>(shape, owned->data(), owner);
}

std::atomic<uint64_t> nextSceneId{1};

} // namespace

struct Renderer::Settings {
    RenderSettings render;
    double targetError = 0.0;
    std::vector<std::string> aovs;
    std::string key; // the flags but --seed and the sample range: what the pipelines depend on
    std::string guidingDecision; // --guiding: asked, or auto's decision and why
};

Renderer::Renderer(std::optional<int> device, bool validation, bool quiet,
                   const std::string& traversal) {
    ContextOptions options;
    options.deviceIndex = device;
    options.validation = validation;
    options.quiet = quiet;
    if (traversal != "auto" && traversal != "bvh" && traversal != "rt")
        throw UsageError("--traversal expects auto, bvh or rt, got '" + traversal + "'");
    options.rayTracing = traversal == "rt"    ? RayTracingRequest::Required
                         : traversal == "bvh" ? RayTracingRequest::Off
                                              : RayTracingRequest::Auto;
    try {
        context_ = std::make_unique<Context>(options);
        compiler_ = std::make_unique<ShaderCompiler>(moduleShaderDir(), defaultShaderCacheDir());
    } catch (const std::exception& error) {
        compiler_.reset();
        context_.reset();
        throw DeviceError(error.what());
    }
}

Renderer::~Renderer() {
    // No GIL release here: a finaliser may run while the interpreter shuts down.
    std::lock_guard lock(mutex_);
    cached_.reset();
    cachedScene_.reset();
    compiler_.reset();
    context_.reset();
}

void Renderer::close() {
    pyb::gil_scoped_release release;
    std::lock_guard lock(mutex_);
    cached_.reset(); // pipelines and buffers, before the device they live on
    cachedScene_.reset();
    compiler_.reset();
    context_.reset();
}

void Renderer::requireOpen() const {
    if (!context_)
        throw ClosedError("this Renderer is closed (make a new one)");
}

std::string Renderer::deviceName() const {
    requireOpen();
    return context_->deviceName();
}

uint32_t Renderer::validationMessages() const {
    requireOpen();
    return context_->validationMessageCount();
}

std::shared_ptr<LoadedScene> Renderer::load(const std::string& path,
                                            const std::vector<std::string>& flags) {
    const ParsedArgs parsed = parseArgs(renderSpec(), flags);
    requireOpen();
    auto loaded = std::make_shared<LoadedScene>();
    pyb::gil_scoped_release release; // loading needs no device: other calls go on meanwhile
    loaded->path = path;
    Scene scene = loadSceneWithFlags(parsed, path, &loaded->summary);
    loaded->prepared = std::make_shared<const PreparedScene>(prepareScene(std::move(scene)));
    loaded->id = nextSceneId++;
    return loaded;
}

Renderer::Settings Renderer::readFlags(const LoadedScene& scene,
                                       const std::vector<std::string>& flags) const {
    const ParsedArgs parsed = parseArgs(renderSpec(), flags);
    RenderRequest request = renderRequestFrom(parsed);
    applyImageSize(parsed, scene.prepared->camera,
                   {.width = kRenderDefaultWidth, .widthFollowsHeight = true}, request.settings);
    // A closed renderer refuses the call afterwards (requireOpen); its flags still parse.
    request.settings.traversal = context_ ? traversalFor(*context_) : Traversal::Bvh;
    const std::string decision = resolveGuiding(request.settings, *scene.prepared).reason;
    Settings settings{request.settings, request.targetError, request.aovs,
                      std::to_string(scene.id), decision};
    for (size_t i = 0; i < flags.size(); ++i) {
        if (flags[i] == "--seed" || flags[i] == "--spp-offset" || flags[i] == "--spp-total")
            ++i; // restart() sets these on a kept renderer
        else
            settings.key += '\x1f' + flags[i];
    }
    return settings;
}

WavefrontRenderer& Renderer::rendererFor(const LoadedScene& scene, const Settings& settings) {
    const RenderSettings& s = settings.render;
    if (cached_ && cachedScene_ == scene.prepared && cachedKey_ == settings.key) {
        cached_->restart(s.seed, s.sppOffset, s.sampleSetSize);
        return *cached_;
    }
    // Another scene with the same flags (a sequence: a load per frame) takes the kept
    // renderer's pipelines where its shaders and image size agree, as render --frames does.
    const auto flagsOf = [](const std::string& key) { // the key less its scene id
        const size_t first = key.find('\x1f');
        return first == std::string::npos ? std::string() : key.substr(first);
    };
    if (cached_ && cachedScene_ != scene.prepared && s.width == cachedWidth_ &&
        s.height == cachedHeight_ && flagsOf(cachedKey_) == flagsOf(settings.key) &&
        cached_->setScene(*scene.prepared)) {
        cachedScene_ = scene.prepared;
        cachedKey_ = settings.key;
        cached_->restart(s.seed, s.sppOffset, s.sampleSetSize);
        return *cached_;
    }
    cached_.reset(); // free the old buffers before making new ones
    cachedKey_.clear();
    cachedScene_ = scene.prepared;
    cached_ = std::make_unique<WavefrontRenderer>(*context_, *scene.prepared, s, *compiler_);
    cachedKey_ = settings.key;
    cachedWidth_ = s.width;
    cachedHeight_ = s.height;
    return *cached_;
}

namespace {

// The render's own error estimate, as the CLI's --json has it.
std::pair<std::string, std::string> errorEstimateField(const WavefrontRenderer& renderer,
                                                       const RenderSettings& settings) {
    return {"errorEstimate",
            errorEstimateJson(estimateFilmError(renderer.readMoments(), settings.sampler))};
}

} // namespace

pyb::dict Renderer::output(const LoadedScene& scene, const Settings& settings,
                           std::vector<float> rgb, uint32_t spp, const RenderStats& stats,
                           const std::vector<std::pair<std::string, std::string>>& extraStats,
                           const std::vector<float>* sampleCounts) {
    const RenderSettings& s = settings.render;
    const pyb::ssize_t w = s.width, h = s.height;
    StatsContext context{scene.path, context_->deviceName(), s.width, s.height, s.maxDepth,
                         s.seed, sceneStatsFields(*scene.prepared)};
    context.extraFields.push_back({"loadSeconds", jsonNumber(scene.summary.loadSeconds)});
    context.extraFields.push_back({"guidingDecision", jsonQuoted(settings.guidingDecision)});
    if (s.guiding)
        context.extraFields.push_back(
            {"guiding", "{\"iterations\": " + std::to_string(stats.guideIterations.size()) +
                            ", \"imageSpp\": " + std::to_string(stats.guideFinalSamples) +
                            ", \"stoppedUnused\": " +
                            (stats.guideStoppedUnused ? "true" : "false") + "}"});
    for (const auto& field : extraStats)
        context.extraFields.push_back(field);
    context.extraFields.push_back({"peakHostMemoryBytes", std::to_string(peakHostMemoryBytes())});
    context.extraFields.push_back(cached_ ? traversalStatsField(*cached_)
                                          : std::make_pair(std::string("traversal"),
                                                           std::string("{\"mode\": \"bvh\"}")));
    RenderStats shown = stats;
    shown.samplesPerPixel = spp;
    AovImages aovs;
    if (s.aov)
        aovs = cached_ ? cached_->readAovs() : AovImages{};
    std::vector<float> counts = sampleCounts ? *sampleCounts
                                             : std::vector<float>(size_t(w) * h, float(spp));
    const std::string statsJson = statsToJson(shown, context);

    pyb::gil_scoped_acquire gil;
    pyb::dict out, aov;
    out["image"] = toArray(std::move(rgb), {h, w, 3});
    for (const std::string& name : settings.aovs) {
        if (name == "albedo")
            aov["albedo"] = toArray(std::move(aovs.albedo), {h, w, 3});
        else if (name == "normal")
            aov["normal"] = toArray(std::move(aovs.normal), {h, w, 3});
        else if (name == "depth")
            aov["depth"] = toArray(std::move(aovs.depth), {h, w});
        else if (name == "variance")
            aov["variance"] = toArray(std::move(aovs.variance), {h, w, 3});
        else
            aov["samples"] = toArray(counts, {h, w});
    }
    out["aov"] = aov;
    out["spp"] = spp;
    out["seconds"] = stats.seconds;
    out["stats"] = statsJson;
    return out;
}

pyb::dict Renderer::render(const LoadedScene& scene, const std::vector<std::string>& flags,
                           const pyb::object& progress) {
    const Settings settings = readFlags(scene, flags);
    std::optional<pyb::error_already_set> pending;
    std::atomic<bool> stop{false};
    pyb::gil_scoped_release release;
    std::lock_guard lock(mutex_);
    requireOpen();
    ++generation_;
    if (settings.targetError > 0.0) {
        // Adaptive renders leave a renderer in pixel-list mode: made for the one render.
        cached_.reset();
        cachedScene_.reset();
        cachedKey_.clear();
        const RenderSettings& s = settings.render;
        WavefrontRenderer renderer(*context_, *scene.prepared, s, *compiler_);
        AdaptiveSettings adaptive;
        adaptive.targetError = settings.targetError;
        adaptive.maxSpp = s.samplesPerPixel;
        adaptive.timeLimitSeconds = s.timeLimitSeconds;
        AdaptiveResult result;
        try {
            result = renderAdaptive(renderer, s.seed, adaptive, s.width, s.height,
                                    [&](const AdaptiveProgress& round) {
                                        pyb::gil_scoped_acquire gil;
                                        if (!checkPython(progress, pending,
                                                         pyb::make_tuple(round.level, s.samplesPerPixel,
                                                                         round.seconds)))
                                            throw Interrupted{};
                                    });
        } catch (const Interrupted&) {
            pyb::gil_scoped_acquire gil;
            throw *pending;
        }
        const uint32_t spp = uint32_t(std::lround(result.meanSpp));
        AovImages aovs = s.aov ? renderer.readAovs() : AovImages{};
        Settings shown = settings;
        shown.render.aov = false; // the layers were read from the one-off renderer above
        pyb::dict out = output(scene, shown, result.rgb, spp, result.stats,
                               {{"errorEstimate", errorEstimateJson(result.estimate)},
                                adaptiveStatsField(result, settings.targetError,
                                                   s.samplesPerPixel)},
                               &result.sampleCounts);
        pyb::gil_scoped_acquire gil;
        pyb::dict aov = out["aov"];
        const pyb::ssize_t w = s.width, h = s.height;
        if (aov.contains("albedo"))
            aov["albedo"] = toArray(std::move(aovs.albedo), {h, w, 3});
        if (aov.contains("normal"))
            aov["normal"] = toArray(std::move(aovs.normal), {h, w, 3});
        if (aov.contains("depth"))
            aov["depth"] = toArray(std::move(aovs.depth), {h, w});
        if (aov.contains("variance"))
            aov["variance"] = toArray(std::move(aovs.variance), {h, w, 3});
        return out;
    }
    WavefrontRenderer& renderer = rendererFor(scene, settings);
    renderer.render(
        [&](const WaveProgress& wave) {
            pyb::gil_scoped_acquire gil;
            if (!checkPython(progress, pending,
                             pyb::make_tuple(wave.samplesDone, wave.samplesTotal,
                                             wave.secondsElapsed)))
                stop = true;
        },
        &stop);
    if (pending) {
        pyb::gil_scoped_acquire gil;
        throw *pending;
    }
    return output(scene, settings, renderer.readImage(), renderer.samplesDone(),
                  renderer.stats(), {errorEstimateField(renderer, settings.render)}, nullptr);
}

uint64_t Renderer::begin(const LoadedScene& scene, const std::vector<std::string>& flags) {
    Settings settings = readFlags(scene, flags);
    if (settings.targetError > 0.0 || settings.render.timeLimitSeconds > 0.0)
        throw UsageError("render_progressive takes neither target_error nor time_limit (the "
                         "caller decides when to stop)");
    if (settings.render.guiding && settings.guidingDecision.rfind("auto", 0) == 0) {
        settings.render.guiding = false; // auto never refuses
        settings.guidingDecision = "auto: off (render_progressive does not guide)";
    }
    if (settings.render.guiding)
        throw UsageError("render_progressive does not guide (its passes would each restart "
                         "the guide's training): use render, or guiding \"off\" or \"auto\"");
    pyb::gil_scoped_release release;
    std::lock_guard lock(mutex_);
    requireOpen();
    rendererFor(scene, settings);
    progressiveScene_ = std::make_shared<LoadedScene>(scene);
    progressiveSettings_ = std::make_unique<Settings>(std::move(settings));
    return ++generation_;
}

pyb::dict Renderer::advance(uint64_t session, uint32_t samples) {
    pyb::gil_scoped_release release;
    std::lock_guard lock(mutex_);
    requireOpen();
    if (session != generation_ || !cached_)
        throw std::runtime_error("this progressive render was ended by another call on the "
                                 "same Renderer (render, converge or a new progressive render)");
    cached_->renderSamples(samples);
    return output(*progressiveScene_, *progressiveSettings_, cached_->readImage(),
                  cached_->samplesDone(), cached_->stats(),
                  {errorEstimateField(*cached_, progressiveSettings_->render)}, nullptr);
}

pyb::list Renderer::converge(const LoadedScene& scene, const std::vector<std::string>& flags,
                             const std::vector<std::string>& methodNames,
                             const std::vector<uint32_t>& seeds, double timeBudget,
                             uint32_t maxSpp, const std::vector<uint32_t>& checkpoints,
                             const std::vector<float>& reference, const pyb::object& progress) {
    // The base settings as `wavefront converge` makes them: size, depth, the rest render's
    // defaults.
    const ParsedArgs parsed = parseArgs(renderSpec(), flags);
    RenderSettings base;
    applyImageSize(parsed, scene.prepared->camera, {.width = 128, .widthFollowsHeight = false},
                   base);
    applyRenderFlags(parsed, kRenderDefaultMaxDepth, base);
    base.traversal = context_ ? traversalFor(*context_) : Traversal::Bvh;
    if (reference.size() != size_t(base.width) * base.height * 3)
        throw UsageError("the reference has " + std::to_string(reference.size() / 3) +
                         " pixels, converge renders " + std::to_string(base.width) + "x" +
                         std::to_string(base.height) + " (match it with width/height)");
    std::string list;
    for (const std::string& name : methodNames)
        list += (list.empty() ? "" : ",") + name;
    const std::vector<ConvergenceMethod> methods = parseMethods(list);
    if (seeds.empty())
        throw UsageError("converge needs at least one seed");
    ConvergenceOptions options;
    options.seeds = seeds;
    options.timeBudget = timeBudget;
    options.maxSpp = maxSpp;
    options.fixedCheckpoints = checkpoints;
    options.keepFirstSeedImages = false;

    std::optional<pyb::error_already_set> pending;
    std::vector<MethodRun> runs;
    {
        pyb::gil_scoped_release release;
        std::lock_guard lock(mutex_);
        requireOpen();
        ++generation_;
        cached_.reset(); // each method makes its own renderers
        cachedScene_.reset();
        cachedKey_.clear();
        try {
            for (const ConvergenceMethod& method : methods)
                runs.push_back(runConvergence(
                    *context_, *scene.prepared, *compiler_, base, method, options, reference,
                    [&](uint32_t seed, const Checkpoint& c) {
                        pyb::gil_scoped_acquire gil;
                        if (!checkPython(progress, pending,
                                         pyb::make_tuple(method.name, seed, c.spp,
                                                         c.wallSeconds, c.error.relMse)))
                            throw Interrupted{};
                    }));
        } catch (const Interrupted&) {
        }
    }
    if (pending)
        throw *pending;
    pyb::list records;
    for (const MethodRun& run : runs)
        for (size_t s = 0; s < run.perSeed.size(); ++s)
            for (const Checkpoint& c : run.perSeed[s]) {
                pyb::dict r;
                r["method"] = run.method.name;
                r["sampler"] = samplerName(run.method.sampler);
                r["light_sampling"] = lightSamplingName(run.method.lightSampling);
                r["seed"] = seeds[s];
                r["seed_index"] = s;
                r["spp"] = c.spp;
                r["gpu_seconds"] = c.gpuSeconds;
                r["wall_seconds"] = c.wallSeconds;
                r["relmse"] = c.error.relMse;
                r["mse"] = c.error.mse;
                r["bias"] = c.error.bias;
                records.append(r);
            }
    return records;
}

} // namespace wf::py
