#include "image/error_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "errors.h"

namespace wf {
namespace {

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f%%", 100.0 * share);
    return text;
}

} // namespace

void judgeErrorEstimate(ErrorEstimate& e) {
    e.reliable = false;
    if (e.pixels < e.pixelsTotal) {
        e.reason = std::to_string(e.pixelsTotal - e.pixels) + " of " +
                   std::to_string(e.pixelsTotal) + " pixels have fewer than 2 samples";
        return;
    }
    if (e.relMse > 0.0 && e.standardError > kReliableRelativeError * e.relMse) {
        e.reason = "its own standard error is " + percent(e.standardError / e.relMse) +
                   " of it: a few bright samples carry it (heavy tails)";
        return;
    }
    if (e.relMse > 0.0 && e.effectivePixels < kReliableEffectivePixels) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "about %.0f pixels carry it: one render's error scatters by about %s "
                      "around it",
                      e.effectivePixels, percent(std::sqrt(2.0 / std::max(e.effectivePixels, 1.0))).c_str());
        e.reason = text;
        return;
    }
    if (e.relMse > 0.0 && e.singleSampleShare > kReliableSingleSampleShare * e.relMse) {
        e.reason = percent(e.singleSampleShare / e.relMse) +
                   " of it comes from pixels where one sample holds most of the light: their "
                   "neighbours may not have found it yet";
        return;
    }
    e.reliable = true;
    e.reason.clear();
}

ErrorEstimate mergeErrorEstimates(const std::vector<ErrorEstimate>& parts,
                                  const std::vector<double>& samplesPerPixel, bool correlated) {
    if (parts.size() != samplesPerPixel.size() || parts.empty())
        throw InternalError("mergeErrorEstimates: one sample count per part");
    double total = 0.0;
    for (double n : samplesPerPixel)
        total += n;
    ErrorEstimate merged;
    double variance = 0.0;
    std::string unreliable;
    for (size_t k = 0; k < parts.size(); ++k) {
        const double w = total > 0.0 ? samplesPerPixel[k] / total : 0.0;
        merged.relMse += w * w * parts[k].relMse;
        variance += std::pow(w * w * parts[k].standardError, 2.0);
        merged.singleSampleShare += w * w * parts[k].singleSampleShare;
        merged.pixels = k == 0 ? parts[k].pixels : std::min(merged.pixels, parts[k].pixels);
        merged.pixelsTotal = std::max(merged.pixelsTotal, parts[k].pixelsTotal);
        merged.effectivePixels = k == 0 ? parts[k].effectivePixels
                                        : std::min(merged.effectivePixels, parts[k].effectivePixels);
        merged.upperBound = merged.upperBound || parts[k].upperBound ||
                            (correlated && parts.size() > 1);
        merged.replicates = k == 0 ? parts[k].replicates
                                   : std::min(merged.replicates, parts[k].replicates);
        if (!parts[k].reliable && unreliable.empty())
            unreliable = "part " + std::to_string(k + 1) + "'s is not: " + parts[k].reason;
    }
    merged.standardError = std::sqrt(variance);
    judgeErrorEstimate(merged);
    if (!unreliable.empty()) {
        merged.reliable = false;
        merged.reason = unreliable;
    }
    return merged;
}

std::string describeErrorEstimate(const ErrorEstimate& e) {
    char text[64];
    const char* bound = e.upperBound ? "<= " : "";
    if (e.reliable)
        std::snprintf(text, sizeof text, "%s%.3g (+-%.2g)", bound, e.relMse, e.standardError);
    else
        std::snprintf(text, sizeof text, "%s%.3g (unreliable)", bound, e.relMse);
    return text;
}

} // namespace wf
