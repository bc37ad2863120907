#include "viewer/viewer_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "render/samplers/samplers.h"
#include "scene/default_camera.h"
#include "scene/lights/environment_map.h"
#include "scene/gltf/gltf_loader.h"

namespace wf {

uint32_t ViewSettings::effectiveSppLimit() const {
    return sppLimit == 0 && samplerIsFiniteSet(render.sampler) ? kFiniteSetSpp : sppLimit;
}

namespace {

Scene loadAt(const ViewerOptions& options, double time, std::vector<std::string>* warnings) {
    GltfOptions gltf{options.instancing, time, options.animation};
    gltf.variant = options.variant;
    Scene scene = loadGltf(options.scenePath, warnings, gltf);
    if (!options.environmentPath.empty())
        scene.environment = loadEnvironmentExr(options.environmentPath);
    if (!scene.hasCamera)
        scene.camera = frameBounds(scene); // as `wavefront render` does
    return scene;
}

} // namespace

ViewerScene loadViewerScene(const ViewerOptions& options) {
    std::vector<std::string> warnings;
    Scene scene = loadAt(options, options.time, &warnings);
    for (const std::string& line : warnings)
        if (!options.quiet)
            std::fprintf(stderr, "%s\n", line.c_str());
    ViewerScene viewer;
    viewer.cameras = viewerCameras(scene);
    viewer.bounds = viewBounds(scene);
    viewer.animationSeconds = scene.animationSeconds;
    viewer.variantNames = scene.variantNames;
    viewer.variant = scene.variant;
    viewer.prepared = prepareScene(std::move(scene));
    return viewer;
}

Scene loadPosedScene(const ViewerOptions& options, double time) {
    std::vector<std::string> warnings;
    return loadAt(options, time, &warnings);
}

WindowSize initialWindowSize(const ViewerOptions& options, const Camera& camera) {
    const double aspect = camera.aspect > 0.0f ? camera.aspect : 1.0;
    int width = options.windowWidth, height = options.windowHeight;
    if (width <= 0 && height <= 0)
        width = 512;
    if (height <= 0)
        height = std::max(1, int(std::lround(width / aspect)));
    else if (width <= 0)
        width = std::max(1, int(std::lround(height * aspect)));
    return {width, height};
}

std::string windowTitle(const std::string& scenePath) {
    return "Wavefront - " + std::filesystem::path(scenePath).filename().string();
}

ContextOptions presentingContext(const ViewerOptions& options, const Window& window) {
    ContextOptions context;
    context.deviceIndex = options.device;
    context.quiet = options.quiet;
    context.rayTracing = options.rayTracing;
    context.instanceExtensions = window.instanceExtensions();
    context.createSurface = [&window](VkInstance instance) {
        return window.createSurface(instance);
    };
    return context;
}

} // namespace wf
