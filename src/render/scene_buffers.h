// The scene on the GPU: triangles in BVH order, the flattened BVH, materials and, only when the
// scene has emissive triangles, the emitter table.
#pragma once
#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "scene/bvh_builder.h"
#include "scene/light_table.h"
#include "scene/scene.h"

namespace wf {

class Context;

// The loaded scene after the BVH build (which reorders triangles) and the light table.
struct PreparedScene {
    std::vector<Triangle> triangles;
    std::vector<BvhNode> nodes;
    std::vector<Material> materials;
    LightTable lights;
    Camera camera;
    bool hasCamera = false;
    BvhBuildStats bvhStats;
};

PreparedScene prepareScene(Scene scene);

class SceneBuffers {
public:
    SceneBuffers(const Context& context, const PreparedScene& scene);

    bool hasEmitters() const { return static_cast<bool>(emitters_); }
    // (binding, buffer) pairs for the descriptor table.
    void appendBindings(std::vector<std::pair<uint32_t, const Buffer*>>& bindings) const;
    void appendMemoryReport(std::vector<std::pair<std::string, uint64_t>>& report) const;

private:
    Buffer triangles_;
    Buffer nodes_;
    Buffer materials_;
    Buffer emitters_; // empty handle when the scene has no emitters
};

} // namespace wf
