// The viewer's overlay: Dear ImGui (Debian's libimgui-dev 1.86, its GLFW and Vulkan backends
// as compiled into libimgui.a). It shows what the renderer is doing (spp, frame time, GPU
// milliseconds per pass, rays/s, paths/s) and edits the ViewSettings, each control labelled
// with its command-line flag. It draws inside the frame presenter's render pass, so it is part
// of "what is shown" and of a screenshot's PNG.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "viewer/animation_overlay.h"
#include "viewer/viewer.h"

struct GLFWwindow;

namespace wf {

class Context;
struct RenderStats;

// Read-only facts for one frame.
struct OverlayFacts {
    std::string scene;
    std::string device;
    uint32_t width = 0; // render size (the framebuffer's)
    uint32_t height = 0;
    uint32_t spp = 0;
    uint32_t samplesThisFrame = 0;
    uint32_t previewDivisor = 1; // > 1: showing the moving-camera preview at 1/d resolution
    double frameMs = 0.0;
    const RenderStats* stats = nullptr; // of the renderer shown
    std::string guideStatus; // viewer_guide.h: training, frozen or none
    bool paused = false;
    std::vector<std::string> cameraNames;
    uint32_t camera = 0;
    std::vector<std::string> variantNames; // KHR_materials_variants; empty: none in the file
    int variant = -1;                      // shown; -1: the primitives' own materials
    AnimationFacts animation; // animation_overlay.h
};

// What the user asked for this frame, beyond the edited settings.
struct OverlayActions {
    bool renderChanged = false;  // max depth, rr depth or seed: rebuild and restart
    bool displayChanged = false; // exposure or tone curve
    bool targetChanged = false;  // target-ms
    int selectCamera = -1;
    bool variantChanged = false; // reload the scene with `variant` (-1: the own materials)
    int variant = -1;
    bool resetView = false;
    bool restart = false;
    bool screenshot = false;
    bool togglePause = false;
    AnimationActions animation; // animation_overlay.h
};

class Overlay {
public:
    Overlay(const Context& context, GLFWwindow* window, VkRenderPass renderPass, float scale);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // Starts an ImGui frame; after it, wantsMouse/wantsKeyboard say whether input is ImGui's.
    void newFrame();
    bool wantsMouse() const;
    bool wantsKeyboard() const;
    // Builds the widgets (nothing when hidden) and finishes the frame's draw lists.
    OverlayActions build(const OverlayFacts& facts, ViewSettings& settings, bool visible);
    // Records the finished draw lists; call inside the presenter's render pass.
    void record(VkCommandBuffer cmd) const;

private:
    VkDevice device_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

// The keys and mouse bindings, for --help and the overlay.
extern const char* const kViewerControlsHelp;

} // namespace wf
