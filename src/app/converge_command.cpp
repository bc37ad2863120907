// wavefront converge: error against time and samples for several methods (sampler x estimator
// x switches), several seeds each; CSV, JSON, equal-time crops, a printed ranking, and charts
// drawn by scripts/plot_convergence.py (matplotlib).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>

#include "app/cli.h"
#include "app/commands.h"
#include "app/reports/convergence_report.h"
#include "app/render_options.h"
#include "errors.h"
#include "gpu/context.h"
#include "image/error_metrics.h"
#include "image/exr_io.h"
#include "render/convergence_summary.h"
#include "render/gpu_scene/scene_buffers.h"

extern char** environ;

namespace fs = std::filesystem;

namespace wf {
namespace {

constexpr uint32_t kDefaultMaxDepth = 16;

const CommandSpec& convergeSpec() {
    static const CommandSpec spec{
        "converge",
        "wavefront converge SCENE.gltf -o DIR [--reference REF.exr] [--time T] [--methods LIST]",
        "Renders SCENE with each method and several seeds, progressively, and records at\n"
        "log-spaced sample counts the GPU time, wall time, relMSE, MSE and bias against a\n"
        "reference. Writes DIR/convergence.csv, DIR/convergence.json, DIR/crops/ (equal-time\n"
        "crops), and the charts DIR/error_vs_time.png, DIR/error_vs_spp.png and\n"
        "DIR/equal_time.png (python3 + matplotlib); prints the time each method takes to reach\n"
        "a target relMSE, and its fitted slope.",
        joinOptions({
            {
                {"--output", "-o", "DIR", "output folder (required; created if missing)"},
                {"--reference", "", "REF.exr", "reference image (default: rendered first with the "
                                               "default method, saved as DIR/reference.exr)"},
                {"--reference-spp", "", "N", "samples per pixel of that reference (default 4096), "
                                            "two halves of two seeds whose difference "
                                            "measures the relMSE its own noise adds"},
                {"--time", "", "T", "render seconds per method and seed: samples double until a "
                                    "checkpoint passes T (default 4)"},
                {"--methods", "", "LIST", "comma-separated methods, each words joined by '+': a "
                                          "sampler, bsdf|nee|mis or an integrator, light, "
                                          "bdpt or vcm (--integrator; each sample's light "
                                          "subpaths' time included), uniform|power|tree "
                                          "(light selection), no-randomize, triangle-area, "
                                          "sphere-area, adaptive (each checkpoint rendered "
                                          "afresh with that mean spp, placed by a pilot whose "
                                          "time counts), guided (path guiding; each checkpoint "
                                          "trains afresh, its training time included), "
                                          "replicates (two error replicates: a calibrated "
                                          "estimate for correlated samplers; adaptive takes "
                                          "them anyway) (default: every sampler with mis, then "
                                          "sobol+bsdf, sobol+nee)"},
                {"--seeds", "", "N", "seeds per method, at least 5 (default 5)"},
                {"--max-spp", "", "N", "stop doubling here (default 65536)"},
                {"--target", "", "R", "relMSE of the ranking (default: the median of the methods' "
                                      "final relMSE)"},
                {"--width", "", "W", "image width (default: the reference's, else 128)"},
                {"--height", "", "H", "image height (default: the reference's, else width / the "
                                      "camera's aspect)"},
            },
            depthOptions(kDefaultMaxDepth),
            lensOptions(),
            {
                {"--crop", "", "X,Y,W,H", "region of the equal-time crops (default: the central "
                                          "half of the image)"},
                {"--no-plot", "", "", "write CSV and JSON only, no charts"},
                instancingOption(),
                variantOption(),
            },
            animationOptions(false),
            {
                deviceOption(),
                traversalOption(),
                quietOption(),
            },
        }),
        "Charts: scripts/plot_convergence.py DIR, run by WAVEFRONT_PYTHON, else\n"
        "/usr/bin/python3 (Debian's python3-matplotlib), else python3.\n"
        "\n"
        "Exit codes: 0 done, 2 bad usage or bad input, 1 internal or device failure.\n"};
    return spec;
}

std::string scriptPath() {
    if (const char* dir = std::getenv("WAVEFRONT_SCRIPT_DIR"); dir && *dir)
        return (fs::path(dir) / "plot_convergence.py").string();
    return (fs::path(WF_SOURCE_SCRIPT_DIR) / "plot_convergence.py").string();
}

// Runs the plotting script; false (and a reason on stderr) when it cannot.
bool plotCharts(const std::string& dir) {
    std::string python = "python3";
    if (const char* env = std::getenv("WAVEFRONT_PYTHON"); env && *env)
        python = env;
    else if (fs::exists("/usr/bin/python3"))
        python = "/usr/bin/python3";
    const std::string script = scriptPath();
    std::vector<std::string> args = {python, script, dir};
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0) {
        std::fprintf(stderr, "wavefront: charts skipped: cannot run %s\n", python.c_str());
        return false;
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "wavefront: charts skipped: %s %s %s failed (needs "
                     "python3-matplotlib)\n", python.c_str(), script.c_str(), dir.c_str());
        return false;
    }
    return true;
}

