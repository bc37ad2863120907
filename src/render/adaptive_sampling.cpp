#include "render/adaptive_sampling.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>

#include "errors.h"
#include "image/error_metrics.h"
#include "render/film_error.h"
#include "render/guiding/guiding_schedule.h"
#include "render/guiding/path_guide.h"

namespace wf {

uint32_t pilotSeedFor(uint32_t seed) {
    // The top bit keeps it off every seed below 2^31; the odd multiplier keeps seeds apart.
    return (seed * 0x9E3779B1u) | 0x80000000u;
}

namespace {

// The seed of image round r (1-based): round 1 uses the render's own seed, later rounds
// streams of their own, apart from the pilot's.
uint32_t roundSeed(uint32_t seed, uint32_t round) {
    return round == 1 ? seed : pilotSeedFor(seed + 0x68E31DA4u * round) ^ 0x40000000u;
}

// The evidence of several independent renders of the same pixels: their moments summed (each
// replicate's too: replicate r of two renders with seeds of their own is still independent of
// replicate r' of both).
void addMoments(FilmMoments& into, const FilmMoments& more) {
    for (size_t i = 0; i < into.replicateSums.size() && i < more.replicateSums.size(); ++i)
        into.replicateSums[i] += more.replicateSums[i];
    for (size_t i = 0; i < into.sum.size(); ++i) {
        into.sum[i] += more.sum[i];
        into.squares[i] += more.squares[i];
    }
    for (size_t i = 0; i < into.count.size(); ++i) {
        into.count[i] += more.count[i];
        into.largest[i] = std::max(into.largest[i], more.largest[i]);
    }
}

// How far the allocation's prediction (from independent samples' variance) overstates the
// error of this renderer's samples: the evidence's calibrated estimate over its
// independent-sample one, where replicates measure it to within kReliableRelativeError (the
// verdict's other tests do not matter to a ratio of two estimates from the same samples); 1
// otherwise (a prediction that errs towards more samples). Low-discrepancy samples gain more
// at higher counts, so the gain at the evidence's count still errs that way.
// `calibrated` is the film's own estimate (estimateFilmError).
double calibrationGain(const FilmMoments& film, const ErrorEstimate& calibrated) {
    if (calibrated.replicates <= 1)
        return 1.0;
    const ErrorEstimate independent = estimateIndependentFilmError(film);
    if (!(calibrated.relMse > 0.0) || !(independent.relMse > 0.0) ||
        calibrated.standardError > kReliableRelativeError * calibrated.relMse)
        return 1.0;
    return std::clamp(calibrated.relMse / independent.relMse, 1e-3, 1.0);
}

// What an allocation aims at for a target: below it by the claim's margin, with the relative
// standard error the evidence's estimate had (about what the image's will have: it depends on
// how many pixels carry the error, not on their counts), and a tenth to spare.
double aimFor(double target, const ErrorEstimate& e) {
    const double relative = e.relMse > 0.0
                                ? std::min(e.standardError / e.relMse, kReliableRelativeError)
                                : kReliableRelativeError;
    return 0.9 * target / (1.0 + kClaimStandardErrors * relative);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The guide of a guided adaptive render (docs/guiding.md, "--target-error"). It trains over
// the whole image with the pilot's seed, so that no sample it learnt from is in the image:
// iterations of 1, 2, 4, ... spp, each sampling the guide the one before it built, until one
// has at least the pilot's spp; that last iteration's image is the pilot (its samples measure
// a guide one iteration older than the frozen one, so the allocation errs towards more
// samples). Before each image round it trains on while its samples stay within that round's
// mean spp (the image at least half of the total, as in a guided render), within half of
// maxSpp and within the time limit, so the guide keeps up with the rounds' doubling, unless
// the learnt shares stopped it (guiding::UnusedGuideStop; the pilot's iterations run
// regardless). Every round samples the guide as frozen then; each round's samples are
// independent of it.
class AdaptiveGuide {
public:
    AdaptiveGuide(WavefrontRenderer& renderer, const std::vector<uint32_t>& everyPixel,
                  uint32_t pilotSeed, const std::function<void(const AdaptiveProgress&)>& onRound)
        : renderer_(renderer), everyPixel_(everyPixel), pilotSeed_(pilotSeed), onRound_(onRound),
          tree_(renderer.guide()->tree()) {}

    // The pilot: iterations up to one of at least `pilotSpp` samples (the renderer restarted
    // with the pilot's seed). Returns the last one's spp; `evidence` gets its moments.
    uint32_t trainPilot(uint32_t pilotSpp, FilmMoments& evidence) {
        uint32_t spp = 0;
        do {
            spp = nextSpp_;
            evidence = runIteration(0.0);
        } while (spp < pilotSpp);
        return spp;
    }

    // Before an image round of mean `meanSpp`: more iterations while the rule above allows,
    // their statistics added to `total`. `overTime(seconds)`: the limit would be passed.
    void trainUpTo(double meanSpp, uint32_t maxSpp, const std::function<bool(double)>& overTime,
                   RenderStats& total) {
        bool restarted = false;
        for (;;) {
            const uint64_t after = uint64_t(trained_) + nextSpp_;
            const double pace = total.seconds / std::max<double>(total.paths, 1);
            if (unused_.stopped() || double(after) > meanSpp || 2 * after > maxSpp ||
                overTime(double(nextSpp_) * renderer_.pixelCount() * pace))
                return;
            if (!restarted) { // the pilot's stream again, its sample indices continuing
                renderer_.restart(pilotSeed_, 0);
                renderer_.guide()->setTree(tree_);
                restarted = true;
            }
            runIteration(total.seconds);
            const RenderStats& more = renderer_.stats();
            addRenderStats(total, more);
            total.guideIterations.push_back(more.guideIterations.back());
            renderer_.reset();
        }
    }

    bool stoppedUnused() const { return unused_.stopped(); }

    // After the renderer restarted for an image round: sample the frozen guide.
    void freeze() {
        renderer_.guide()->setTree(tree_);
        if (unused_.stopped())
            renderer_.guide()->sampleBsdfAlone(); // and no vertex walks to its leaf
    }

private:
    // secondsBefore: the render's seconds before the renderer's own (progress lines).
    FilmMoments runIteration(double secondsBefore) {
        PathGuide& guide = *renderer_.guide();
        guide.setTraining(true);
        renderer_.clearImage();
        const auto start = std::chrono::steady_clock::now();
        renderer_.renderPixelList(everyPixel_, trained_, nextSpp_);
        const double seconds = secondsSince(start);
        FilmMoments moments = renderer_.readMoments();
        unused_.endIteration(
            renderer_.endGuideIteration(iteration_, nextSpp_, seconds).payingLeaves > 0,
            uint64_t(everyPixel_.size()) * nextSpp_);
        guide.setTraining(false);
        tree_ = guide.tree();
        if (unused_.stopped())
            tree_.setBsdfFractions(1.0f); // the rounds sample the BSDF alone
        trained_ += nextSpp_;
        if (onRound_)
            onRound_({"training", 1, iteration_ + 1, 0, renderer_.pixelCount(), nextSpp_,
                      secondsBefore + renderer_.stats().seconds, 0.0});
        ++iteration_;
        nextSpp_ *= 2;
        return moments;
    }

    WavefrontRenderer& renderer_;
    const std::vector<uint32_t>& everyPixel_;
    uint32_t pilotSeed_;
    const std::function<void(const AdaptiveProgress&)>& onRound_;
    guiding::SDTree tree_;
    guiding::UnusedGuideStop unused_; // the pilot's iterations count, but always run
    uint32_t trained_ = 0;  // samples per pixel so far, all with the pilot's seed
    uint32_t nextSpp_ = 1;
    uint32_t iteration_ = 0;
};

} // namespace

AdaptiveResult renderAdaptive(WavefrontRenderer& renderer, uint32_t seed,
                              const AdaptiveSettings& requested, uint32_t width, uint32_t height,
                              const std::function<void(const AdaptiveProgress&)>& onRound) {
    // Base-2 sequences take their counts at powers of two, where their prefixes are nets.
    AdaptiveSettings settings = requested;
    const SamplerKind sampler = renderer.variant().sampler;
    settings.powerOfTwoLevels = settings.powerOfTwoLevels || sampler == SamplerKind::Sobol ||
                                sampler == SamplerKind::BlueNoise;
    if (size_t(width) * height != renderer.pixelCount())
        throw InternalError("renderAdaptive: image size differs from the renderer's");
    const auto start = std::chrono::steady_clock::now();
    const bool target = settings.targetError > 0.0;
    AdaptiveResult result;
    result.pilotSpp = settings.pilotSpp ? settings.pilotSpp : pilotSppFor(settings.maxSpp);
    std::vector<uint32_t> everyPixel(renderer.pixelCount());
    std::iota(everyPixel.begin(), everyPixel.end(), 0u);
    auto addStats = [&](bool first) {
        if (first)
            result.stats = renderer.stats();
        else
            addRenderStats(result.stats, renderer.stats());
    };
    auto overTime = [&](double more) {
        return settings.timeLimitSeconds > 0.0 &&
               secondsSince(start) + more > settings.timeLimitSeconds;
    };

    renderer.restart(pilotSeedFor(seed), 0);
    FilmMoments evidence;
    std::optional<ErrorEstimate> halfPilot; // the estimate after half the pilot's samples
    std::optional<AdaptiveGuide> guide;
    if (renderer.guide()) {
        guide.emplace(renderer, everyPixel, pilotSeedFor(seed), onRound);
        result.pilotSpp = guide->trainPilot(result.pilotSpp, evidence);
        addStats(true);
    } else {
        // In two halves: the estimate at each tells how fast this sampler's error falls.
        const uint32_t half = result.pilotSpp / 2;
        if (half >= 2 && renderer.variant().errorReplicates > 1) {
            renderer.renderPixelList(everyPixel, 0, half);
            halfPilot = estimateFilmError(renderer.readMoments(), sampler);
        }
        renderer.renderPixelList(everyPixel, halfPilot ? half : 0,
                                 halfPilot ? result.pilotSpp - half : result.pilotSpp);
        addStats(true);
        if (onRound)
            onRound({"pilot", 1, 1, 1, renderer.pixelCount(), result.pilotSpp,
                     result.stats.seconds, 0.0});
        evidence = renderer.readMoments();
    }
    // The gain the plan assumes at a mean count n: gainBase (n / gainBaseSpp)^-(slope - 1),
    // from the pilot's gain and, where its halves measured it, how much faster than 1/n the
    // calibrated error fell between them, at most n^-1.5: the rate of scrambled nets on 2D
    // integrands with discontinuities (Owen 1997), which a pixel's are. Smooth pixels fall
    // faster at first (the tiny light's pilot: 4.8x from 8 to 16 spp), but its gain over
    // independent samples went from 0.04 at 16 spp to 0.015 at 128, as n^-1.5 says. Later rounds
    // take the last reliable image's gain at its own mean.
    ErrorEstimate evidenceEstimate = estimateFilmError(evidence, sampler); // once a round
    double slope = 1.0;
    if (halfPilot) {
        const ErrorEstimate& whole = evidenceEstimate;
        const double precise = kReliableRelativeError;
        if (halfPilot->relMse > 0.0 && whole.relMse > 0.0 &&
            halfPilot->standardError <= precise * halfPilot->relMse &&
            whole.standardError <= precise * whole.relMse)
            slope = std::clamp(std::log(halfPilot->relMse / whole.relMse) /
                                   std::log(double(result.pilotSpp) / (result.pilotSpp / 2)),
                               1.0, 1.5);
    }
    result.errorSlope = slope;
    double gainBase = calibrationGain(evidence, evidenceEstimate);
    double gainBaseSpp = result.pilotSpp;
    auto gainAt = [&](double meanSpp) {
        return std::clamp(gainBase * std::pow(std::max(meanSpp, 1.0) / gainBaseSpp, 1.0 - slope),
                          1e-4, 1.0);
    };
    double previousMean = 0.0;
    // The gain the last image had at its own counts (0 until an image was reliable).
    double measuredGain = 0.0;
    for (uint32_t round = 1;; ++round) {
        const std::vector<double> relVariance = relativeSampleVariance(evidence);
        const std::vector<double> shape = defensiveShape(relVariance, width, height);
        // The plan's target in the prediction's own terms (independent samples' error). A
        // low-discrepancy sequence gains unevenly with the count (most at powers of two), so
        // the gain an image had at its own counts is the better guide once there is one.
        AdaptiveSettings planned = settings;
        if (measuredGain > 0.0) {
            gainBase = measuredGain;
            gainBaseSpp = previousMean;
        }
        double gain = gainAt(gainBaseSpp);
        SampleAllocation allocation;
        // The gain depends on the count the plan picks: a few fixed-point steps settle it.
        const double aim = target ? aimFor(settings.targetError, evidenceEstimate) : 0.0;
        for (int step = 0; step < (target ? 4 : 1); ++step) {
            if (target)
                planned.targetError = aim / gain;
            allocation = allocateSamples(relVariance, shape, planned);
            if (target)
                gain = gainAt(allocation.meanSpp);
        }
        gain = gainAt(allocation.meanSpp);
        allocation.predictedRelMse *= gain;
        // A later round exists because the last image missed the target. Where it was not
        // evidence enough (its estimate unreliable) the next at least doubles the samples, so
        // that rounds end and rare paths get their chance; where it was, and only fell short,
        // its own error plans the next, with at least a level's more samples (1.25x).
        const double growth = measuredGain > 0.0 ? 1.25 : 2.0;
        if (round > 1 && allocation.meanSpp < growth * previousMean) {
            AdaptiveSettings doubled = settings;
            doubled.targetError = 0.0;
            doubled.meanSpp = growth * previousMean;
            const bool reachable = allocation.targetMet;
            allocation = allocateSamples(relVariance, shape, doubled);
            allocation.predictedRelMse *= gain;
            allocation.targetMet = reachable;
        }
        const uint32_t most = *std::max_element(allocation.spp.begin(), allocation.spp.end());
        const auto levels = static_cast<uint32_t>(
            std::find(allocation.levels.begin(), allocation.levels.end(), most) -
            allocation.levels.begin() + 1);
        // A round after the first starts only if the pace so far says it ends in time.
        const double secondsPerPath =
            result.stats.seconds / std::max<double>(result.stats.paths, 1);
        if (round > 1 &&
            overTime(allocation.meanSpp * renderer.pixelCount() * secondsPerPath)) {
            result.stoppedBy = "time-limit";
            break;
        }

        if (guide)
            guide->trainUpTo(allocation.meanSpp, settings.maxSpp, overTime, result.stats);
        renderer.restart(roundSeed(seed, round), 0);
        if (guide)
            guide->freeze();
        uint32_t previous = 0;
        bool cut = false;
        for (uint32_t k = 0; k < levels; ++k) {
            const uint32_t level = allocation.levels[k];
            std::vector<uint32_t> active;
            for (uint32_t i = 0; i < renderer.pixelCount(); ++i)
                if (allocation.spp[i] >= level)
                    active.push_back(i);
            // Whole levels only, while the pace so far says they end in time (the first level
            // always runs, as a time-limited render's first pass does).
            const double pace = (result.stats.seconds + renderer.stats().seconds) /
                                std::max<double>(result.stats.paths + renderer.stats().paths, 1);
            if (k > 0 && overTime(double(active.size()) * (level - previous) * pace)) {
                cut = true;
                break;
            }
            renderer.renderPixelList(active, previous, level - previous);
            previous = level;
            if (onRound)
                onRound({"render", round, k + 1, levels, uint32_t(active.size()), level,
                         result.stats.seconds + renderer.stats().seconds,
                         allocation.predictedRelMse});
        }
        addStats(false);
        const FilmMoments film = renderer.readMoments();
        result.allocation = std::move(allocation);
        result.imageRounds = round;
        result.estimate = estimateFilmError(film, sampler);
        result.rgb = renderer.readImage();
        result.sampleCounts = film.count;
        result.meanSpp = 0.0;
        for (float n : film.count)
            result.meanSpp += n;
        result.meanSpp /= std::max<size_t>(film.count.size(), 1);
        if (guide) {
            result.stats.guideFinalSamples = static_cast<uint32_t>(std::lround(result.meanSpp));
            result.stats.guideBytes = renderer.guide()->deviceBytes();
            result.stats.guideStoppedUnused = guide->stoppedUnused();
        }
        result.plannedGain = gain;
        if (round == 1)
            result.firstImageReliable = result.estimate.reliable;
        result.targetMet = target && result.estimate.reliable &&
                           result.estimate.relMse +
                                   kClaimStandardErrors * result.estimate.standardError <=
                               settings.targetError;
        if (!target) {
            result.stoppedBy = "budget";
            break;
        }
        // The gain the image's own counts had: its calibrated estimate over its
        // independent-sample one, from the same samples (the pilot's prediction may have missed
        // rare light that the image found; the evidence the next plan reads now holds it).
        measuredGain = result.estimate.reliable && result.estimate.replicates > 1
                           ? calibrationGain(film, result.estimate)
                           : 0.0;
        if (result.targetMet) {
            result.stoppedBy = "target";
            break;
        }
        if (cut) {
            result.stoppedBy = "time-limit";
            break;
        }
        // No round can add samples once every pixel had the cap.
        if (result.allocation.levels.front() == settings.maxSpp ||
            std::all_of(result.allocation.spp.begin(), result.allocation.spp.end(),
                        [&](uint32_t n) { return n == settings.maxSpp; })) {
            result.stoppedBy = "spp";
            break;
        }
        if (round == settings.maxRounds) {
            result.stoppedBy = "rounds";
            break;
        }
        previousMean = result.meanSpp;
        addMoments(evidence, film); // independent of the next round's samples
        evidenceEstimate = estimateFilmError(evidence, sampler);
    }
    return result;
}

} // namespace wf
