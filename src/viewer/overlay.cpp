#include "viewer/overlay.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "gpu/context.h"
#include "gpu/vk_check.h"
#include "render/samplers/samplers.h"
#include "render/wavefront_renderer.h"

namespace wf {

const char* const kViewerControlsHelp =
    "  left drag            orbit around the target\n"
    "  middle / shift+left  pan\n"
    "  wheel                dolly towards / away from the target\n"
    "  right drag           look around (fly)\n"
    "  W A S D, Q E         fly forward, left, back, right, down, up (shift: faster)\n"
    "  C, 1-9               next camera, camera N (the file's, then the framing camera)\n"
    "  R                    reset the view to the current camera and restart\n"
    "  Space                pause / resume refinement\n"
    "  T                    play / pause the animation (animated scenes)\n"
    "  F12 or P             screenshot: SCENE-NNN.exr (radiance) + .png (as shown)\n"
    "  H                    show / hide the overlay\n"
    "  Esc                  quit\n";

namespace {

void checkImGuiVk(VkResult result) {
    if (result < 0) // ImGui also reports VK_SUCCESS; only errors are negative
        throwVkError("Dear ImGui Vulkan backend", result, __FILE__, __LINE__);
}

double perSecond(double count, double seconds) { return seconds > 0.0 ? count / seconds : 0.0; }

// Counts as 967k, 1.2M: the overlay must stay narrow.
std::string shortCount(double value) {
    char text[32];
    if (value >= 1e6)
        std::snprintf(text, sizeof text, "%.3gM", value / 1e6);
    else if (value >= 1e3)
        std::snprintf(text, sizeof text, "%.3gk", value / 1e3);
    else
        std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

void statsSection(const OverlayFacts& facts) {
    ImGui::TextDisabled("%s", facts.device.c_str());
    ImGui::Text("%u x %u", facts.width, facts.height);
    if (facts.previewDivisor > 1) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "moving: 1/%u preview",
                           facts.previewDivisor);
    }
    ImGui::Text("spp %u (+%u)%s   frame %.0f ms", facts.spp, facts.samplesThisFrame,
                facts.paused ? " paused" : "", facts.frameMs);
    if (!facts.stats)
        return;
    const RenderStats& s = *facts.stats;
    const double rays = double(s.cameraRays + s.extensionRays + s.shadowRays);
    ImGui::Text("%.3g spp/s  %s paths/s  %s rays/s", perSecond(s.samplesPerPixel, s.seconds),
                shortCount(perSecond(double(s.paths), s.seconds)).c_str(),
                shortCount(perSecond(rays, s.seconds)).c_str());
    if (s.samplesPerPixel == 0 ||
        !ImGui::CollapsingHeader("GPU time per pass", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingFixedFit)) {
        // Summed over the waves since the last restart, shown per sample per pixel.
        for (const auto& [pass, ms] : s.passMilliseconds) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(pass.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%7.2f ms/spp", ms / s.samplesPerPixel);
        }
        ImGui::EndTable();
    }
}

// The estimator's settings, as render's flags name them.
void samplingRows(RenderSettings& render, OverlayActions& actions) {
    int sampler = 0;
    std::string choices;
    for (size_t i = 0; i < allSamplers().size(); ++i) {
        sampler = allSamplers()[i] == render.sampler ? int(i) : sampler;
        choices += std::string(samplerName(allSamplers()[i])) + '\0';
    }
    if (ImGui::Combo("--sampler", &sampler, choices.c_str())) {
        render.sampler = allSamplers()[size_t(sampler)];
        actions.renderChanged = true;
    }
    // Integrator's order: path, light, bdpt, vcm.
    int integrator = int(render.integrator);
    if (ImGui::Combo("--integrator", &integrator, "path\0light\0bdpt\0vcm\0")) {
        render.integrator = Integrator(integrator);
        actions.renderChanged = true;
    }
    int lightSampling = int(render.lightSampling);
    if (ImGui::Combo("--light-sampling", &lightSampling, "bsdf\0nee\0mis\0")) {
        render.lightSampling = LightSampling(lightSampling);
        actions.renderChanged = true;
    }
    // LightSelection's order: auto (the scene's default), uniform, power, tree.
    int selection = int(render.lightSelection);
    if (ImGui::Combo("--light-selection", &selection, "default\0uniform\0power\0tree\0")) {
        render.lightSelection = LightSelection(selection);
        actions.renderChanged = true;
    }
    int triangle = render.triangleSolidAngle ? 1 : 0, sphere = render.sphereSolidAngle ? 1 : 0;
    if (ImGui::Combo("--triangle-sampling", &triangle, "area\0solid-angle\0")) {
        render.triangleSolidAngle = triangle == 1;
        actions.renderChanged = true;
    }
    if (ImGui::Combo("--sphere-sampling", &sphere, "area\0solid-angle\0")) {
        render.sphereSolidAngle = sphere == 1;
        actions.renderChanged = true;
    }
    ImGui::InputFloat("--min-throughput", &render.minThroughput, 0.0f, 0.0f, "%g");
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        render.minThroughput = std::max(render.minThroughput, 0.0f);
        actions.renderChanged = true;
    }
    ImGui::InputFloat("--clamp", &render.clampRadiance, 0.0f, 0.0f, "%g");
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        render.clampRadiance = std::max(render.clampRadiance, 0.0f);
        actions.renderChanged = true;
    }
}

