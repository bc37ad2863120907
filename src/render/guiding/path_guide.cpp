#include "render/guiding/path_guide.h"

#include <chrono>

#include "errors.h"
#include "shaders/types/render_types.h"

namespace wf {

using gpu_types::GuideDirNode;
using gpu_types::GuideParams;
using gpu_types::GuideRecord;
using gpu_types::GuideSpatialNode;

namespace {
// Capacities: 2^15 spatial nodes (2^14 leaves) and 2^18 quadtree nodes per array, 8 MiB each;
// the splat counters are as large. Trees that outgrow them are coarsened.
constexpr size_t kSpatialNodes = size_t(1) << 15;
constexpr size_t kDirNodes = size_t(1) << 18;
constexpr double kEnergyThreshold = 0.01; // the paper's share of a leaf's energy
// A leaf learns its BSDF share from at least this many records in an iteration: fewer give
// second moments ruled by one or two records.
constexpr double kFractionMinRecords = 256.0;
} // namespace

PathGuide::PathGuide(const Context& context, glm::vec3 sceneLo, glm::vec3 sceneHi,
                     uint32_t pathCapacity, float bsdfFraction, uint32_t maxDepth,
                     bool learnFraction, bool parallax)
    : tree_(sceneLo, sceneHi), bsdfFraction_(bsdfFraction), maxDepth_(maxDepth),
      learnFraction_(learnFraction), parallax_(parallax),
      params_(context, "guide params", sizeof(GuideParams)),
      spatial_(context, "guide spatial tree", kSpatialNodes * sizeof(GuideSpatialNode)),
      sampling_(context, "guide sampling quadtrees", kDirNodes * sizeof(GuideDirNode)),
      building_(context, "guide building quadtrees", kDirNodes * sizeof(GuideDirNode)),
      splats_(context, "guide splats", kDirNodes * 8 * sizeof(uint32_t)),
      leafSamples_(context, "guide leaf statistics",
                   kSpatialNodes * WF_GUIDE_LEAF_STATS * sizeof(uint32_t)),
      records_(context, "guide records",
               uint64_t(pathCapacity) * WF_GUIDE_RECORDS * sizeof(GuideRecord)),
      counts_(context, "guide record counts", uint64_t(pathCapacity) * sizeof(uint32_t)) {
    flat_ = tree_.flatten();
    upload();
}

void PathGuide::appendBindings(DescriptorBindings& bindings) const {
    bindings.push_back({WF_BINDING_GUIDE_PARAMS, &params_});
    bindings.push_back({WF_BINDING_GUIDE_SPATIAL, &spatial_});
    bindings.push_back({WF_BINDING_GUIDE_SAMPLING, &sampling_});
    bindings.push_back({WF_BINDING_GUIDE_BUILDING, &building_});
    bindings.push_back({WF_BINDING_GUIDE_SPLATS, &splats_});
    bindings.push_back({WF_BINDING_GUIDE_LEAF_SAMPLES, &leafSamples_});
    bindings.push_back({WF_BINDING_GUIDE_RECORDS, &records_});
    bindings.push_back({WF_BINDING_GUIDE_COUNTS, &counts_});
}

void PathGuide::appendMemoryReport(std::vector<std::pair<std::string, uint64_t>>& report) const {
    for (const Buffer* b :
         {&params_, &spatial_, &sampling_, &building_, &splats_, &leafSamples_, &records_, &counts_})
        report.emplace_back(b->name(), b->size());
}

uint64_t PathGuide::deviceBytes() const {
    uint64_t total = 0;
    for (const Buffer* b :
         {&params_, &spatial_, &sampling_, &building_, &splats_, &leafSamples_, &records_, &counts_})
        total += b->size();
    return total;
}

void PathGuide::reset() {
    bsdfAlone_ = false;
    tree_ = guiding::SDTree(tree_.boxLo(), tree_.boxLo() + tree_.boxSize());
    flat_ = tree_.flatten();
    upload();
}

void PathGuide::setTree(guiding::SDTree tree) {
    bsdfAlone_ = false;
    tree_ = std::move(tree);
    flat_ = tree_.flatten();
    upload();
}

void PathGuide::sampleBsdfAlone() {
    bsdfAlone_ = true;
    tree_.setBsdfFractions(1.0f);
    flat_ = tree_.flatten();
    upload();
}

void PathGuide::setTraining(bool training) {
    training_ = training;
    GuideParams p{};
    p.boxLo = tree_.boxLo();
    // Leaves that learnt no share sample the default one; before the first iteration ends the
    // guide is uniform, which loses to the BSDF's own sampling wherever shares are learnt, so
    // the first iteration samples the BSDF alone (its records still learn from it).
    p.bsdfFraction = learnFraction_ && !tree_.hasLearnt() ? 1.0f : bsdfFraction_;
    p.invBoxSize = 1.0f / tree_.boxSize();
    p.training = training ? 1u : 0u;
    // Sampling the BSDF alone, no vertex needs the guide: not even a walk to its leaf.
    p.maxDepth = bsdfAlone_ ? 0u : maxDepth_;
    p.learnFraction = learnFraction_ ? 1u : 0u;
    p.parallax = parallax_ ? 1u : 0u;
    // Twice the box's diagonal: past anything in the scene.
    p.farDistance = 2.0f * glm::length(tree_.boxSize());
    params_.upload(&p, sizeof p);
}

void PathGuide::upload() {
    if (flat_.spatial.size() > kSpatialNodes || flat_.sampling.size() > kDirNodes ||
        flat_.building.size() > kDirNodes)
        throw InternalError("path guide: the trees outgrew their buffers");
    spatial_.upload(flat_.spatial);
    sampling_.upload(flat_.sampling);
    building_.upload(flat_.building);
    splats_.upload(std::vector<uint32_t>(flat_.splatCounterCount(), 0u));
    leafSamples_.upload(
        std::vector<uint32_t>(flat_.samplingBase.size() * WF_GUIDE_LEAF_STATS, 0u));
    setTraining(training_);
}

double PathGuide::endIteration(uint32_t iteration) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<uint32_t> counters(flat_.splatCounterCount());
    splats_.download(counters.data(), counters.size() * sizeof(uint32_t));
    std::vector<uint32_t> samples(flat_.samplingBase.size() * WF_GUIDE_LEAF_STATS);
    leafSamples_.download(samples.data(), samples.size() * sizeof(uint32_t));
    tree_.addSplats(flat_, counters, samples);
    if (learnFraction_)
        tree_.learnFractions(kFractionMinRecords);
    tree_.endIteration(guiding::spatialSplitThreshold(iteration), kEnergyThreshold,
                       WF_GUIDE_MAX_DIR_DEPTH, kSpatialNodes / 2);
    flat_ = tree_.flatten();
    for (double threshold = 2.0 * kEnergyThreshold;
         flat_.sampling.size() > kDirNodes || flat_.building.size() > kDirNodes;
         threshold *= 2.0) {
        tree_.coarsen(threshold, WF_GUIDE_MAX_DIR_DEPTH);
        flat_ = tree_.flatten();
    }
    upload();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace wf
