// The viewer's path guide (--guiding on, auto's choice, or the overlay's switch): the guide
// trains while the image refines. The accumulation restarts after 1, 2, 4, ... spp, each time
// with the guide improved by those samples (guiding_schedule.h: progressiveTrainingEnd), and
// after kIterations (or earlier, where guiding::UnusedGuideStop says the guide does not pay)
// the guide freezes and the image keeps refining. Sample indices keep
// counting across the restarts, so the shown image's samples never trained the guide it
// samples. A moved camera restarts the image but keeps what the guide learnt (it is a
// world-space radiance estimate, valid from any viewpoint).
#pragma once
#include <cstdint>
#include <string>

#include "render/guiding/guiding_schedule.h"

namespace wf {

class WavefrontRenderer;
struct PreparedScene;
struct RenderSettings;

class ViewerGuide {
public:
    static constexpr uint32_t kIterations = 8; // 1 + 2 + ... + 128 = 255 spp of training

    // --guiding auto: decides render.guiding for the viewer's scene (guiding_schedule.h's rule,
    // with no end to the samples); off and on are kept.
    static void resolve(RenderSettings& render, const PreparedScene& scene);
    // A new full-resolution renderer (the viewer rebuilt its targets): training starts afresh
    // where it guides; nothing happens where it does not.
    void attach(WavefrontRenderer* renderer);
    // After a frame's samples on `renderer`, the full-resolution one (a renderer other than the
    // attached one, made since, is attached first): ends the training iteration once it holds
    // its samples (whole samples only), rebuilding the guide and restarting the image. At the
    // viewer's --spp limit (sppLimit > 0; it counts training samples too) the image is kept.
    void afterSamples(WavefrontRenderer* renderer, uint32_t sppLimit);
    // The samples per pixel `renderer`'s next frame must not pass: the viewer's limit
    // (`sppLimit`, 0: none) and, while training, the end of the training iteration, so that
    // every iteration holds exactly its samples however many a frame's budget allows.
    uint32_t frameSppLimit(const WavefrontRenderer* renderer, uint32_t sppLimit) const;
    std::string status() const; // one line for the overlay

private:
    WavefrontRenderer* attached_ = nullptr; // the renderer attach() saw, guided or not
    WavefrontRenderer* renderer_ = nullptr; // it, where it guides
    uint32_t iteration_ = 0;
    uint32_t start_ = 0;         // samplesDone() when this iteration's image began
    uint32_t trainedSpp_ = 0;
    guiding::UnusedGuideStop unused_;
};

} // namespace wf