void parseCrop(const ParsedArgs& parsed, ConvergenceInfo& info) {
    const int w = int(info.width), h = int(info.height);
    int crop[4] = {w / 4, h / 4, std::max(1, w / 2), std::max(1, h / 2)};
    if (auto text = parsed.value("--crop")) {
        if (std::sscanf(text->c_str(), "%d,%d,%d,%d", &crop[0], &crop[1], &crop[2], &crop[3]) !=
                4 ||
            crop[0] < 0 || crop[1] < 0 || crop[2] < 1 || crop[3] < 1 || crop[0] + crop[2] > w ||
            crop[1] + crop[3] > h)
            throw UsageError("--crop expects X,Y,W,H inside the " + std::to_string(w) + "x" +
                             std::to_string(h) + " image, got '" + *text + "'");
    }
    std::copy(crop, crop + 4, info.crop);
}

// The reference: the sample-weighted mean of two independent halves of settings' samples
// (seeds settings.seed and settings.seed + 1), whose difference measures the relMSE its own
// noise adds to every figure against it (`noise`; left as it is for a single sample).
std::vector<float> renderReference(const Context& context, const PreparedScene& prepared,
                                   const ShaderCompiler& compiler, const RenderSettings& settings,
                                   double& noise) {
    auto render = [&](uint32_t spp, uint32_t seed) {
        RenderSettings half = settings;
        half.samplesPerPixel = spp;
        half.seed = seed;
        WavefrontRenderer renderer(context, prepared, half, compiler);
        renderer.render();
        return renderer.readImage();
    };
    const uint32_t sppA = settings.samplesPerPixel / 2;
    const uint32_t sppB = settings.samplesPerPixel - sppA;
    if (sppA == 0)
        return render(sppB, settings.seed);
    const std::vector<float> a = render(sppA, settings.seed);
    const std::vector<float> b = render(sppB, settings.seed + 1);
    std::vector<float> reference = mergeBySampleCount({a, b}, {double(sppA), double(sppB)});
    noise = referenceNoiseRelMse(a, sppA, b, sppB, reference);
    return reference;
}

} // namespace

std::string convergeHelp() { return helpText(convergeSpec()); }

