#include "render/gpu_scene/frame_scenes.h"

#include <chrono>

#include "errors.h"
#include "scene/bvh/bvh_refit.h"

namespace wf {

FrameBvh parseFrameBvh(const std::string& name) {
    if (name == "auto")
        return FrameBvh::Auto;
    if (name == "refit")
        return FrameBvh::Refit;
    if (name == "rebuild")
        return FrameBvh::Rebuild;
    throw UsageError("--frame-bvh " + name + ": expected auto, refit or rebuild");
}

const char* frameBvhName(FrameBvh mode) {
    return mode == FrameBvh::Auto ? "auto" : mode == FrameBvh::Refit ? "refit" : "rebuild";
}

// The previous frame's tree and triangle order over this frame's triangles, when the loader
// produced the same triangles (count and material of each) in one-level form and the refit
// tree has not worn out; `scene` is left whole when this returns false.
bool FrameScenes::refit(Scene& scene, PreparedScene& out) {
    const PreparedScene& previous = scenes_[current_];
    // Motion blur's keys (--shutter) are built with the tree: such frames are rebuilt.
    if (!previous.instances.empty() || !scene.placements.empty() || scene.motionSegments != 0 ||
        scene.triangles.size() != order_.size() ||
        scene.materials.size() != previous.materials.size())
        return false;
    for (size_t i = 0; i < order_.size(); ++i)
        if (scene.triangles[order_[i]].material != previous.triangles[i].material)
            return false;
    std::vector<Triangle> triangles(order_.size());
    for (size_t i = 0; i < order_.size(); ++i) {
        triangles[i] = scene.triangles[order_[i]];
        triangles[i].pad = order_[i]; // followTriangleOrder's tag
    }
    std::vector<BvhPair> pairs = previous.bvhPairs;
    refitBvhPairs(pairs, triangles);
    costRatio_ = builtCost_ > 0.0 ? pairTreeCost(pairs) / builtCost_ : 1.0;
    if (costRatio_ > rebuildRatio_)
        return false;
    // The render time the worn tree is expected to add, against what a build would cost.
    if (mode_ == FrameBvh::Auto &&
        (builtRender_ < 0.0 || builtRender_ * (costRatio_ - 1.0) > buildSeconds_))
        return false;
    out = PreparedScene{};
    out.triangles = std::move(triangles);
    out.bvhPairs = std::move(pairs);
    out.bvhStats = previous.bvhStats; // the same tree: depth, stack need, leaves
    out.bvhStats.buildSeconds = 0.0;
    out.materials = std::move(scene.materials);
    out.camera = scene.camera;
    out.hasCamera = scene.hasCamera;
    out.punctualLights = std::move(scene.lights);
    out.environment = std::move(scene.environment);
    out.surface = std::move(scene.surface);
    followTriangleOrder(out.triangles, out.surface);
    out.instancedTriangles = out.triangles.size();
    out.bounds = sceneBounds(out.triangles, out.punctualLights);
    prepareLights(out);
    return true;
}

const PreparedScene& FrameScenes::prepare(Scene scene) {
    const int next = current_ < 0 ? 0 : 1 - current_;
    PreparedScene& out = scenes_[next];
    refitted_ = mode_ != FrameBvh::Rebuild && current_ >= 0 && refit(scene, out);
    if (!refitted_) {
        const auto start = std::chrono::steady_clock::now();
        out = prepareScene(std::move(scene), &order_);
        buildSeconds_ =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        builtCost_ = out.instances.empty() ? pairTreeCost(out.bvhPairs) : 0.0;
        costRatio_ = 1.0;
        builtRender_ = -1.0;
    }
    current_ = next;
    return out;
}

void FrameScenes::rendered(double seconds) {
    if (!refitted_)
        builtRender_ = seconds;
}

} // namespace wf
