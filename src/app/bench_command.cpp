// wavefront bench: warm-up frames, then timed frames of the wavefront (and, on request, of the
// megakernel built from the same GLSL, frames interleaved so both see the same machine load);
// per-pass GPU times, throughput, queue occupancy, memory, as a table and as JSON.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>

#include "app/reports/bench_report.h"
#include "app/reports/host_memory.h"
#include "app/cli.h"
#include "app/commands.h"
#include "app/render_options.h"
#include "app/reports/stats_json.h"
#include "errors.h"
#include "gpu/context.h"
#include "image/atomic_file.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/guiding/guiding_schedule.h"
#include "render/guiding/path_guide.h"
#include "render/wavefront_renderer.h"

namespace wf {
namespace {

constexpr uint32_t kDefaultWidth = 256;
constexpr uint32_t kDefaultMaxDepth = 8;

const CommandSpec& benchSpec() {
    static const CommandSpec spec{
        "bench",
        "wavefront bench SCENE.gltf [options]",
        "Times frames of SCENE: per-pass GPU time (min/median/max over frames), frame time,\n"
        "rays/s per kind, paths/s, queue occupancy per bounce, device memory per buffer. With\n"
        "--megakernel or --compare-megakernel the same samples are also traced by the\n"
        "megakernel baseline in the same run and the ratio is reported.",
        joinOptions({
            imageSizeOptions(kDefaultWidth),
            {
                {"--frames", "", "N", "timed frames (default 10)"},
                {"--warmup", "", "N", "untimed frames first (default 2)"},
                {"--spp", "", "N", "samples per pixel in one frame (default 1)"},
            },
            depthOptions(kDefaultMaxDepth),
            lensOptions(),
            samplingOptions(),
            {
                noRandomizeOption(),
                {"--megakernel", "", "", "time the megakernel baseline too; print its table and "
                                         "the ratio"},
                {"--compare-megakernel", "", "", "time both; print both tables and the ratio"},
                {"--budget-ms", "", "MS", "longest time one submit should take (default 250; 0: "
                                          "waves of --wave-paths regardless of time)"},
                {"--wave-paths", "", "N", "most paths in one wave (default 1048576)"},
                {"--json", "", "OUT.json", "write the same report as JSON"},
                deviceOption(),
                traversalOption(),
                quietOption(),
                cameraOption(),
                envOption(),
                instancingOption(),
                variantOption(),
            },
            animationOptions(),
        }),
        "Exit codes: 0 done, 2 bad usage or bad input, 1 internal or device failure.\n"};
    return spec;
}

struct Timed {
    std::unique_ptr<WavefrontRenderer> renderer;
    BenchRun run;
};

void renderFrame(Timed& timed, uint32_t spp, bool record) {
    WavefrontRenderer& renderer = *timed.renderer;
    const RenderStats before = renderer.stats();
    const auto start = std::chrono::steady_clock::now();
    renderer.renderSamples(spp);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!record)
        return;
    RenderStats frame = statsBetween(before, renderer.stats());
    timed.run.frames.push_back({seconds, frame.passMilliseconds});
    addRenderStats(timed.run.timed, frame);
}

// --guiding on: the guide trains before the timed frames, as a render of kBenchGuideBudget spp
// would (GuideSchedule: 1 + 2 + ... + 16 spp, 31 in all), on the wavefront; then it freezes
// and the megakernel gets the same tree, so the frames time the guided image phase of both
// kernels on one guide: like with like.
constexpr uint32_t kBenchGuideBudget = 64;

struct GuideTraining {
    uint32_t spp = 0;
    double seconds = 0.0;
};

GuideTraining trainBenchGuide(std::vector<Timed>& kernels) {
    WavefrontRenderer& renderer = *kernels[0].renderer;
    PathGuide& guide = *renderer.guide();
    guiding::GuideSchedule schedule(kBenchGuideBudget, 0.0, 0xffffffffu);
    const auto start = std::chrono::steady_clock::now();
    GuideTraining training;
    guide.setTraining(true);
    for (uint32_t iteration = 0, spp = 0;
         (spp = schedule.nextTrainingSpp(training.spp, 0.0)) > 0; ++iteration) {
        renderer.renderSamples(spp);
        guide.endIteration(iteration);
        training.spp += spp;
    }
    guide.setTraining(false);
    for (size_t k = 1; k < kernels.size(); ++k)
        kernels[k].renderer->guide()->setTree(guide.tree());
    training.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return training;
}

} // namespace

