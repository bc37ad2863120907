// Parts of one render made with --spp-offset, and their merge (`wavefront merge`): each part's
// EXR header says what it is (scene file hash, the settings that shape the image, seed, size,
// sample range), and parts merge only when all of that agrees and no two ranges overlap. The
// merge is the sample-weighted mean, which is the image of one run of all the samples up to
// float rounding.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "image/error_estimate.h"
#include "image/exr_io.h"
#include "image/tonemap.h"

namespace wf {

// FNV-1a 64 of a file's bytes, as 16 hex digits. Throws InputError if it cannot be read.
std::string fileHash(const std::string& path);

struct RenderPart {
    std::string path;
    int width = 0;
    int height = 0;
    std::vector<float> rgb;
    std::string sceneHash;      // fileHash of the scene (and of --env's file, if any)
    std::string renderSettings; // renderSettingsKey of the run
    std::string scene;          // the scene's path, as given
    std::string sampler;
    int seed = 0;
    int maxDepth = 0;
    uint32_t sppOffset = 0;
    uint32_t spp = 0;
    uint32_t sppTotal = 0;
    double renderSeconds = 0.0;
    // The render's estimate of its own relMSE (attributes estimatedRelMse, estimatedRelMseError,
    // estimatedRelMseFromSingleSamples, errorEstimateReliable, errorEstimateReason,
    // errorEstimateIsUpperBound); absent in
    // files of versions before it. A merge carries the parts' merged estimate when every part
    // has one.
    std::optional<ErrorEstimate> errorEstimate;
    // The PNG preview's tone curve (--tonemap); not a property of the image, so not stored.
    Tonemap previewTonemap = kDefaultTonemap;
};

// Reads a part; InputError naming the file and the attribute when one is missing.
RenderPart readRenderPart(const std::string& path);

// The PNG preview written beside OUT.exr: OUT.png.
std::string previewPathFor(const std::string& exrPath);

// Writes `part` (its rgb and every attribute readRenderPart reads, plus `extra` strings) as an
// EXR, atomically, and its PNG preview beside it unless `preview` is false.
void writeRenderPart(const std::string& path, const RenderPart& part,
                     const std::vector<std::pair<std::string, std::string>>& extra = {},
                     bool preview = true, const std::vector<ExrChannel>& channels = {});

struct MergedRender {
    RenderPart image;                  // path empty; spp the sum, sppOffset the first sample
    std::string ranges;                // "0-511,768-1023": the sample ranges merged
    std::vector<std::string> gaps;     // "512-767": samples in no part
};

// InputError naming the first part of `parts` that is not of the same render as parts[0]
// (scene, size, settings, seed, sampler, a finite set's size). What mergeRenderParts checks
// first; `render --resume` checks a checkpoint against the run the same way.
void checkSameRender(const std::vector<RenderPart>& parts);

// InputError naming the parts when they come from different scenes, settings, seeds, sizes or
// (finite-set samplers) sets, or when two sample ranges overlap; gaps are reported, not
// refused. The merged sppTotal is the first part's.
MergedRender mergeRenderParts(const std::vector<RenderPart>& parts);

} // namespace wf
