// The scene on the GPU: triangles in BVH order, the flattened BVH, materials and, only when the
// scene has emissive triangles, the emitter table.
#pragma once
#include <memory>
#include <utility>
#include <vector>

#include "gpu/acceleration_structure.h"
#include "gpu/buffer.h"
#include "gpu/compute_program.h"
#include "scene/bvh/bvh_builder.h"
#include "scene/lights/light_table.h"
#include "scene/lights/light_tree.h"
#include "render/shader_variant.h"
#include "render/gpu_scene/surface_buffers.h"
#include "scene/scene.h"

namespace wf {

class Context;

// The loaded scene after the BVH build (which reorders triangles) and the light table.
struct PreparedScene {
    std::vector<Triangle> triangles;
    std::vector<BvhPair> bvhPairs; // what traversal reads
    // Two-level scenes (instance_bvh.h): the top level's leaves; empty for one-level scenes.
    std::vector<Instance> instances;
    uint32_t meshCount = 0;          // instanced meshes
    uint64_t instancedTriangles = 0; // triangles as rendered, every placement counted
    std::vector<Material> materials;
    LightTable lights;
    LightTree lightTree; // over the lights that have a place, when there are two or more
    std::vector<PunctualLight> punctualLights; // spheres first, as the light table orders them
    Environment environment;
    SurfaceData surface; // per-triangle arrays in BVH order, textures
    SceneBounds bounds;
    Camera camera;
    bool hasCamera = false;
    BvhBuildStats bvhStats;
    // Motion blur (WF_MOTION; motion.glsl): motionSegments + 1 keys per moving thing, the
    // instances' (Instance::motionKeys), the lights' (PunctualLight::motion, 1 + the first),
    // then the camera's; 0 segments when nothing moves.
    uint32_t motionSegments = 0;
    std::vector<glm::vec4> motionKeys;
    uint32_t cameraMotionKeys = 0; // 1 + the camera's first key; 0: it is still
};

// `order`, when given, receives the triangle permutation the build applied: entry i is the
// loader's index of the triangle now at i (what scene_refit.h refits later frames by).
PreparedScene prepareScene(Scene scene, std::vector<uint32_t>* order = nullptr);
// prepareScene's last step, over triangles already in their tree's order: bounds, light table
// and light tree (scene_refit.h, after refitting the tree).
void prepareLights(PreparedScene& prepared);

class SceneBuffers {
public:
    SceneBuffers(const Context& context, const PreparedScene& scene,
                 const ShaderVariant& variant);

    // The variant's defines the buffers were made for: renderers that share them must match.
    const ShaderDefines& defines() const { return defines_; }

    bool hasEmitters() const { return static_cast<bool>(emitters_); }
    bool hasLights() const { return static_cast<bool>(lights_); }
    bool hasEnvironment() const { return static_cast<bool>(environment_); }
    // The driver's acceleration structures (variants with rayTracing), else null.
    const AccelerationStructureSet* acceleration() const { return acceleration_.get(); }
    // (binding, buffer) pairs for the descriptor table.
    void appendBindings(DescriptorBindings& bindings) const;
    void appendMemoryReport(std::vector<std::pair<std::string, uint64_t>>& report) const;

private:
    ShaderDefines defines_;
    std::vector<Buffer> trianglePages_; // the variant's trianglePages
    std::vector<Buffer> bvhPages_;      // and bvhPages
    std::vector<Buffer> instancePages_; // and instancePages: two-level scenes only
    Buffer materials_;
    Buffer emitters_; // empty handle when the scene has no emitters
    Buffer lightTree_;       // nodes and each emitter's trail, with --light-selection tree
    Buffer lightTreeTrails_;
    Buffer lights_;   // punctual and sphere lights, if any
    Buffer environment_;
    Buffer environmentAlias_;
    Buffer motionKeys_; // WF_MOTION: the moving things' keys (motion.glsl)
    SurfaceBuffers surface_; // normals, tangents, UVs, textures: what the scene uses
    std::unique_ptr<AccelerationStructureSet> acceleration_;
};

} // namespace wf
