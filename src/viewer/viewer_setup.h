// What the viewer sets up before its first frame, read as `wavefront render` reads it: the
// scene with the same camera choice and environment, the window sized by the same rule, and a
// Vulkan context that can present to that window.
#pragma once
#include <string>
#include <vector>

#include "gpu/context.h"
#include "render/gpu_scene/scene_buffers.h"
#include "viewer/camera_list.h"
#include "viewer/viewer.h"
#include "viewer/window.h"

namespace wf {

struct ViewerScene {
    PreparedScene prepared;
    CameraList cameras;
    ViewBounds bounds;
    double animationSeconds = 0.0; // the last key of the animations played (0: static)
    std::vector<std::string> variantNames; // KHR_materials_variants, for the overlay's list
    int variant = -1;                      // the one shown (--variant); -1: the own materials
};

// Loads options.scenePath (and --env), printing the loader's warnings unless quiet.
ViewerScene loadViewerScene(const ViewerOptions& options);
// The same scene posed at `time` (the playback's later frames), warnings dropped: they were
// printed with the first pose.
Scene loadPosedScene(const ViewerOptions& options, double time);

// --width/--height as `wavefront render` reads them: a missing one follows the camera's aspect.
WindowSize initialWindowSize(const ViewerOptions& options, const Camera& camera);

std::string windowTitle(const std::string& scenePath);

// Context options for `window`: its surface extensions, and its surface created with the
// instance. The window must outlive the context.
ContextOptions presentingContext(const ViewerOptions& options, const Window& window);

} // namespace wf