std::string benchHelp() { return helpText(benchSpec()); }

int runBenchCommand(const std::vector<std::string>& args) {
    std::optional<ParsedArgs> maybeParsed = parseSceneCommand(benchSpec(), args);
    if (!maybeParsed)
        return 0; // --help
    const ParsedArgs& parsed = *maybeParsed;
    const uint32_t frames = parsed.uintValue("--frames", 10, 1, 100000);
    const uint32_t warmup = parsed.uintValue("--warmup", 2, 0, 100000);
    const uint32_t spp = parsed.uintValue("--spp", 1, 1, 1u << 16);
    RenderSettings settings;
    applyRenderFlags(parsed, kDefaultMaxDepth, settings);
    settings.submitBudgetSeconds = parsed.uintValue("--budget-ms", 250, 0, 600000) * 1e-3;
    settings.maxPathsPerWave = parsed.uintValue("--wave-paths", 1u << 20, 1024, 1u << 26);
    if (uint64_t(frames + warmup) * spp > (1u << 24))
        throw UsageError("(--frames + --warmup) x --spp must stay under 16777216 samples");
    settings.samplesPerPixel = (frames + warmup) * spp;
    const bool compare = parsed.has("--compare-megakernel");
    const bool withMegakernel = compare || parsed.has("--megakernel");
    const bool quiet = parsed.has("--quiet");

    const std::string scenePath = parsed.positional.front();
    SceneSummary summary;
    Scene scene = loadSceneWithFlags(parsed, scenePath, &summary);
    // Unlike render, --height alone keeps the default width.
    applyImageSize(parsed, scene.camera, {.width = kDefaultWidth, .widthFollowsHeight = false},
                   settings);

    Context context(contextOptionsFrom(parsed));
    settings.traversal = traversalFor(context);
    ShaderCompiler compiler;
    const PreparedScene prepared = prepareScene(std::move(scene));
    const guiding::GuidingDecision guideDecision = resolveGuiding(settings, prepared);

    std::vector<Timed> kernels(withMegakernel ? 2 : 1);
    kernels[0].renderer =
        std::make_unique<WavefrontRenderer>(context, prepared, settings, compiler);
    kernels[0].run.kernel = "wavefront";
    if (withMegakernel) {
        RenderSettings mega = settings;
        mega.megakernel = true;
        // The megakernel walks the BVH whatever --traversal says: it shares the wavefront's
        // scene tables only where those were made for the BVH variant too.
        kernels[1].renderer = std::make_unique<WavefrontRenderer>(
            context, prepared, mega, compiler,
            settings.traversal == Traversal::Bvh ? kernels[0].renderer->sceneBuffers()
                                                 : nullptr);
        kernels[1].run.kernel = "megakernel";
    }
    for (Timed& k : kernels)
        k.run.memory = k.renderer->memoryReport();
    GuideTraining training;
    if (settings.guiding)
        training = trainBenchGuide(kernels);

    BenchSetup setup{scenePath, context.deviceName(), context.driverInfo(),
                     kernels[0].renderer->variant().describe(), settings.width, settings.height,
                     spp, settings.maxDepth, settings.seed, warmup, frames,
                     settings.submitBudgetSeconds, prepared.triangles.size(),
                     prepared.materials.size(), prepared.bvhStats};
    setup.instances = prepared.instances.size();
    setup.guiding = settings.guiding;
    setup.guidingText = guideDecision.reason;
    setup.guideTrainingSpp = training.spp;
    setup.guideTrainingSeconds = training.seconds;
    setup.instancedTriangles = prepared.instancedTriangles;
    const ShaderVariant& variant = kernels[0].renderer->variant();
    setup.lightSelection = variant.nextEventEstimation
                               ? lightSelectionName(variant.lightSelection) : "none";
    setup.lightSelectionText = describeLightSelection(prepared, variant);
    if (variant.lightTree()) {
        setup.lightTreeLights = prepared.lightTree.lights;
        setup.lightTreeDepth = prepared.lightTree.depth;
        setup.lightTreeBuildSeconds = prepared.lightTree.buildSeconds;
    }
    const WavefrontRenderer& wavefront = *kernels[0].renderer;
    setup.traversalText = describeTraversal(wavefront);
    if (const AccelerationStructureSet* structures = wavefront.sceneBuffers()->acceleration();
        structures && wavefront.traversal() == Traversal::RayTracing) {
        setup.traversal = "rt";
        setup.accelerationBytes = structures->bytes();
        setup.accelerationBuildSeconds = structures->buildSeconds();
    }
    // Frames alternate between the kernels so a change in machine load hits both alike.
    for (uint32_t f = 0; f < warmup + frames; ++f) {
        for (Timed& k : kernels) {
            if (f == warmup)
                k.renderer->resetLongestSubmit();
            renderFrame(k, spp, f >= warmup);
        }
        if (!quiet)
            std::fprintf(stderr, "wavefront: bench frame %u/%u%s\n", f + 1, warmup + frames,
                         f < warmup ? " (warm-up)" : "");
    }

    setup.peakHostMemoryBytes = peakHostMemoryBytes();
    setup.loadSeconds = summary.loadSeconds;
    std::printf("Wavefront bench: %s, %ux%u, %u spp per frame, max depth %u, seed %u; %u frames "
                "after %u warm-up\n",
                scenePath.c_str(), settings.width, settings.height, spp, settings.maxDepth,
                settings.seed, frames, warmup);
    std::printf("device: %s (%s)\nshader variant: %s\n", setup.device.c_str(),
                setup.driver.c_str(), setup.variant.c_str());
    std::printf("scene: %llu triangles, %llu materials; BVH %u nodes, %u leaves, depth %u, "
                "stack need %u, traversal cost %g, SAH cost %.2f, built in %.1f ms\n",
                static_cast<unsigned long long>(setup.triangles),
                static_cast<unsigned long long>(setup.materials), setup.bvh.nodeCount,
                setup.bvh.leafCount, setup.bvh.maxDepth, setup.bvh.stackNeed,
                setup.bvh.traversalCost, setup.bvh.sahCost,
                setup.bvh.buildSeconds * 1e3);
    if (setup.instances > 0)
        std::printf("instances: %llu (%llu triangles as placed)\n",
                    static_cast<unsigned long long>(setup.instances),
                    static_cast<unsigned long long>(setup.instancedTriangles));
    std::printf("light selection: %s\n", setup.lightSelectionText.c_str());
    std::printf("traversal: %s%s\n", setup.traversalText.c_str(),
                withMegakernel ? "; the megakernel walks the BVH" : "");
    if (setup.guiding)
        std::printf("guiding: %s; the guide trained over %u spp first (%.3f s, untimed), then "
                    "froze%s\n\n",
                    setup.guidingText.c_str(), setup.guideTrainingSpp,
                    setup.guideTrainingSeconds,
                    withMegakernel ? "; both kernels sample the same guide" : "");
    else
        std::printf("guiding: %s\n\n", setup.guidingText.c_str());
    // --megakernel shows the megakernel's table, --compare-megakernel both.
    if (!withMegakernel || compare)
        std::fputs(benchTable(setup, kernels[0].run).c_str(), stdout);
    if (withMegakernel) {
        if (compare)
            std::fputs("\n", stdout);
        std::fputs(benchTable(setup, kernels[1].run).c_str(), stdout);
        std::fputs("\n", stdout);
        std::fputs(benchRatioLine(kernels[0].run, kernels[1].run).c_str(), stdout);
    }
    std::fflush(stdout);

    if (auto json = parsed.value("--json")) {
        std::vector<BenchRun> runs;
        for (const Timed& k : kernels)
            runs.push_back(k.run);
        const std::string text = benchJson(setup, runs);
        writeFileAtomically(*json, [&](const std::string& tmp) {
            std::ofstream out(tmp, std::ios::binary);
            out << text;
            if (!out)
                throw InputError("cannot write " + *json);
        });
    }
    if (context.validationMessageCount() > 0) {
        std::fprintf(stderr, "wavefront: %u validation message(s)\n",
                     context.validationMessageCount());
        return 1;
    }
    return 0;
}

} // namespace wf
