// The prepared scene of each frame of a sequence (render --frames, the viewer's playback): a
// full build (prepareScene), or the last build's tree refitted to the frame's triangles where
// they keep their count and materials (a skin, morph targets, rigid nodes moving: the loader
// flattens them all into the same triangle list in the same order at every time). A refit
// costs a fraction of a build but traces slower as its boxes grow (docs/animation.md: a tree
// 1.17x the built one's surface-area cost rendered 1.15x slower), so Auto refits only while
// the render time that growth is expected to add (the last built frame's render time x the
// cost's growth) stays under the last build's time, and never past `rebuildRatio`; Refit
// refits up to `rebuildRatio`. Two scenes are kept, so the one a renderer still reads stays
// valid while the next is prepared.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "render/gpu_scene/scene_buffers.h"

namespace wf {

enum class FrameBvh { Auto, Refit, Rebuild };
FrameBvh parseFrameBvh(const std::string& name); // UsageError if unknown
const char* frameBvhName(FrameBvh mode);

// A refit tree this much costlier than when it was built is rebuilt (docs/animation.md).
constexpr double kRefitRebuildRatio = 1.5;

class FrameScenes {
public:
    explicit FrameScenes(FrameBvh mode, double rebuildRatio = kRefitRebuildRatio)
        : mode_(mode), rebuildRatio_(rebuildRatio) {}

    // The next frame's scene, prepared; valid until the call after next.
    const PreparedScene& prepare(Scene scene);
    // The render time of the frame last prepared (Auto weighs refits by it).
    void rendered(double seconds);
    bool refitted() const { return refitted_; }    // by the last prepare
    double costRatio() const { return costRatio_; } // the last tree's cost / cost when built

private:
    bool refit(Scene& scene, PreparedScene& out);

    FrameBvh mode_;
    double rebuildRatio_;
    PreparedScene scenes_[2];
    int current_ = -1; // none yet
    std::vector<uint32_t> order_; // the last build's triangle permutation (prepareScene)
    double builtCost_ = 0.0;
    double buildSeconds_ = 0.0;  // the last build's
    double builtRender_ = -1.0;  // the render time of the last built frame; < 0: not known
    bool refitted_ = false;
    double costRatio_ = 1.0;
};

} // namespace wf
