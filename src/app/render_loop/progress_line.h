// The render's progress line on stderr: spp done, elapsed and ETA (or the adaptive rounds),
// redrawn in place on a terminal and at most once a second in a log.
#pragma once
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>

#include "image/error_estimate.h"
#include "render/adaptive_sampling.h"
#include "render/wavefront_renderer.h"

namespace wf {

class ProgressLine {
public:
    ProgressLine(bool enabled, double timeLimit)
        : enabled_(enabled), tty_(isatty(STDERR_FILENO)), timeLimit_(timeLimit) {}
    // The line shows the image's error estimate too, refreshed at most once a second (it reads
    // the film back).
    void showEstimate(std::function<ErrorEstimate()> estimate) { estimate_ = std::move(estimate); }

    void update(const WaveProgress& progress, bool stopped = false) {
        if (!enabled_)
            return;
        const bool last = progress.samplesDone == progress.samplesTotal || stopped;
        // On a terminal redraw one line; in a log, at most a line a second.
        if (!tty_ && !last && progress.secondsElapsed - lastPrinted_ < 1.0)
            return;
        lastPrinted_ = progress.secondsElapsed;
        double eta = progress.secondsElapsed / progress.samplesDone *
                     (progress.samplesTotal - progress.samplesDone);
        if (timeLimit_ > 0.0)
            eta = std::min(eta, std::max(0.0, timeLimit_ - progress.secondsElapsed));
        char limit[64] = "";
        if (timeLimit_ > 0.0)
            std::snprintf(limit, sizeof limit, " of a %g s limit", timeLimit_);
        if (estimate_ && (last || progress.secondsElapsed - lastEstimated_ >= 1.0)) {
            estimateText_ = ", relMSE ~" + describeErrorEstimate(estimate_());
            lastEstimated_ = progress.secondsElapsed;
        }
        std::fprintf(stderr, "%swavefront: %u/%u spp, %.1f s elapsed%s, %s %.1f s%s%s",
                     tty_ ? "\r" : "", progress.samplesDone, progress.samplesTotal,
                     progress.secondsElapsed, limit, stopped ? "stopped at the limit after" : "ETA",
                     stopped ? progress.secondsElapsed : eta, estimateText_.c_str(),
                     tty_ && !last ? "   " : "\n");
        std::fflush(stderr);
    }

    void update(const AdaptiveProgress& round, double target) {
        if (!enabled_)
            return;
        if (round.stage == "training") { // the guide's iterations: one line each
            std::fprintf(stderr, "%swavefront: target relMSE %g: training the guide, iteration "
                                 "%u of %u spp, %.1f s elapsed\n",
                         tty_ ? "\r" : "", target, round.round, round.level, round.seconds);
            std::fflush(stderr);
            return;
        }
        // A later image round may follow; each image's last level ends its line.
        const bool last = round.stage == "render" && round.round == round.rounds;
        if (!tty_ && !last && round.seconds - lastPrinted_ < 1.0 && round.stage != "pilot")
            return;
        lastPrinted_ = round.seconds;
        char predicted[64] = "";
        if (round.predictedRelMse > 0.0)
            std::snprintf(predicted, sizeof predicted, " (predicted %.3g)",
                          round.predictedRelMse);
        char image[32] = "";
        if (round.stage == "render")
            std::snprintf(image, sizeof image, " %u", round.imageRound);
        std::fprintf(stderr, "%swavefront: target relMSE %g%s: %s%s level %u/%u, %u pixels to %u "
                             "spp, %.1f s elapsed%s",
                     tty_ ? "\r" : "", target, predicted, round.stage.c_str(), image,
                     round.round, round.rounds, round.activePixels, round.level, round.seconds,
                     tty_ && !last && round.stage != "pilot" ? "   " : "\n");
        std::fflush(stderr);
    }

private:
    bool enabled_;
    bool tty_;
    double timeLimit_;
    double lastPrinted_ = -1.0;
    std::function<ErrorEstimate()> estimate_;
    std::string estimateText_;
    double lastEstimated_ = -1.0;
};

} // namespace wf