int runConvergeCommand(const std::vector<std::string>& args) {
    std::optional<ParsedArgs> maybeParsed = parseSceneCommand(convergeSpec(), args);
    if (!maybeParsed)
        return 0; // --help
    const ParsedArgs& parsed = *maybeParsed;
    const auto dir = parsed.value("--output");
    if (!dir || dir->empty())
        throw UsageError("converge needs -o DIR (see wavefront converge --help)");
    const std::vector<ConvergenceMethod> methods =
        parsed.has("--methods") ? parseMethods(*parsed.value("--methods")) : defaultMethods();
    ConvergenceOptions options;
    const uint32_t seedCount = parsed.uintValue("--seeds", 5, 5, 1000);
    for (uint32_t s = 1; s <= seedCount; ++s)
        options.seeds.push_back(s);
    options.timeBudget = parsed.floatValue("--time", 4.0f, 0.0f, 1e6f);
    options.maxSpp = parsed.uintValue("--max-spp", 1u << 16, 1, 1u << 20);
    const uint32_t referenceSpp = parsed.uintValue("--reference-spp", 4096, 1, 1u << 20);
    const bool quiet = parsed.has("--quiet");

    const std::string scenePath = parsed.positional.front();
    // --time is the render budget here: the scene's time is --frame N / --fps, else 0.
    if (parsed.has("--fps") && !parsed.has("--frame") && !parsed.has("--shutter"))
        throw UsageError("--fps applies to --frame or --shutter");
    const double sceneTime = parsed.has("--frame")
                                 ? double(parsed.uintValue("--frame", 0, 0, 1u << 30)) /
                                       parsed.floatValue("--fps", 24.0f, 1e-3f, 1e6f)
                                 : 0.0;
    Scene scene = loadSceneWithFlags(parsed, scenePath, nullptr, sceneTime);
    std::vector<float> reference;
    ExrImage given;
    if (auto path = parsed.value("--reference"))
        given = readExr(*path);
    RenderSettings base;
    // A given reference sizes the image unless --width or --height says otherwise.
    ImageSizeRule size{.width = given.width ? uint32_t(given.width) : 128u,
                       .widthFollowsHeight = false};
    if (given.height)
        size.height = uint32_t(given.height);
    applyImageSize(parsed, scene.camera, size, base);
    applyRenderFlags(parsed, kDefaultMaxDepth, base); // --max-depth and --rr-depth here
    if (base.guiding)
        throw UsageError("converge: guide a method with the word guided (--methods "
                         "sobol+mis,sobol+mis+guided), not --guiding");
    if (given.width && (uint32_t(given.width) != base.width ||
                        uint32_t(given.height) != base.height))
        throw InputError("reference " + *parsed.value("--reference") + " is " +
                         std::to_string(given.width) + "x" + std::to_string(given.height) +
                         ", converge renders " + std::to_string(base.width) + "x" +
                         std::to_string(base.height) + " (match it with --width/--height)");
    ConvergenceInfo info;
    info.scene = scenePath;
    info.width = base.width;
    info.height = base.height;
    info.maxDepth = base.maxDepth;
    info.seeds = options.seeds;
    info.timeBudget = options.timeBudget;
    parseCrop(parsed, info);
    fs::create_directories(*dir);

    Context context(contextOptionsFrom(parsed));
    base.traversal = traversalFor(context);
    info.device = context.deviceName();
    info.traversal = base.traversal == Traversal::RayTracing ? "rt" : "bvh";
    ShaderCompiler compiler;
    PreparedScene prepared = prepareScene(std::move(scene));

    if (given.width) {
        reference = std::move(given.rgb);
        info.reference = *parsed.value("--reference");
        info.referenceMethod = "given";
    } else {
        RenderSettings settings = base;
        settings.samplesPerPixel = referenceSpp;
        settings.seed = 1000003; // apart from the measured seeds 1..N
        info.reference = (fs::path(*dir) / "reference.exr").string();
        info.referenceMethod = std::string(samplerName(settings.sampler)) + "+" +
                               (settings.integrator == Integrator::Path
                                    ? lightSamplingName(settings.lightSampling)
                                    : integratorName(settings.integrator));
        info.referenceSpp = referenceSpp;
        std::fprintf(stderr, "wavefront: no --reference: rendering one with Wavefront itself, "
                     "%s at %u spp (seeds %u and %u), saved as %s\n",
                     info.referenceMethod.c_str(), referenceSpp, settings.seed,
                     settings.seed + 1, info.reference.c_str());
        reference = renderReference(context, prepared, compiler, settings, info.referenceNoise);
        writeExr(info.reference, int(base.width), int(base.height), reference,
                 {{"software", "Wavefront"}, {"scene", scenePath},
                  {"sampler", samplerName(settings.sampler)}},
                 {}, {{"spp", int(referenceSpp)}, {"seed", int(settings.seed)}});
    }

    std::vector<MethodRun> runs;
    std::vector<MethodSummary> summaries;
    for (const ConvergenceMethod& method : methods) {
        runs.push_back(runConvergence(
            context, prepared, compiler, base, method, options, reference,
            [&](uint32_t seed, const Checkpoint& c) {
                if (!quiet)
                    std::fprintf(stderr, "wavefront: %-28s seed %u %6u spp %8.3f s  relMSE %.4g\n",
                                 method.name.c_str(), seed, c.spp, c.gpuSeconds, c.error.relMse);
            }));
        summaries.push_back(summarize(runs.back()));
    }
    info.target = parsed.has("--target") ? parsed.floatValue("--target", 0.0f, 1e-30f, 1e30f)
                                         : defaultTarget(summaries);
    for (MethodSummary& s : summaries)
        setTimeToTarget(s, info.target);

    const std::vector<EqualTimeCrop> crops =
        writeEqualTimeCrops(*dir, runs, summaries, reference, info);
    writeConvergenceCsv((fs::path(*dir) / "convergence.csv").string(), runs);
    writeConvergenceJson((fs::path(*dir) / "convergence.json").string(), info, runs, summaries,
                         crops);
    std::fputs(rankingText(summaries, info.target).c_str(), stdout);
    if (std::isfinite(info.referenceNoise))
        std::printf("the reference's own noise adds relMSE %.3g to each figure above "
                    "(convergence.json: relMseLessReferenceNoise takes it off)\n",
                    info.referenceNoise);
    if (!parsed.has("--no-plot"))
        plotCharts(*dir);
    if (context.validationMessageCount() > 0) {
        std::fprintf(stderr, "wavefront: %u validation message(s)\n",
                     context.validationMessageCount());
        return 1;
    }
    return 0;
}

} // namespace wf