// --guiding off|on|auto: a live switch (the renderer is rebuilt, and a guided one trains while
// the image refines: viewer_guide.h), and where the guide stands.
void guidingRow(const std::string& status, RenderSettings& render, OverlayActions& actions) {
    int mode = render.guidingAuto ? 2 : render.guiding ? 1 : 0;
    if (ImGui::Combo("--guiding", &mode, "off\0on\0auto\0")) {
        render.guiding = mode == 1;
        render.guidingAuto = mode == 2;
        actions.renderChanged = true;
    }
    ImGui::TextUnformatted(status.c_str());
}

// One control per ViewSettings field that changes the image, labelled as its flag. A new
// RenderSettings field (a sampler) gets its row here and its flag in view_command.cpp, and
// sets renderChanged like max-depth does; the viewer passes RenderSettings through whole.
void renderSection(ViewSettings& settings, OverlayActions& actions) {
    RenderSettings& render = settings.render;
    int maxDepth = int(render.maxDepth), rrDepth = int(render.rrDepth);
    int seed = int(render.seed), spp = int(settings.sppLimit);
    ImGui::SliderInt("--max-depth", &maxDepth, 1, 64);
    if (ImGui::IsItemDeactivatedAfterEdit()) { // rebuilding per slider step would stall
        render.maxDepth = uint32_t(maxDepth);
        actions.renderChanged = true;
    }
    ImGui::SliderInt("--rr-depth", &rrDepth, 0, 64);
    if (ImGui::IsItemDeactivatedAfterEdit()) {
        render.rrDepth = uint32_t(rrDepth);
        actions.renderChanged = true;
    }
    if (ImGui::InputInt("--seed", &seed) && seed >= 0) {
        render.seed = uint32_t(seed);
        actions.renderChanged = true;
    }
    if (ImGui::InputInt("--spp (0: none)", &spp, 16) && spp >= 0) {
        settings.sppLimit = uint32_t(spp);
        // A finite-set sampler's set is the limit: a new limit is a new set.
        actions.renderChanged |= samplerIsFiniteSet(render.sampler);
    }
    if (ImGui::TreeNode("Sampling")) {
        samplingRows(render, actions);
        ImGui::TreePop();
    }
}

void displaySection(ViewSettings& settings, OverlayActions& actions) {
    actions.displayChanged |= ImGui::SliderFloat("--exposure (EV)", &settings.exposure, -10.0f,
                                                 10.0f, "%.1f");
    int tonemap = int(settings.tonemap);
    if (ImGui::Combo("--tonemap", &tonemap, "linear\0aces\0neutral\0")) {
        settings.tonemap = Tonemap(tonemap);
        actions.displayChanged = true;
    }
    float targetMs = float(settings.targetMs);
    if (ImGui::SliderFloat("--target-ms", &targetMs, 5.0f, 1000.0f, "%.0f",
                           ImGuiSliderFlags_Logarithmic)) {
        settings.targetMs = targetMs;
        actions.targetChanged = true;
    }
}

} // namespace

