// WavefrontRenderer's guided renders (declared in wavefront_renderer.h; the schedule itself is
// render/guiding/guiding_schedule.h's): training iterations of 1, 2, 4, ... spp, each
// rebuilding the guide from its splats, then the image from the rest of the budget, the
// iterations' images weighed by their samples where the film keeps second moments. Host work
// between iterations counts in the render's time as the pass "guide (host)".
#include "render/wavefront_renderer.h"

#include <chrono>

#include "errors.h"
#include "render/guiding/guide_combination.h"
#include "render/guiding/guiding_schedule.h"
#include "render/guiding/path_guide.h"
#include "render/path_buffers.h"

namespace wf {

void WavefrontRenderer::renderGuided(uint32_t budget,
                                     const std::function<void(const WaveProgress&)>& onWave,
                                     const std::atomic<bool>* stop) {
    if (!guide_)
        throw InternalError("renderGuided: the renderer was made without guiding");
    // Which iterations, how many spp each, and the image passes within --time-limit.
    guiding::GuideSchedule schedule(budget, settings_.timeLimitSeconds,
                                    settings_.guideMaxIterations);
    const auto begin = std::chrono::steady_clock::now();
    auto elapsed = [&]() {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    };
    const bool combine = settings_.guideCombineIterations && pathBuffers_->momentFilm;
    guiding::ImageCombiner combiner(pixelCount_);
    guide_->setTraining(true);
    for (uint32_t iteration = 0; !(stop && stop->load()); ++iteration) {
        const uint32_t spp = schedule.nextTrainingSpp(samplesDone_, elapsed());
        if (spp == 0)
            break;
        clearFilm();
        const auto start = std::chrono::steady_clock::now();
        renderSamples(spp);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto host = std::chrono::steady_clock::now();
        if (combine)
            combiner.add(readMoments(), spp);
        countGuideHostTime(host);
        schedule.endIteration(endGuideIteration(iteration, spp, seconds).payingLeaves > 0,
                              uint64_t(pixelCount_) * spp);
        if (onWave)
            onWave({samplesDone_, budget, stats_.seconds});
    }
    guide_->setTraining(false);
    stats_.guideStoppedUnused = schedule.stoppedUnused();
    if (stats_.guideStoppedUnused)
        guide_->sampleBsdfAlone(); // leaves whose share did not pay may still be below 1
    if (stop && stop->load())
        return; // the film keeps the last iteration's image, for a checkpoint
    clearFilm();
    const uint32_t first = samplesDone_;
    while (samplesDone_ < budget && !(stop && stop->load())) {
        const uint32_t samples = schedule.nextImageSpp(samplesDone_, elapsed());
        if (samples == 0)
            break;
        advance(samples);
        if (onWave)
            onWave({samplesDone_, budget, stats_.seconds});
    }
    stats_.guideFinalSamples = samplesDone_ - first;
    stats_.guideBytes = guide_->deviceBytes();
    if (!combine || combiner.iterations() == 0 || samplesDone_ == first)
        return;
    const auto host = std::chrono::steady_clock::now();
    combiner.add(readMoments(), samplesDone_ - first);
    const guiding::CombinedImage image = combiner.combine();
    if (!image.film.empty()) {
        pathBuffers_->film.upload(image.film);
        pathBuffers_->momentFilm.upload(image.moments);
        stats_.guideFinalSamples = image.samplesPerPixel;
        stats_.guideWeights = image.weights;
    }
    countGuideHostTime(host);
}

const RenderStats::GuideIterationStats&
WavefrontRenderer::endGuideIteration(uint32_t iteration, uint32_t spp, double seconds) {
    if (!guide_)
        throw InternalError("endGuideIteration: the renderer was made without guiding");
    const auto host = std::chrono::steady_clock::now();
    RenderStats::GuideIterationStats it;
    it.samplesPerPixel = spp;
    it.seconds = seconds;
    it.rebuildSeconds = guide_->endIteration(iteration);
    const guiding::SDTreeStats tree = guide_->tree().stats(settings_.guideBsdfFraction);
    it.spatialLeaves = tree.spatialLeaves;
    it.directionalNodes = tree.samplingNodes;
    it.meanBsdfFraction = tree.meanBsdfFraction;
    it.guidedLeaves = tree.guidedLeaves;
    // A fixed share (learning off) learns nothing that says it does not pay.
    it.payingLeaves = settings_.guideLearnFraction ? tree.payingLeaves : tree.guidedLeaves;
    stats_.guideIterations.push_back(it);
    countGuideHostTime(host);
    return stats_.guideIterations.back();
}

// Host work between training iterations (tree rebuilds, reading films back, the combination)
// counts in the render's time, as a pass of its own.
void WavefrontRenderer::countGuideHostTime(std::chrono::steady_clock::time_point start) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats_.seconds += seconds;
    stats_.passMilliseconds["guide (host)"] += 1000.0 * seconds;
}

} // namespace wf
