#include "viewer/viewer.h"

#include <GLFW/glfw3.h>

#include <signal.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "errors.h"
#include "gpu/context.h"
#include "render/gpu_scene/frame_scenes.h"
#include "render/samplers/samplers.h"
#include "scene/animation/animation_clock.h"
#include "viewer/camera_controller.h"
#include "viewer/camera_list.h"
#include "viewer/frame_presenter.h"
#include "viewer/overlay.h"
#include "viewer/render_targets.h"
#include "viewer/screenshot.h"
#include "viewer/viewer_guide.h"
#include "viewer/viewer_input.h"
#include "viewer/viewer_setup.h"
#include "viewer/window.h"

namespace wf {
namespace {

using Clock = std::chrono::steady_clock;

// SIGINT and SIGTERM end the frame loop like Esc, so the device is idled and every object
// destroyed in order; a second signal (SA_RESETHAND) kills at once.
volatile sig_atomic_t quitSignalled = 0;
void onQuitSignal(int) { quitSignalled = 1; }

// The moving-camera preview stays this long after the last change, so that a drag that
// pauses for a frame does not start a full-resolution sample (most of a second on lavapipe).
constexpr double kPreviewHoldSeconds = 0.25;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

uint32_t startCamera(const ViewerOptions& options, const CameraList& cameras) {
    return options.camera ? findCamera(cameras, *options.camera) : cameras.renderDefault;
}

class Viewer {
public:
    explicit Viewer(const ViewerOptions& options)
        : options_(options), settings_(options.settings),
          scene_(loadViewerScene(options)), cameraIndex_(startCamera(options, scene_.cameras)),
          window_(windowTitle(options.scenePath),
                  initialWindowSize(options, scene_.cameras.cameras[cameraIndex_].camera)),
          context_(presentingContext(options, window_)),
          controller_(scene_.cameras.cameras[cameraIndex_].camera, scene_.bounds.center,
                      scene_.bounds.radius),
          presenter_(context_, waitForFramebuffer()),
          overlay_(context_, window_.handle(), presenter_.overlayRenderPass(),
                   window_.contentScale()),
          targets_(context_, compiler_, scene_.prepared), input_(window_, overlay_),
          overlayVisible_(options.overlay),
          clock_(scene_.animationSeconds, options.fps, options.time) {
        clock_.setPlaying(options.play);
        framebuffer_ = window_.framebufferSize();
        targets_.setTargetSeconds(settings_.targetMs / 1000.0);
        rebuildTargets();
    }

    int run();

private:
    VkExtent2D waitForFramebuffer();
    bool fitWindow(bool force);
    void rebuildTargets();
    void applyKeys(const WindowEvents& events);
    void applyOverlay(const OverlayActions& actions);
    void selectCamera(uint32_t index);
    void repose();
    void switchVariant(int variant);
    void cameraMoved() {
        ++cameraVersion_;
        lastMove_ = Clock::now();
    }
    RenderTarget& chooseTarget(bool forScreenshot);
    OverlayFacts facts() const;
    bool present(RenderTarget& target, bool keepPixels);
    void saveScreenshot(const std::string& exrPath);
    void captureScreenshot(const std::string& exrPath);
    bool refining() const {
        const uint32_t spp = targets_.fullSpp();
        const uint32_t limit = settings_.effectiveSppLimit();
        return !paused_ && (limit == 0 || spp < limit);
    }