Overlay::Overlay(const Context& context, GLFWwindow* window, VkRenderPass renderPass,
                 float scale)
    : device_(context.device()) {
    // The backend needs one combined image sampler: the font atlas.
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 1;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool_));

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini left in the user's working folder
    io.FontGlobalScale = scale;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().ScaleAllSizes(scale);
    ImGui_ImplGlfw_InitForVulkan(window, true);

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance();
    info.PhysicalDevice = context.physicalDevice();
    info.Device = device_;
    info.QueueFamily = context.queueFamily();
    info.Queue = context.queue();
    info.DescriptorPool = pool_;
    // Frames are presented one at a time (the presenter waits), so two vertex-buffer sets
    // (the backend's minimum) never overlap.
    info.MinImageCount = 2;
    info.ImageCount = 2;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkImGuiVk;
    ImGui_ImplVulkan_Init(&info, renderPass);
    context.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

Overlay::~Overlay() {
    vkDeviceWaitIdle(device_);
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(device_, pool_, nullptr);
}

void Overlay::newFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

bool Overlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool Overlay::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

OverlayActions Overlay::build(const OverlayFacts& facts, ViewSettings& settings, bool visible) {
    OverlayActions actions;
    if (visible) {
        ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
        // Auto-sized, but never taller than the window: a small window scrolls the overlay.
        ImGui::SetNextWindowSizeConstraints(
            ImVec2(0, 0), ImVec2(FLT_MAX, std::max(ImGui::GetIO().DisplaySize.y - 16.0f, 64.0f)));
        ImGui::SetNextWindowBgAlpha(0.75f);
        ImGui::Begin(facts.scene.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::PushItemWidth(ImGui::GetFontSize() * 7.0f);
        statsSection(facts);
        animationSection(facts.animation, actions.animation);
        if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen))
            renderSection(settings, actions);
        if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen))
            displaySection(settings, actions);
        if (ImGui::CollapsingHeader("Path guiding", ImGuiTreeNodeFlags_DefaultOpen))
            guidingRow(facts.guideStatus, settings.render, actions);
        if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
            int camera = int(facts.camera);
            std::string items;
            for (const std::string& name : facts.cameraNames)
                items += name + '\0';
            if (ImGui::Combo("--camera", &camera, items.c_str()))
                actions.selectCamera = camera;
            actions.resetView = ImGui::Button("Reset view (R)");
            ImGui::SameLine();
            actions.restart = ImGui::Button("Restart");
        }
        if (!facts.variantNames.empty() &&
            ImGui::CollapsingHeader("Material variant", ImGuiTreeNodeFlags_DefaultOpen)) {
            int variant = facts.variant + 1; // 0: the primitives' own materials
            std::string items = std::string("(own materials)") + '\0';
            for (size_t i = 0; i < facts.variantNames.size(); ++i)
                items += (facts.variantNames[i].empty() ? "variant " + std::to_string(i)
                                                        : facts.variantNames[i]) + '\0';
            if (ImGui::Combo("--variant", &variant, items.c_str())) {
                actions.variantChanged = variant - 1 != facts.variant;
                actions.variant = variant - 1;
            }
        }
        actions.togglePause = ImGui::Button(facts.paused ? "Resume (Space)" : "Pause (Space)");
        ImGui::SameLine();
        actions.screenshot = ImGui::Button("Screenshot (F12)");
        if (ImGui::CollapsingHeader("Keys"))
            ImGui::TextUnformatted(kViewerControlsHelp);
        ImGui::PopItemWidth();
        ImGui::End();
    }
    ImGui::Render();
    return actions;
}

void Overlay::record(VkCommandBuffer cmd) const {
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
}

} // namespace wf
