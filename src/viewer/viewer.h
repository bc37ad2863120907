// `wavefront view`: a window that refines the image progressively while the user looks, moves
// and compares. The frame loop (viewer.cpp) reads top-down:
//   events -> keys and camera -> overlay -> path trace a bounded amount -> display -> present
// Accumulation restarts on any change of camera or render settings; exposure and tone curve
// only change the display.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "gpu/context.h"
#include "render/wavefront_renderer.h"
#include "scene/gltf/gltf_instancing.h"
#include "viewer/display_pass.h"

namespace wf {

// What the user can change while viewing, named as the command-line flags.
struct ViewSettings {
    // The renderer's settings (max depth, Russian roulette, seed, and whatever the renderer
    // gains): a change rebuilds the renderers and restarts the accumulation. Width, height and
    // spp are the viewer's business and ignored here.
    RenderSettings render;
    // Refinement stops at this many samples per pixel; 0: never, except for the finite-set
    // samplers, whose set must be known up front: they stop at kFiniteSetSpp.
    uint32_t sppLimit = 0;
    static constexpr uint32_t kFiniteSetSpp = 256;
    uint32_t effectiveSppLimit() const;
    // Display only.
    float exposure = 0.0f; // stops (EV)
    Tonemap tonemap = kDefaultTonemap;
    // Frame pacing: path tracing per frame aims at this many milliseconds.
    double targetMs = 33.0;
};

struct ResizeAt {
    uint32_t frame;
    int width;
    int height;
};

struct ViewerOptions {
    std::string scenePath;
    // Initial window size in screen coordinates; the render size is the framebuffer's. 0: from
    // the other one and the starting camera's aspect ratio, as `render` sizes its image.
    int windowWidth = 512;
    int windowHeight = 0;
    ViewSettings settings;
    // The starting camera, by name or index in the list (the file's cameras, then the framing
    // one); none: the camera `wavefront render` uses.
    std::optional<std::string> camera;
    std::string environmentPath; // --env, replacing the scene's environment
    Instancing instancing = Instancing::Auto; // --instancing
    double time = 0.0;                        // --time, --frame: the pose shown first
    double fps = 24.0;                        // --fps: playback shows frames of 1/fps
    bool play = false;                        // --play: start playing (T plays / pauses)
    std::string animation;                    // --animation
    std::string variant;                      // --variant (KHR_materials_variants)
    std::optional<int> device;
    RayTracingRequest rayTracing = RayTracingRequest::Off; // --traversal
    bool overlay = true;
    bool quiet = false;
    // Automation (scripts and tests).
    uint32_t frames = 0;          // quit after this many frames; 0: when the user quits
    bool untilDone = false;       // quit once the image reaches its sample limit (--until-done)
    std::string screenshot;       // .exr written on quit, with the shown frame as .png beside it
    std::optional<ResizeAt> resizeAt; // resize the window after a frame
    float orbitDegrees = 0.0f;    // orbit the camera this much every frame, as a drag would
};

// Returns the exit code: 0, or 1 when validation messages were counted.
int runViewer(const ViewerOptions& options);

} // namespace wf
