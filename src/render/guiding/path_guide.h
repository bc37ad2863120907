// The path guide of one render: the host SD-tree (sd_tree.h), the GPU buffers it is flattened
// into (fixed capacities, bound once in the renderer's descriptor table), and the rebuild
// between training iterations: read the splats back, split, refine, swap, upload.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_program.h"
#include "render/guiding/sd_tree.h"

namespace wf {

class Context;

// One line of --verbose and one entry of the JSON's guiding.iterations.
struct GuideIteration {
    uint32_t samplesPerPixel = 0;
    size_t spatialLeaves = 0;   // after the rebuild that ended it
    size_t directionalNodes = 0;
    double renderSeconds = 0.0;
    double rebuildSeconds = 0.0;
};

class PathGuide {
public:
    // sceneLo/Hi: the scene's bounds; pathCapacity: paths per wave (training records).
    PathGuide(const Context& context, glm::vec3 sceneLo, glm::vec3 sceneHi,
              uint32_t pathCapacity, float bsdfFraction, uint32_t maxDepth,
              bool learnFraction, bool parallax);

    void appendBindings(DescriptorBindings& bindings) const;
    void appendMemoryReport(std::vector<std::pair<std::string, uint64_t>>& report) const;
    void setTraining(bool training);
    void reset(); // forget what was learnt: one uniform quadtree over the whole box
    // Samples from `tree` from now on (tests: a deliberately wrong guide). Its box must be
    // this guide's.
    void setTree(guiding::SDTree tree);
    // Ends training iteration `iteration` (0-based): reads the splats back, rebuilds the trees
    // and uploads them. Returns the rebuild's seconds.
    double endIteration(uint32_t iteration);
    const guiding::SDTree& tree() const { return tree_; }
    // Every leaf samples the BSDF alone from now on (the guide does not pay), and no vertex
    // looks the guide up (until reset() or setTree()).
    void sampleBsdfAlone();
    uint64_t deviceBytes() const;

private:
    void upload();

    guiding::SDTree tree_;
    guiding::FlatGuide flat_;
    float bsdfFraction_;
    uint32_t maxDepth_;
    bool learnFraction_;
    bool parallax_;
    bool training_ = false;
    bool bsdfAlone_ = false; // sampleBsdfAlone() since the last reset() or setTree()
    Buffer params_, spatial_, sampling_, building_, splats_, leafSamples_, records_, counts_;
};

} // namespace wf
