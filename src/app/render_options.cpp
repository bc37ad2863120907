#include "app/render_options.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "errors.h"
#include "render/adaptive_sampling.h"
#include "render/guiding/guiding_schedule.h"
#include "render/samplers/samplers.h"
#include "scene/default_camera.h"
#include "scene/lights/environment_map.h"
#include "scene/lights/light_table.h"
#include "scene/gltf/gltf_loader.h"

namespace wf {

std::vector<OptionSpec> imageSizeOptions(uint32_t defaultWidth) {
    return {
        {"--width", "", "W", "image width in pixels (default " + std::to_string(defaultWidth) +
                                 ")"},
        {"--height", "", "H", "image height (default: width / the camera's aspect ratio)"},
    };
}

std::vector<OptionSpec> depthOptions(uint32_t defaultMaxDepth) {
    return {
        {"--max-depth", "", "D", "path segments from the camera: 1 shows emitters only, 2 adds "
                                 "direct light (default " + std::to_string(defaultMaxDepth) +
                                     ")"},
        {"--rr-depth", "", "N", "Russian roulette from bounce N on (default 3)"},
    };
}

std::vector<OptionSpec> samplingOptions() {
    return {
        {"--integrator", "", "NAME", "path (the path tracer with next-event estimation; "
                                     "default), light (light tracing: light subpaths "
                                     "connect each vertex to the camera, camera rays add the "
                                     "emitters they see; unbiased, leaves black what only "
                                     "Dirac surfaces seen directly show), bdpt "
                                     "(bidirectional path tracing: each pixel sample's camera "
                                     "subpath and the light subpath it shares with "
                                     "--light-share pixels, every connection between them "
                                     "weighed by MIS, the power heuristic; unbiased; keeps "
                                     "max-depth - 2 light vertices per pixel) or vcm (vertex "
                                     "connection and merging: bdpt plus merging each camera "
                                     "vertex with the light vertices within --vcm-radius, all "
                                     "weighed by MIS; CONSISTENT, NOT UNBIASED: its bias "
                                     "shrinks as the samples grow, and its error estimate "
                                     "measures variance, not that bias; keeps max-depth - 1 "
                                     "light vertices per pixel). light, bdpt and vcm trace "
                                     "whole samples of the image per wave (each sample's two "
                                     "subpaths at one time within --shutter) and take neither "
                                     "--target-error, guiding nor an orthographic camera"},
        {"--bdpt-heuristic", "", "NAME", "bdpt's and vcm's MIS weights: power (the power "
                                         "heuristic, beta 2; default) or balance (beta 1)"},
        {"--vcm-radius", "", "F", "vcm's merging radius at the first sample, as a fraction of "
                                  "the scene's bounding-sphere radius (default 0.01); sample "
                                  "i merges within that times (i + 1)^-1/8"},
        {"--light-share", "", "N", "light, bdpt and vcm: one light subpath per N pixels per "
                                   "sample, shared by those pixels' camera subpaths (pixels "
                                   "scattered over the image; unbiased: another image of the "
                                   "same expectation with fewer light tracer splats; default 8 "
                                   "for bdpt and vcm in scenes without a Dirac lobe (roughness "
                                   "0 on a mirror, clear glass or a coat), whose caustics need "
                                   "those splats and photons, else 1, and 1 for light; always 1 "
                                   "with something moving)"},
        {"--spectral", "", "MODE", "scenes with KHR_materials_dispersion only: from its first "
                                   "dispersive vertex on a path carries single (one "
                                   "wavelength; default) or hero (four, a quarter of the "
                                   "range apart, weighed by spectral MIS; docs/gltf.md)"},
        {"--light-sampling", "", "MODE", "bsdf (emission found by BSDF rays), nee (light "
                                         "sampling only) or mis (default)"},
        {"--light-selection", "", "MODE", "how NEE picks a light: uniform, power or tree (the "
                                          "light tree; default: tree with 4 or more lights "
                                          "that have a place, else power)"},
        {"--triangle-sampling", "", "MODE", "area or solid-angle (spherical triangles; "
                                            "default)"},
        {"--sphere-sampling", "", "MODE", "area or solid-angle (the cone; default)"},
        {"--min-throughput", "", "T", "end paths whose throughput falls below T (biased; "
                                      "default 0: off)"},
        {"--clamp", "", "X", "clamp each contribution to X per channel (biased; default 0: "
                             "off)"},
        {"--seed", "", "S", "random seed; same seed, same image bit for bit (default 0)"},
        {"--guiding", "", "MODE", "path guiding: off, on, or auto (default: on only where the "
                                  "measured rule of docs/guiding.md predicts a gain; on "
                                  "lavapipe it predicts none). "
                                  "Trains an SD-tree over 1, 2, 4, ... spp (within "
                                  "--time-limit), each spatial leaf learning its BSDF share "
                                  "(training stops, and the rest samples the BSDF alone, "
                                  "once no leaf's share paid in two iterations in a row), the "
                                  "image from the rest, the iterations' images weighed by "
                                  "their samples; a --resume trains its own guide; with "
                                  "--target-error the guide trains as the pilot and the rounds "
                                  "sample it frozen"},
        {"--sampler", "", "NAME", "sample pattern: independent, stratified, multijitter, "
                                  "halton, hammersley, sobol (default) or bluenoise"},
        {"--error-replicates", "", "K", "split each pixel's samples into K independently "
                                        "randomized copies of the sampler's sequence, whose "
                                        "spread measures the image's error for any sampler "
                                        "(calibrated, not a bound); 1 to 16 (default 1: one "
                                        "sequence, whose estimate bounds a correlated "
                                        "sampler's error from above; 2 with --target-error; "
                                        "the independent sampler needs none; a guided "
                                        "render's combined iterations keep the bound)"},
        {"--texture-filter", "", "MODE", "cone (mip levels chosen by ray cones; default) or "
                                         "none (full-resolution bilinear lookups)"},
        {"--shade-split", "", "MODE", "auto (scenes of Lambert and smooth mirror or glass "
                                      "materials shade each kind in its own pass; default), "
                                      "on (any scene of several kinds) or off (one shade pass "
                                      "for every hit)"},
    };
}

OptionSpec noRandomizeOption() {
    return {"--no-randomize", "", "", "same sample points in every pixel and for every seed "
                                      "(shows a pattern's structure; biased)"};
}

OptionSpec deviceOption() {
    return {"--device", "", "N", "Vulkan device index (default: WAVEFRONT_DEVICE, else the "
                                 "first GPU)"};
}

OptionSpec traversalOption() {
    return {"--traversal", "", "MODE",
            "auto (default: rt where the device has ray-tracing pipelines and is a GPU, else "
            "bvh; on lavapipe bvh measured faster), bvh (the project's BVH in compute) or rt "
            "(the driver's acceleration structures through ray-tracing pipelines: every "
            "extension ray, the light subpaths' too, while light_splat's shadow rays walk the "
            "BVH; refused where the device has none, and with --shutter, where auto takes "
            "bvh)"};
}

RayTracingRequest traversalRequest(const ParsedArgs& parsed) {
    const std::string mode = parsed.choiceValue("--traversal", "auto", {"auto", "bvh", "rt"});
    // Motion blur runs in the project's BVH only (motion.glsl), so auto takes it there.
    return mode == "rt"                                    ? RayTracingRequest::Required
           : mode == "bvh" || parsed.has("--shutter") ? RayTracingRequest::Off
                                                          : RayTracingRequest::Auto;
}

Traversal traversalFor(const Context& context) {
    // The context enables ray tracing only where the request (and auto's rule) picked it.
    return context.rayTracingEnabled() ? Traversal::RayTracing : Traversal::Bvh;
}

OptionSpec quietOption() { return {"--quiet", "-q", "", "no progress line on stderr"}; }

OptionSpec cameraOption() {
    return {"--camera", "", "NAME|INDEX", "render from the file's camera of this name or index "
                                          "(default: the first)"};
}

std::vector<OptionSpec> lensOptions() {
    return {{"--aperture", "", "D", "thin-lens camera: the lens's diameter in scene units "
                                    "(default: the camera's extras.aperture, else 0, a "
                                    "pinhole)"},
            {"--focus-distance", "", "F", "distance along the view to the plane in focus "
                                          "(default: the camera's extras.focusDistance, else "
                                          "the scene's centre's)"}};
}

OptionSpec instancingOption() {
    return {"--instancing", "", "MODE", "meshes that several nodes place: auto (kept once and "
                                        "instanced where the copies would add 1M triangles or "
                                        "more), on (always) or off (flattened); default auto"};
}

OptionSpec variantOption() {
    return {"--variant", "", "NAME|INDEX", "KHR_materials_variants: the primitives take this "
                                           "variant's materials, by name or index (default: "
                                           "their own; --verbose lists the file's variants)"};
}

std::vector<OptionSpec> animationOptions(bool withTime) {
    std::vector<OptionSpec> options = {
        {"--time", "", "SECONDS", "pose the scene's animations, skins and morph targets at this "
                                  "time (default 0: their start; clamped to each animation's "
                                  "keys)"},
            {"--frame", "", "N", "pose at frame N, the time N / --fps (instead of --time)"},
            {"--fps", "", "F", "frames per second of --frame, --frames and --shutter (default "
                               "24)"},
            {"--animation", "", "NAME|INDEX", "play only this animation of the file (default: "
                                              "every animation at once, as viewers do)"},
            {"--shutter", "", "OPEN:CLOSE", "motion blur: the shutter's interval in frames around "
                                            "the scene's time (e.g. -0.25:0.25, 1/--fps seconds "
                                            "a frame); each camera ray takes a time in it, "
                                            "moving nodes' meshes, cameras and lights are seen "
                                            "there; skinned, morphed or emissive meshes stay at "
                                            "its centre (warned). Default: none"}};
    if (!withTime)
        options.erase(options.begin());
    return options;
}

void applyShutter(const ParsedArgs& parsed, GltfOptions& options) {
    const auto text = parsed.value("--shutter");
    if (!text)
        return;
    const std::string usage = "--shutter " + *text + ": expected OPEN:CLOSE in frames, OPEN <= "
                                                     "CLOSE, e.g. -0.25:0.25";
    const size_t colon = text->find(':');
    if (colon == std::string::npos)
        throw UsageError(usage);
    auto number = [&](const std::string& part) {
        size_t used = 0;
        double value = 0.0;
        try {
            value = std::stod(part, &used);
        } catch (const std::exception&) {
            throw UsageError(usage);
        }
        if (used != part.size() || !std::isfinite(value) || std::abs(value) > 1e6)
            throw UsageError(usage);
        return value;
    };
    const double open = number(text->substr(0, colon));
    const double close = number(text->substr(colon + 1));
    if (open > close)
        throw UsageError(usage);
    if (parsed.value("--traversal") == "rt")
        throw UsageError("--traversal rt: motion blur (--shutter) is traced by the project's "
                         "BVH only; use --traversal bvh or auto");
    const double fps = parsed.floatValue("--fps", 24.0f, 1e-3f, 1e6f);
    options.shutterOpen = options.time + open / fps;
    options.shutterClose = options.time + close / fps;
    options.time = 0.5 * (options.shutterOpen + options.shutterClose);
}

double sceneTimeFrom(const ParsedArgs& parsed) {
    if (parsed.has("--time") && parsed.has("--frame"))
        throw UsageError("--time and --frame both set the scene's time: give one");
    if (parsed.has("--fps") && !parsed.has("--frame") && !parsed.has("--frames") &&
        !parsed.has("--shutter") && !parsed.has("--play"))
        throw UsageError("--fps applies to --frame, --frames or --shutter (view: and --play)");
    const double fps = parsed.floatValue("--fps", 24.0f, 1e-3f, 1e6f);
    if (parsed.has("--frame"))
        return double(parsed.uintValue("--frame", 0, 0, 1u << 30)) / fps;
    return parsed.floatValue("--time", 0.0f, -1e9f, 1e9f);
}

OptionSpec envOption() {
    return {"--env", "", "FILE.exr", "equirectangular environment map, linear RGB, +Y up "
                                     "(default: none; uniform white if nothing emits)"};
}

void applyRenderFlags(const ParsedArgs& parsed, uint32_t defaultMaxDepth,
                      RenderSettings& settings) {
    settings.maxDepth = parsed.uintValue("--max-depth", defaultMaxDepth, 1, 1024);
    settings.rrDepth = parsed.uintValue("--rr-depth", 3, 0, 1024);
    settings.seed = parsed.uintValue("--seed", 0, 0, 0xffffffffu);
    settings.integrator =
        parseIntegrator(parsed.choiceValue("--integrator", "path",
                                           {"path", "light", "bdpt", "vcm"}));
    settings.bdptBalance =
        parsed.choiceValue("--bdpt-heuristic", "power", {"power", "balance"}) == "balance";
    if (settings.bdptBalance && !bidirectional(settings.integrator))
        throw UsageError("--bdpt-heuristic applies to --integrator bdpt or vcm");
    // converge's methods name their integrators themselves (the word vcm).
    if (parsed.has("--vcm-radius") && parsed.has("--integrator") &&
        settings.integrator != Integrator::Vcm)
        throw UsageError("--vcm-radius applies to --integrator vcm");
    settings.vcmRadius = parsed.floatValue("--vcm-radius", settings.vcmRadius, 1e-6f, 1.0f);
    if (parsed.has("--light-share") && settings.integrator == Integrator::Path)
        throw UsageError("--light-share applies to --integrator light, bdpt or vcm");
    settings.lightShare = parsed.uintValue("--light-share", 0, 1, 1u << 24);
    settings.spectral = parseSpectralSampling(
        parsed.choiceValue("--spectral", spectralSamplingName(settings.spectral),
                           {"single", "hero"}));
    settings.lightSampling =
        parseLightSampling(parsed.choiceValue("--light-sampling", "mis", {"bsdf", "nee", "mis"}));
    if (parsed.has("--light-selection"))
        settings.lightSelection = parseLightSelection(
            parsed.choiceValue("--light-selection", "power", {"uniform", "power", "tree"}));
    settings.triangleSolidAngle = parsed.choiceValue("--triangle-sampling", "solid-angle",
                                                     {"area", "solid-angle"}) == "solid-angle";
    settings.sphereSolidAngle = parsed.choiceValue("--sphere-sampling", "solid-angle",
                                                   {"area", "solid-angle"}) == "solid-angle";
    settings.minThroughput = parsed.floatValue("--min-throughput", 0.0f, 0.0f, 1e30f);
    settings.clampRadiance = parsed.floatValue("--clamp", 0.0f, 0.0f, 1e30f);
    settings.sampler = parseSampler(
        parsed.choiceValue("--sampler", samplerName(kDefaultSampler), samplerNames()));
    settings.randomizeSamples = !parsed.has("--no-randomize");
    // A target is planned and judged by the estimate: calibrated unless told otherwise.
    settings.errorReplicates = parsed.uintValue(
        "--error-replicates", parsed.has("--target-error") ? kTargetErrorReplicates : 1, 1, 16);
    const guiding::GuidingMode guide =
        guiding::parseGuidingMode(parsed.choiceValue("--guiding", "auto", {"off", "on", "auto"}));
    settings.guiding = guide == guiding::GuidingMode::On;
    settings.guidingAuto = guide == guiding::GuidingMode::Auto;
    settings.textureLod =
        parsed.choiceValue("--texture-filter", "cone", {"cone", "none"}) == "cone";
    const std::string split = parsed.choiceValue("--shade-split", "auto", {"auto", "on", "off"});
    settings.shadeSplit = split == "on"    ? ShadeSplit::On
                          : split == "off" ? ShadeSplit::Off
                                           : ShadeSplit::Auto;
    if (!settings.randomizeSamples && settings.sampler == SamplerKind::Independent)
        throw UsageError("--no-randomize: the independent sampler has no randomization to "
                         "remove (pick another --sampler)");
}

Tonemap previewTonemapFrom(const ParsedArgs& parsed) {
    return parseTonemap(parsed.value("--tonemap").value_or(tonemapName(kDefaultTonemap)));
}

ContextOptions contextOptionsFrom(const ParsedArgs& parsed) {
    ContextOptions options;
    if (parsed.has("--device"))
        options.deviceIndex = static_cast<int>(parsed.uintValue("--device", 0, 0, 64));
    options.quiet = parsed.has("--quiet");
    options.rayTracing = traversalRequest(parsed);
    return options;
}

namespace {

// --aperture and --focus-distance over the camera's own; an unset focus distance with a lens
// focuses on the scene's centre (its bounding sphere's, along the view).
void applyLensFlags(const ParsedArgs& parsed, Scene& scene) {
    Camera& camera = scene.camera;
    if (camera.orthoHalfHeight > 0.0f) { // parallel rays: no lens, whatever extras say
        if (parsed.floatValue("--aperture", 0.0f, 0.0f, 1e30f) > 0.0f)
            throw UsageError("--aperture: the chosen camera is orthographic, which has no lens");
        camera.aperture = 0.0f;
    }
    camera.aperture = parsed.floatValue("--aperture", camera.aperture, 0.0f, 1e30f);
    camera.focusDistance =
        parsed.floatValue("--focus-distance", camera.focusDistance, 1e-30f, 1e30f);
    if (camera.aperture <= 0.0f || camera.focusDistance > 0.0f)
        return;
    const bool empty = scene.triangles.empty() && scene.lights.empty();
    const float along =
        empty ? 0.0f : glm::dot(sceneBounds(scene).center - camera.position, camera.forward);
    camera.focusDistance = along > 0.0f ? along : 1.0f;
}

} // namespace

Scene loadSceneWithFlags(const ParsedArgs& parsed, const std::string& path,
                         SceneSummary* summary, std::optional<double> time,
                         bool printWarnings) {
    std::vector<std::string> warnings; // printed once the scene and flags are accepted
    GltfOptions options;
    options.time = time ? *time : sceneTimeFrom(parsed);
    options.animation = parsed.value("--animation").value_or("");
    applyShutter(parsed, options);
    if (auto mode = parsed.value("--instancing"))
        options.instancing = parseInstancing(*mode);
    options.variant = parsed.value("--variant").value_or("");
    const auto start = std::chrono::steady_clock::now();
    Scene scene = loadGltf(path, &warnings, options);
    const double loadSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (auto name = parsed.value("--camera")) {
        scene.camera = selectCamera(scene, *name, path);
        scene.hasCamera = true;
    }
    if (auto env = parsed.value("--env"))
        scene.environment = loadEnvironmentExr(*env);
    if (summary) {
        *summary = summarize(scene);
        summary->loadSeconds = loadSeconds;
    }
    if (!scene.hasCamera)
        scene.camera = frameBounds(scene);
    applyLensFlags(parsed, scene);
    for (const std::string& line : warnings)
        if (printWarnings)
            std::fprintf(stderr, "%s\n", line.c_str());
    return scene;
}

void applyImageSize(const ParsedArgs& parsed, const Camera& camera, const ImageSizeRule& rule,
                    RenderSettings& settings) {
    const float aspect = camera.aspect > 0.0f ? camera.aspect : 1.0f;
    const auto rounded = [](float size) {
        return std::max(1u, static_cast<uint32_t>(std::lround(size)));
    };
    const bool hasWidth = parsed.has("--width"), hasHeight = parsed.has("--height");
    settings.width = parsed.uintValue("--width", rule.width, 1, 16384);
    settings.height = parsed.uintValue("--height", 0, 1, 16384);
    if (!hasHeight && rule.height && !hasWidth)
        settings.height = *rule.height;
    else if (!hasHeight)
        settings.height = rounded(settings.width / aspect);
    else if (!hasWidth && rule.widthFollowsHeight)
        settings.width = rounded(settings.height * aspect);
}

guiding::GuidingDecision resolveGuiding(RenderSettings& settings, const PreparedScene& scene) {
    if (!settings.guidingAuto)
        return guiding::decideGuiding(settings.guiding ? guiding::GuidingMode::On
                                                       : guiding::GuidingMode::Off,
                                      {}, settings.samplesPerPixel);
    settings.guidingAuto = false;
    guiding::GuidingDecision decision;
    if (settings.integrator != Integrator::Path) {
        decision.reason = std::string("auto: off with --integrator ") +
                          integratorName(settings.integrator) + " (the guide guides camera paths)";
    } else if (settings.pixelList) {
        // auto never refuses: where `on` would be refused, it stays off.
        decision.reason = "auto: off with --target-error (its budget is unknown until the pilot; "
                          "--guiding on trains the guide as the pilot)";
    } else {
        decision = guiding::decideGuiding(guiding::GuidingMode::Auto,
                                          guiding::guideSceneTraits(scene),
                                          settings.samplesPerPixel);
    }
    settings.guiding = decision.on;
    return decision;
}

} // namespace wf