    ViewerOptions options_;
    ViewSettings settings_;
    ViewerGuide guide_; // --guiding: trains while the image refines
    ViewerScene scene_;
    uint32_t cameraIndex_;
    Window window_; // outlives the context, which owns the window's surface
    Context context_;
    ShaderCompiler compiler_;
    CameraController controller_;
    FramePresenter presenter_;
    Overlay overlay_;
    RenderTargets targets_;
    ViewerInput input_;
    VkExtent2D framebuffer_{};
    bool overlayVisible_;
    bool paused_ = false;
    bool resizePending_ = false; // --resize-at asked for a size the window has not reached yet
    bool screenshotRequested_ = false;
    uint64_t cameraVersion_ = 0;
    Clock::time_point lastMove_ = Clock::now() - std::chrono::hours(1);
    // What the overlay shows about the frame before.
    RenderStats shownStats_;
    uint32_t shownSpp_ = 0;
    uint32_t shownSamples_ = 0;
    uint32_t shownDivisor_ = 1;
    double frameMs_ = 0.0;
    // Playback (animated scenes): the time shown, and each pose's scene (refit while the
    // tree holds up), which the renderers read.
    anim::AnimationClock clock_;
    FrameScenes poses_{FrameBvh::Refit};
    bool poseChanged_ = false;
    // For the closing summary.
    uint64_t fullSamples_ = 0;
    uint32_t previewFrames_ = 0;
    uint32_t posesShown_ = 0;
};

VkExtent2D Viewer::waitForFramebuffer() {
    // A window can start minimised (zero-sized); there is nothing to present to until it is not.
    for (VkExtent2D size = window_.framebufferSize();; size = window_.framebufferSize()) {
        if (size.width > 0 && size.height > 0)
            return size;
        if (quitSignalled || window_.shouldClose())
            throw InternalError("the viewer window was closed before it was shown");
        window_.waitEvents(0.1);
    }
}

bool Viewer::fitWindow(bool force) {
    const VkExtent2D size = window_.framebufferSize();
    if (size.width == 0 || size.height == 0)
        return false; // minimised
    const bool sameSize = size.width == framebuffer_.width && size.height == framebuffer_.height;
    if (!force && sameSize)
        return true;
    if (!sameSize)
        resizePending_ = false;
    framebuffer_ = size;
    presenter_.resize(size);
    rebuildTargets();
    return true;
}

void Viewer::rebuildTargets() {
    RenderSettings render = settings_.render;
    // The context enabled ray tracing only where --traversal (or auto's rule) picked it.
    render.traversal = context_.rayTracingEnabled() ? Traversal::RayTracing : Traversal::Bvh;
    if (samplerIsFiniteSet(render.sampler)) // the set is what the viewer will accumulate
        render.sampleSetSize = settings_.effectiveSppLimit();
    ViewerGuide::resolve(render, scene_.prepared);
    targets_.rebuild(presenter_.extent(), render, presenter_.displayBuffer());
    guide_.attach(targets_.full().renderer.get());
}

void Viewer::selectCamera(uint32_t index) {
    if (index >= scene_.cameras.cameras.size())
        return;
    cameraIndex_ = index;
    controller_.setCamera(scene_.cameras.cameras[index].camera);
    ++cameraVersion_; // a jump, not a drag: the next frame renders at full resolution
}

void Viewer::applyKeys(const WindowEvents& events) {
    for (size_t i = 0; i < events.keysPressed.size(); ++i) {
        const int key = events.keysPressed[i];
        if (key == GLFW_KEY_ESCAPE)
            window_.requestClose();
        if (overlay_.wantsKeyboard()) // typing into an overlay field
            continue;
        if (key == GLFW_KEY_F12 || key == GLFW_KEY_P)
            screenshotRequested_ = true;
        else if (key == GLFW_KEY_SPACE)
            paused_ = !paused_;
        else if (key == GLFW_KEY_R)
            selectCamera(cameraIndex_);
        else if (key == GLFW_KEY_H)
            overlayVisible_ = !overlayVisible_;
        else if (key == GLFW_KEY_T)
            clock_.toggle();
        else if (key == GLFW_KEY_C)
            selectCamera((cameraIndex_ + 1) % scene_.cameras.cameras.size());
        else if (key >= GLFW_KEY_1 && key <= GLFW_KEY_9)
            selectCamera(static_cast<uint32_t>(key - GLFW_KEY_1));
    }
}

void Viewer::applyOverlay(const OverlayActions& actions) {
    if (actions.renderChanged) {
        try {
            rebuildTargets();
        } catch (const UsageError& error) {
            // A switch this scene refuses (an integrator with an orthographic camera): say so
            // and keep the path tracer.
            std::fprintf(stderr, "wavefront: %s; back to --integrator path\n", error.what());
            settings_.render.integrator = Integrator::Path;
            rebuildTargets();
        }
    }
    if (actions.targetChanged)
        targets_.setTargetSeconds(settings_.targetMs / 1000.0);
    if (actions.selectCamera >= 0)
        selectCamera(static_cast<uint32_t>(actions.selectCamera));
    if (actions.resetView)
        selectCamera(cameraIndex_);
    if (actions.restart)
        targets_.full().renderer->reset();
    if (actions.variantChanged)
        switchVariant(actions.variant);
    screenshotRequested_ |= actions.screenshot;
    paused_ ^= actions.togglePause;
    if (actions.animation.togglePlay)
        clock_.toggle();
    if (actions.animation.seek)
        poseChanged_ |= clock_.seek(actions.animation.seekTime);
}

// The scene at the clock's time: loaded and posed again, its tree refit, its tables under the
// renderers' pipelines (render_targets.h); accumulation restarts.
void Viewer::repose() {
    targets_.setScene(poses_.prepare(loadPosedScene(options_, clock_.time())));
    poseChanged_ = false;
    ++posesShown_;
}

// Another KHR_materials_variants variant: the file read again with it (only materials change,
// so the view stays); a variant the file cannot give (a bad mapping) is refused on stderr and
// the shown one kept.
void Viewer::switchVariant(int variant) {
    const std::string previous = options_.variant;
    // By name where that name is its own (names are matched before indices), else by index.
    const std::vector<std::string>& names = scene_.variantNames;
    options_.variant = variant < 0 ? std::string() : std::to_string(variant);
    if (variant >= 0 && !names[variant].empty() &&
        std::find(names.begin(), names.end(), names[variant]) - names.begin() == variant)
        options_.variant = names[variant];
    try {
        targets_.setScene(poses_.prepare(loadPosedScene(options_, clock_.time())));
        scene_.variant = variant;
    } catch (const InputError& e) {
        options_.variant = previous;
        std::fprintf(stderr, "wavefront: %s\n", e.what());
    }
}

RenderTarget& Viewer::chooseTarget(bool forScreenshot) {
    // Playback shows each pose briefly: the preview while a full sample is over the target.
    const bool moving = secondsSince(lastMove_) < kPreviewHoldSeconds || clock_.playing();
    const uint32_t divisor = moving && !forScreenshot ? targets_.movingDivisor() : 1;
    RenderTarget& target = divisor > 1 ? targets_.preview(divisor) : targets_.full();
    RenderTargets::follow(target, controller_.camera(), cameraVersion_);
    return target;
}

OverlayFacts Viewer::facts() const {
    OverlayFacts facts;
    facts.scene = options_.scenePath;
    facts.device = context_.deviceName();
    facts.width = presenter_.extent().width;
    facts.height = presenter_.extent().height;
    facts.spp = shownSpp_;
    facts.samplesThisFrame = shownSamples_;
    facts.previewDivisor = shownDivisor_;
    facts.guideStatus = guide_.status();
    facts.frameMs = frameMs_;
    facts.stats = &shownStats_;
    facts.paused = paused_;
    for (const NamedCamera& camera : scene_.cameras.cameras)
        facts.cameraNames.push_back(camera.name);
    facts.camera = cameraIndex_;
    facts.variantNames = scene_.variantNames;
    facts.variant = scene_.variant;
    facts.animation = {clock_.animated(), clock_.playing(), clock_.time(), clock_.end(),
                       clock_.frame(), clock_.fps()};
    return facts;
}

bool Viewer::present(RenderTarget& target, bool keepPixels) {
    return presenter_.presentFrame(
        [&](VkCommandBuffer cmd) {
            target.display->record(cmd, settings_.exposure, settings_.tonemap);
        },
        [&](VkCommandBuffer cmd) { overlay_.record(cmd); }, keepPixels);
}

void Viewer::saveScreenshot(const std::string& exrPath) {
    WavefrontRenderer& renderer = *targets_.full().renderer;
    ScreenshotData data;
    data.scenePath = options_.scenePath;
    data.width = presenter_.extent().width;
    data.height = presenter_.extent().height;
    data.radiance = renderer.readImage();
    data.stats = &renderer.stats();
    data.seed = settings_.render.seed;
    data.maxDepth = settings_.render.maxDepth;
    data.shownWidth = presenter_.extent().width;
    data.shownHeight = presenter_.extent().height;
    data.shownRgba = presenter_.shownPixels();
    const std::string png = writeScreenshot(exrPath, data);
    if (!options_.quiet)
        std::fprintf(stderr, "wavefront: wrote %s (%u spp) and %s\n", exrPath.c_str(),
                     renderer.samplesDone(), png.c_str());
}

// At quit: shows the full-resolution image once more, reading it back, and saves it.
void Viewer::captureScreenshot(const std::string& exrPath) {
    RenderTarget& target = chooseTarget(true);
    target.renderer->finishSample();
    if (target.renderer->samplesDone() == 0)
        target.renderer->renderSamples(1);
    for (int attempt = 0; attempt < 2; ++attempt) {
        overlay_.newFrame();
        overlay_.build(facts(), settings_, overlayVisible_);
        if (present(target, true))
            return saveScreenshot(exrPath);
        if (!fitWindow(true))
            break;
    }
    throw InternalError("cannot show the frame for the screenshot " + exrPath +
                        ": the window is minimised or its surface keeps changing");
}

int Viewer::run() {
    const Clock::time_point start = Clock::now();
    Clock::time_point last = start;
    uint32_t frame = 0;
    while (!quitSignalled && !window_.shouldClose()) {
        const bool automated = options_.frames > 0 || options_.orbitDegrees != 0.0f;
        if (!automated && !screenshotRequested_ && !refining() && !clock_.playing())
            window_.waitEvents(0.1); // nothing to refine: sleep until input
        else
            window_.pollEvents();
        if (quitSignalled || window_.shouldClose())
            break;
        if (!fitWindow(false)) {
            window_.waitEvents(0.1);
            continue;
        }
        const double seconds = secondsSince(last);
        last = Clock::now();

        overlay_.newFrame();
        const WindowEvents events = window_.takeEvents();
        applyKeys(events);
        bool moved = input_.moveCamera(controller_, events, static_cast<float>(seconds));
        if (options_.orbitDegrees != 0.0f) {
            controller_.orbit(options_.orbitDegrees * 3.14159265f / 180.0f, 0.0f);
            moved = true;
        }
        if (moved)
            cameraMoved();
        applyOverlay(overlay_.build(facts(), settings_, overlayVisible_));
        poseChanged_ |= clock_.advance(seconds);
        if (poseChanged_)
            repose();

        const bool screenshot = screenshotRequested_;
        RenderTarget& target = chooseTarget(screenshot);
        if (screenshot)
            target.renderer->finishSample(); // the EXR holds whole samples only
        // Paused or at the limit, a moved camera still gets one sample to show.
        uint32_t samples = 0;
        if (refining() || target.renderer->samplesDone() == 0)
            samples = targets_.render(
                target, target.divisor == 1 ? guide_.frameSppLimit(target.renderer.get(),
                                                                   settings_.effectiveSppLimit())
                                            : 0);
        if (target.divisor == 1) {
            fullSamples_ += samples;
            guide_.afterSamples(target.renderer.get(), settings_.effectiveSppLimit());
            if (samples > 0 && !refining() && !options_.quiet)
                std::fprintf(stderr, "wavefront: refined to %u spp at %ux%u\n",
                             targets_.fullSpp(), presenter_.extent().width,
                             presenter_.extent().height);
        } else {
            ++previewFrames_;
        }
        shownStats_ = target.renderer->stats();
        shownSpp_ = target.renderer->samplesDone();
        shownSamples_ = samples;
        shownDivisor_ = target.divisor;

        if (!present(target, screenshot)) {
            fitWindow(true);
            continue;
        }
        if (screenshot) {
            screenshotRequested_ = false;
            saveScreenshot(nextScreenshotPath(
                std::filesystem::path(options_.scenePath).stem().string()));
        }
        frameMs_ = 1000.0 * secondsSince(last);
        if (++frame == 1 && !options_.quiet)
            std::fprintf(stderr, "wavefront: viewing %s at %ux%u on %s (H: overlay, Esc: quit)\n",
                         options_.scenePath.c_str(), presenter_.extent().width,
                         presenter_.extent().height, context_.deviceName().c_str());
        if (options_.resizeAt && frame == options_.resizeAt->frame) {
            resizePending_ = true;
            window_.setSize(options_.resizeAt->width, options_.resizeAt->height);
        }
        if (options_.frames > 0 && frame >= options_.frames)
            break;
        // --until-done: the image at its limit, after any --resize-at has reached the window
        // (the window system applies it some frames later), whatever the frames took.
        const bool resizeAhead =
            resizePending_ || (options_.resizeAt && frame < options_.resizeAt->frame);
        if (options_.untilDone && !refining() && !resizeAhead)
            break;
    }
    const double wall = secondsSince(start);
    if (!options_.screenshot.empty())
        captureScreenshot(options_.screenshot);
    if (!options_.quiet && targets_.full().renderer && targets_.full().renderer->guide())
        std::fprintf(stderr, "wavefront: %s\n", guide_.status().c_str());
    if (!options_.quiet)
        std::fprintf(stderr,
                     "wavefront: %u frames (%u previews) in %.2f s (%.1f ms/frame); %u spp at "
                     "%ux%u, %.2f spp/s at full resolution\n",
                     frame, previewFrames_, wall, frame ? 1000.0 * wall / frame : 0.0,
                     targets_.fullSpp(),
                     presenter_.extent().width, presenter_.extent().height,
                     wall > 0.0 ? fullSamples_ / wall : 0.0);
    if (!options_.quiet && posesShown_ > 0)
        std::fprintf(stderr, "wavefront: %u poses of the animation shown, the last at t = %.4g s\n",
                     posesShown_, clock_.time());
    if (context_.validationMessageCount() > 0) {
        std::fprintf(stderr, "wavefront: %u validation message(s)\n",
                     context_.validationMessageCount());
        return 1;
    }
    return 0;
}

} // namespace

int runViewer(const ViewerOptions& options) {
    quitSignalled = 0;
    struct sigaction action {};
    action.sa_handler = onQuitSignal;
    action.sa_flags = SA_RESETHAND;
    struct sigaction oldInt {}, oldTerm {};
    sigaction(SIGINT, &action, &oldInt);
    sigaction(SIGTERM, &action, &oldTerm);
    int code;
    try {
        Viewer viewer(options);
        code = viewer.run();
    } catch (...) {
        sigaction(SIGINT, &oldInt, nullptr);
        sigaction(SIGTERM, &oldTerm, nullptr);
        throw;
    }
    sigaction(SIGINT, &oldInt, nullptr);
    sigaction(SIGTERM, &oldTerm, nullptr);
    return code;
}

} // namespace wf
