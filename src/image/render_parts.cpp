#include "image/render_parts.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "errors.h"
#include "image/error_metrics.h"
#include "image/exr_io.h"
#include "image/png_writer.h"

namespace wf {

std::string fileHash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot be read");
    uint64_t hash = 1469598103934665603ull;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        for (std::streamsize i = 0; i < in.gcount(); ++i)
            hash = (hash ^ static_cast<unsigned char>(buffer[i])) * 1099511628211ull;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

namespace {

std::string attribute(const std::string& path, const std::string& name) {
    auto value = readExrAttribute(path, name);
    if (!value)
        throw InputError(path + ": not a part of a Wavefront render (no '" + name +
                         "' attribute; render it with this version)");
    return *value;
}

uint32_t count(const std::string& path, const std::string& name) {
    const std::string text = attribute(path, name);
    try {
        const long value = std::stol(text);
        if (value >= 0)
            return static_cast<uint32_t>(value);
    } catch (const std::exception&) {
    }
    throw InputError(path + ": attribute '" + name + "' is not a sample count: " + text);
}

std::string range(uint32_t first, uint32_t end) {
    return std::to_string(first) + "-" + std::to_string(end - 1);
}

void appendRange(std::string& list, uint32_t first, uint32_t end) {
    if (!list.empty())
        list += ',';
    list += range(first, end);
}

} // namespace

RenderPart readRenderPart(const std::string& path) {
    RenderPart part;
    part.path = path;
    ExrImage image = readExr(path);
    part.width = image.width;
    part.height = image.height;
    part.rgb = std::move(image.rgb);
    part.sceneHash = attribute(path, "sceneHash");
    part.renderSettings = attribute(path, "renderSettings");
    part.scene = attribute(path, "scene");
    part.sampler = attribute(path, "sampler");
    part.seed = static_cast<int>(count(path, "seed"));
    part.maxDepth = static_cast<int>(count(path, "maxDepth"));
    part.spp = count(path, "spp");
    part.sppOffset = count(path, "sppOffset");
    part.sppTotal = count(path, "sppTotal");
    part.renderSeconds = std::stod(attribute(path, "renderSeconds"));
    if (auto relMse = readExrAttribute(path, "estimatedRelMse")) {
        ErrorEstimate estimate;
        auto number = [&](const char* name) {
            auto text = readExrAttribute(path, name);
            try {
                return text ? std::stod(*text) : 0.0;
            } catch (const std::exception&) {
                throw InputError(path + ": attribute '" + name + "' is not a number: " + *text);
            }
        };
        estimate.relMse = number("estimatedRelMse");
        estimate.standardError = number("estimatedRelMseError");
        estimate.singleSampleShare = number("estimatedRelMseFromSingleSamples");
        estimate.pixels = estimate.pixelsTotal = uint32_t(part.width) * uint32_t(part.height);
        estimate.reliable = readExrAttribute(path, "errorEstimateReliable") == "true";
        estimate.reason = readExrAttribute(path, "errorEstimateReason").value_or("");
        estimate.upperBound = readExrAttribute(path, "errorEstimateIsUpperBound") == "true";
        estimate.replicates = static_cast<uint32_t>(std::max(1.0, number("errorEstimateReplicates")));
        // Files from before it: every pixel, which the verdict they carry did not weigh.
        estimate.effectivePixels = readExrAttribute(path, "estimatedRelMseEffectivePixels")
                                       ? number("estimatedRelMseEffectivePixels")
                                       : double(estimate.pixelsTotal);
        part.errorEstimate = estimate;
    }
    if (part.spp == 0)
        throw InputError(path + ": a part of no samples");
    return part;
}

std::string previewPathFor(const std::string& exrPath) {
    return std::filesystem::path(exrPath).replace_extension(".png").string();
}

void writeRenderPart(const std::string& path, const RenderPart& part,
                     const std::vector<std::pair<std::string, std::string>>& extra,
                     bool preview, const std::vector<ExrChannel>& channels) {
    std::vector<std::pair<std::string, std::string>> strings = {
        {"software", "Wavefront"}, {"scene", part.scene}, {"sampler", part.sampler},
        {"sceneHash", part.sceneHash}, {"renderSettings", part.renderSettings}};
    if (const auto& estimate = part.errorEstimate) {
        char numbers[4][32];
        std::snprintf(numbers[0], sizeof numbers[0], "%.6g", estimate->relMse);
        std::snprintf(numbers[1], sizeof numbers[1], "%.6g", estimate->standardError);
        std::snprintf(numbers[2], sizeof numbers[2], "%.6g", estimate->singleSampleShare);
        std::snprintf(numbers[3], sizeof numbers[3], "%.6g", estimate->effectivePixels);
        strings.insert(strings.end(), {{"estimatedRelMse", numbers[0]},
                                       {"estimatedRelMseError", numbers[1]},
                                       {"estimatedRelMseFromSingleSamples", numbers[2]},
                                       {"estimatedRelMseEffectivePixels", numbers[3]},
                                       {"errorEstimateReliable",
                                        estimate->reliable ? "true" : "false"},
                                       {"errorEstimateIsUpperBound",
                                        estimate->upperBound ? "true" : "false"},
                                       {"errorEstimateReplicates",
                                        std::to_string(estimate->replicates)}});
        if (!estimate->reliable)
            strings.push_back({"errorEstimateReason", estimate->reason});
    }
    strings.insert(strings.end(), extra.begin(), extra.end());
    writeExr(path, part.width, part.height, part.rgb, strings,
             {{"renderSeconds", static_cast<float>(part.renderSeconds)}},
             {{"spp", static_cast<int>(part.spp)},
              {"seed", part.seed},
              {"maxDepth", part.maxDepth},
              {"sppOffset", static_cast<int>(part.sppOffset)},
              {"sppTotal", static_cast<int>(part.sppTotal)}},
             channels);
    if (preview)
        writePngPreview(previewPathFor(path), part.width, part.height, part.rgb,
                        part.previewTonemap);
}

void checkSameRender(const std::vector<RenderPart>& parts) {
    if (parts.empty())
        throw UsageError("merge needs at least one part");
    const RenderPart& first = parts.front();
    auto differs = [&](const RenderPart& part, const std::string& what, const std::string& a,
                       const std::string& b) {
        throw InputError(part.path + ": " + what + " " + a + " differs from " + first.path +
                         "'s " + b + ": not a part of the same render");
    };
    for (const RenderPart& part : parts) {
        if (part.sceneHash != first.sceneHash)
            differs(part, "scene (file hash)", part.sceneHash, first.sceneHash);
        if (part.width != first.width || part.height != first.height)
            differs(part, "size", std::to_string(part.width) + "x" + std::to_string(part.height),
                    std::to_string(first.width) + "x" + std::to_string(first.height));
        if (part.renderSettings != first.renderSettings)
            differs(part, "settings", "'" + part.renderSettings + "'",
                    "'" + first.renderSettings + "'");
        if (part.seed != first.seed)
            differs(part, "seed", std::to_string(part.seed), std::to_string(first.seed));
        // Only a finite set's samples depend on its size (render --spp-total).
        const bool finiteSet = first.sampler == "stratified" || first.sampler == "multijitter" ||
                               first.sampler == "hammersley";
        if (finiteSet && part.sppTotal != first.sppTotal)
            differs(part, "--spp-total", std::to_string(part.sppTotal),
                    std::to_string(first.sppTotal));
        if (part.sampler != first.sampler)
            differs(part, "sampler", part.sampler, first.sampler);
    }
}

MergedRender mergeRenderParts(const std::vector<RenderPart>& parts) {
    checkSameRender(parts);
    std::vector<const RenderPart*> order;
    for (const RenderPart& part : parts)
        order.push_back(&part);
    std::sort(order.begin(), order.end(), [](const RenderPart* a, const RenderPart* b) {
        return a->sppOffset < b->sppOffset;
    });
    MergedRender merged;
    uint32_t runStart = order.front()->sppOffset, runEnd = runStart;
    std::vector<std::vector<float>> images;
    std::vector<double> weights;
    merged.image = *order.front();
    merged.image.path.clear();
    merged.image.spp = 0;
    merged.image.renderSeconds = 0.0;
    merged.image.errorEstimate.reset();
    std::vector<ErrorEstimate> estimates;
    for (const RenderPart* part : order) {
        const uint32_t end = part->sppOffset + part->spp;
        if (part->sppOffset < runEnd)
            throw InputError(part->path + " (samples " + range(part->sppOffset, end) +
                             ") overlaps samples " + range(runStart, runEnd) + " of another part");
        if (part->sppOffset > runEnd) {
            appendRange(merged.ranges, runStart, runEnd);
            merged.gaps.push_back(range(runEnd, part->sppOffset));
            runStart = part->sppOffset;
        }
        runEnd = end;
        images.push_back(part->rgb);
        weights.push_back(part->spp);
        merged.image.spp += part->spp;
        merged.image.renderSeconds += part->renderSeconds;
        if (part->errorEstimate)
            estimates.push_back(*part->errorEstimate);
    }
    if (estimates.size() == order.size())
        merged.image.errorEstimate =
            mergeErrorEstimates(estimates, weights, order.front()->sampler != "independent");
    appendRange(merged.ranges, runStart, runEnd);
    merged.image.rgb = mergeBySampleCount(images, weights);
    return merged;
}

} // namespace wf
