// When the path guide trains and when --guiding auto turns it on. Pure decisions, no GPU:
// WavefrontRenderer::renderGuided asks GuideSchedule how many samples per pixel each training
// iteration and each image pass takes (within --spp and --time-limit), the viewer asks
// progressiveTrainingEnd where to restart its accumulation, and the commands ask
// decideGuiding whether `auto` guides a scene. Unit tests: tests/unit/test_guiding_schedule.cpp.
#ifndef WF_RENDER_GUIDING_GUIDING_SCHEDULE_H
#define WF_RENDER_GUIDING_GUIDING_SCHEDULE_H

#include <cstdint>
#include <string>

namespace wf {

struct PreparedScene;

namespace guiding {

// Where the guide does not pay, stop paying for it: training ends after
// kUnusedIterationsToStop iterations in a row in which no spatial leaf learnt a share that
// pays (below 1 and cutting kMinVarianceCut of its paths' variance, SDTree::learnFractions),
// the last of them iteration kFirstUnusedStop or later (1 + 2 + 4 = 7 spp trained) and the
// iterations so far having traced at least kMinStopPixelSamples camera samples, and the rest
// samples the BSDF alone: the image is unguided MIS's. Fewer records do not learn a share
// below 1 even where the guide pays: the narrow gap's first two iterations never do, its
// third does in every seed at 64x64 (7 spp of 4096 pixels) and larger, but at 32x32 only its
// fourth or fifth in most seeds. Measured in docs/guiding.md ("2026-12-04 17:09-18:08:
// training stops where the guide does not pay", "2026-12-04 19:48: training may stop after
// 7 spp; photons tried").
constexpr uint32_t kUnusedIterationsToStop = 2;
constexpr uint32_t kFirstUnusedStop = 2;
constexpr uint64_t kMinStopPixelSamples = 64 * 64 * 7;

class UnusedGuideStop {
public:
    // After each training iteration, in order: whether some leaf learnt a share that pays,
    // and the camera samples the iteration traced (pixels x spp).
    void endIteration(bool guidePays, uint64_t pixelSamples);
    bool stopped() const { return stopped_; }

private:
    uint32_t iterations_ = 0;
    uint32_t unusedStreak_ = 0;
    uint64_t pixelSamples_ = 0;
    bool stopped_ = false;
};

// Iterations of 1, 2, 4, ... spp, the image keeping at least half of the budget: iteration k
// (2^k spp) runs while the samples done after it are at most half of the budget, so the image
// gets the rest. With a time limit the same rule holds in seconds: an iteration runs only
// while the pace so far (seconds per spp, rebuilds included) says training ends within half of
// the limit. The first iteration always runs (as the first pass of an unguided render does),
// so a time limit shorter than one iteration still trains once and renders one image pass.
// Training also ends where UnusedGuideStop says so.
class GuideSchedule {
public:
    // budgetSpp: samples per pixel of this render (or of this --spp-offset part), training
    // included; timeLimitSeconds: 0 for none; maxIterations: tests set 0 (a guide they froze).
    GuideSchedule(uint32_t budgetSpp, double timeLimitSeconds, uint32_t maxIterations);

    // The spp of the next training iteration, or 0: training is over. samplesDone: the
    // render's samples so far (all of them training); seconds: wall time since it began.
    uint32_t nextTrainingSpp(uint32_t samplesDone, double seconds);
    // After each training iteration: whether some spatial leaf learnt a share that pays and
    // the camera samples it traced; see UnusedGuideStop.
    void endIteration(bool guidePays, uint64_t pixelSamples) {
        unused_.endIteration(guidePays, pixelSamples);
    }
    // Whether training ended because the guide learnt that it does not pay.
    bool stoppedUnused() const { return unused_.stopped(); }
    // After training: the spp of the next image pass (at most; a pass may take fewer), or 0 to
    // stop. The first image pass always gets at least one sample; later ones only as many as
    // the image phase's own pace says still fit in the limit.
    uint32_t nextImageSpp(uint32_t samplesDone, double seconds);

    uint32_t iterations() const { return iterations_; }

private:
    uint32_t budget_;
    double limit_;
    uint32_t maxIterations_;
    uint32_t iterations_ = 0;
    uint32_t nextSpp_ = 1;
    UnusedGuideStop unused_;
    // Where the image phase began (samples, seconds); imageStarted_ once nextImageSpp ran.
    bool imageStarted_ = false;
    uint32_t imageFirstSample_ = 0;
    double imageFirstSecond_ = 0.0;
};

// The viewer's schedule: the accumulation restarts after 1, 2, 4, ... spp with the guide
// improved by each, then keeps refining with the guide frozen. Returns the spp at which the
// current training iteration ends (samples counted from its restart), or 0 once iteration
// `iteration` is past the last (maxIterations of them; the viewer trains 1 + ... + 2^(n-1)).
uint32_t progressiveTrainingEnd(uint32_t iteration, uint32_t maxIterations);

// --guiding off|on|auto.
enum class GuidingMode { Off, On, Auto };
GuidingMode parseGuidingMode(const std::string& word); // UsageError on other words

// What `auto` looks at in a scene.
struct GuideSceneTraits {
    bool nonDelta = false; // some material has a non-delta lobe (where the guide samples)
    bool delta = false;    // some material is a smooth mirror or glass only (caustic paths)
    bool emits = false;    // some light, emissive triangle or environment
};
GuideSceneTraits guideSceneTraits(const PreparedScene& scene);

// auto's rule: guide where the predicted efficiency (1 / (relMSE x seconds)) gain is at least
// kAutoMinGain. The prediction is the least gain measured at equal time (training included)
// on the project's scenes of the scene's kind (docs/guiding.md, "auto"): caustic scenes, where
// delta surfaces send light onto non-delta ones, and diffuse or glossy scenes. Scenes without
// a non-delta surface or without light gain nothing.
struct GuidingDecision {
    bool on = false;
    double predictedGain = 0.0;
    std::string reason; // one line, for --verbose
};
constexpr double kAutoMinGain = 1.1;
GuidingDecision decideGuiding(GuidingMode mode, const GuideSceneTraits& traits,
                              uint32_t budgetSpp);

} // namespace guiding
} // namespace wf

#endif
