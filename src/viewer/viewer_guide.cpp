#include "viewer/viewer_guide.h"

#include <algorithm>

#include "render/guiding/guiding_schedule.h"
#include "render/guiding/path_guide.h"
#include "render/render_settings.h"
#include "render/wavefront_renderer.h"

namespace wf {

void ViewerGuide::resolve(RenderSettings& render, const PreparedScene& scene) {
    if (!render.guidingAuto)
        return;
    render.guidingAuto = false;
    render.guiding = guiding::decideGuiding(guiding::GuidingMode::Auto,
                                            guiding::guideSceneTraits(scene), 1u << 16)
                         .on;
}

void ViewerGuide::attach(WavefrontRenderer* renderer) {
    attached_ = renderer;
    renderer_ = renderer && renderer->guide() ? renderer : nullptr;
    iteration_ = 0;
    start_ = 0;
    trainedSpp_ = 0;
    unused_ = {};
    if (renderer_)
        renderer_->guide()->setTraining(true);
}

void ViewerGuide::afterSamples(WavefrontRenderer* renderer, uint32_t sppLimit) {
    if (renderer != attached_)
        attach(renderer);
    if (!renderer_)
        return;
    const uint32_t end = guiding::progressiveTrainingEnd(iteration_, kIterations);
    if (end == 0)
        return; // frozen
    const uint32_t done = renderer_->samplesDone();
    if (done < start_)
        start_ = 0; // the camera moved: a new image, the same guide
    if (renderer_->pixelsOfNextSample() > 0 || done - start_ < end ||
        (sppLimit > 0 && done >= sppLimit))
        return;
    PathGuide& guide = *renderer_->guide();
    guide.endIteration(iteration_);
    unused_.endIteration(guide.tree().stats().payingLeaves > 0, // learnt shares only
                         uint64_t(renderer_->pixelCount()) * (done - start_));
    renderer_->clearImage();
    trainedSpp_ += done - start_;
    start_ = done;
    ++iteration_;
    if (unused_.stopped()) { // the guide does not pay here: frozen, unsampled
        iteration_ = kIterations;
        guide.sampleBsdfAlone();
    }
    if (guiding::progressiveTrainingEnd(iteration_, kIterations) == 0)
        guide.setTraining(false);
}

uint32_t ViewerGuide::frameSppLimit(const WavefrontRenderer* renderer, uint32_t sppLimit) const {
    if (!renderer_ || renderer != renderer_)
        return sppLimit;
    const uint32_t end = guiding::progressiveTrainingEnd(iteration_, kIterations);
    if (end == 0)
        return sppLimit;
    // A moved camera (samplesDone() below start_) began a new image; afterSamples resets start_.
    const uint32_t iterationEnd = (renderer_->samplesDone() < start_ ? 0 : start_) + end;
    return sppLimit == 0 ? iterationEnd : std::min(sppLimit, iterationEnd);
}

std::string ViewerGuide::status() const {
    if (!renderer_)
        return "guide: none (unguided)";
    const uint32_t end = guiding::progressiveTrainingEnd(iteration_, kIterations);
    if (end == 0 && unused_.stopped())
        return "guide: unused (no leaf's share paid) after " +
               std::to_string(trainedSpp_) + " spp of training; the image refines";
    if (end == 0)
        return "guide: frozen after " + std::to_string(trainedSpp_) +
               " spp of training; the image refines";
    return "guide: training, iteration " + std::to_string(iteration_ + 1) + " of " +
           std::to_string(kIterations) + " (the image restarts after " + std::to_string(end) +
           " spp)";
}

} // namespace wf
