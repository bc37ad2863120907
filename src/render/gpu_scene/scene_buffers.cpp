#include "render/gpu_scene/scene_buffers.h"

#include <cstring>

#include "errors.h"
#include "gpu/context.h"
#include "passes/shade_kinds.h"
#include "scene/bvh/bvh_tuning.h"
#include "scene/bvh/instance_bvh.h"
#include "render/gpu_scene/scene_acceleration.h"
#include "render/gpu_scene/table_pages.h"
#include "shaders/types/render_types.h"
#include "shaders/bsdf/sheen.h"

namespace wf {

namespace {

// The moving lights' and the camera's keys after the instances' (motion.glsl's table).
void appendLightAndCameraMotion(const Scene& scene, PreparedScene& prepared) {
    prepared.motionSegments = scene.motionSegments;
    if (scene.motionSegments == 0)
        return;
    const uint32_t keys = scene.motionSegments + 1;
    for (PunctualLight& light : prepared.punctualLights) {
        if (light.motion == 0u)
            continue;
        const uint32_t first = uint32_t(prepared.motionKeys.size());
        for (uint32_t k = 0; k < keys; ++k)
            prepared.motionKeys.emplace_back(scene.lightMotionKeys.at(light.motion - 1u + k), 1.0f);
        light.motion = first + 1u;
    }
    if (prepared.camera.motion.size() == keys) {
        prepared.cameraMotionKeys = uint32_t(prepared.motionKeys.size()) + 1u;
        for (const CameraKey& key : prepared.camera.motion) {
            prepared.motionKeys.emplace_back(key.position, 1.0f);
            prepared.motionKeys.emplace_back(key.forward, 0.0f);
            prepared.motionKeys.emplace_back(key.up, 0.0f);
        }
    }
}

} // namespace

PreparedScene prepareScene(Scene scene, std::vector<uint32_t>* order) {
    PreparedScene prepared;
    prepared.triangles = std::move(scene.triangles);
    prepared.materials = std::move(scene.materials);
    prepared.camera = scene.camera;
    prepared.hasCamera = scene.hasCamera;
    prepared.punctualLights = std::move(scene.lights);
    prepared.environment = std::move(scene.environment);
    prepared.surface = std::move(scene.surface);
    tagTriangles(prepared.triangles); // the per-triangle arrays follow the BVH's order
    if (!scene.placements.empty()) {
        prepared.instancedTriangles = scene.instancedTriangleCount();
        prepared.meshCount = uint32_t(scene.meshes.size());
        TwoLevelBvh bvh = buildTwoLevelBvh(prepared.triangles, scene.meshes, scene.placements,
                                           prepared.materials, prepared.camera);
        prepared.bvhPairs = std::move(bvh.pairs);
        prepared.instances = std::move(bvh.instances);
        prepared.motionKeys = std::move(bvh.motionKeys);
        prepared.bvhStats = bvh.stats;
        Bounds box;
        for (const Bounds& instance : bvh.instanceBoxes) {
            box.grow(instance.lo);
            box.grow(instance.hi);
        }
        prepared.bounds = sceneBounds(box, prepared.punctualLights);
    } else {
        prepared.instancedTriangles = prepared.triangles.size();
        {
            // The builder's tree is needed only until it is paired (what traversal reads).
            std::vector<BvhNode> nodes;
            prepared.bvhStats =
                buildTunedBvh(prepared.triangles, nodes, prepared.materials, prepared.camera);
            prepared.bvhPairs = pairBvhNodes(nodes);
        }
        prepared.bvhStats.stackNeed = bvhStackNeed(prepared.bvhPairs);
        prepared.bounds = sceneBounds(prepared.triangles, prepared.punctualLights);
    }
    if (order) {
        order->resize(prepared.triangles.size());
        for (size_t i = 0; i < prepared.triangles.size(); ++i)
            (*order)[i] = prepared.triangles[i].pad;
    }
    appendLightAndCameraMotion(scene, prepared);
    followTriangleOrder(prepared.triangles, prepared.surface);
    prepareLights(prepared);
    return prepared;
}

void prepareLights(PreparedScene& prepared) {
    prepared.lights = buildLightTable(prepared.triangles, prepared.materials,
                                      prepared.punctualLights, prepared.environment,
                                      prepared.bounds, prepared.surface);
    prepared.lightTree = buildLightTree(prepared.lights, prepared.triangles, prepared.materials,
                                        prepared.punctualLights, prepared.motionKeys,
                                        prepared.motionSegments);
    if (prepared.lightTree.lights < 2)
        prepared.lightTree = LightTree{}; // one light needs no tree
}

namespace {

// The emitter table as the shaders choose from it: by power as built; with equal weights; or,
// for the tree, the lights beside it by power and one more slot, last, that stands for the
// tree with the power of its lights (theirs are 0 there: the tree chooses among them).
std::vector<Emitter> selectionTable(const LightTable& table, const LightTree& tree,
                                    LightSelection selection,
                                    const std::vector<PunctualLight>& lights) {
    if (selection == LightSelection::Power)
        return table.emitters;
    std::vector<double> weights;
    std::vector<uint32_t> sources;
    for (const Emitter& emitter : table.emitters) {
        const bool inTree = selection == LightSelection::Tree && inLightTree(emitter.source, lights);
        weights.push_back(selection == LightSelection::Uniform ? 1.0
                          : inTree ? 0.0
                                   : double(emitter.pmf) * table.totalPower);
        sources.push_back(emitter.source);
    }
    if (selection == LightSelection::Tree) {
        weights.push_back(tree.power);
        sources.push_back(WF_EMITTER_TREE);
    }
    std::vector<Emitter> chosen = buildAliasTable(weights);
    for (size_t i = 0; i < chosen.size(); ++i)
        chosen[i].source = sources[i];
    return chosen;
}

template <typename T>
Buffer uploadTable(const Context& context, const char* name, const std::vector<T>& values) {
    Buffer buffer(context, name, values.size() * sizeof(T));
    buffer.upload(values);
    return buffer;
}

// The material table as texels; scenes with a sheen get the sheen albedo table in front
// (scene_tables.glsl reads it there). Scenes shaded by kind carry each material's shade bin in
// its flags, for intersect to bin hits by.
std::vector<glm::vec4> materialTexels(std::vector<Material> materials, bool sheen,
                                      uint32_t shadeKinds) {
    if (shadeKinds != 0)
        for (Material& m : materials)
            m.flags |= shadeBinOf(shadeKinds, shadeKind(m)) << WF_MATERIAL_SHADE_BIN_SHIFT;
    const size_t front = sheen ? WF_SHEEN_TABLE_TEXELS : 0;
    std::vector<glm::vec4> texels(front + materials.size() * WF_MATERIAL_TEXELS, glm::vec4(0.0f));
    if (sheen)
        std::memcpy(texels.data(), gpu_types::WF_SHEEN_ALBEDO, sizeof gpu_types::WF_SHEEN_ALBEDO);
    if (!materials.empty())
        std::memcpy(texels.data() + front, materials.data(), materials.size() * sizeof(Material));
    return texels;
}

} // namespace

SceneBuffers::SceneBuffers(const Context& context, const PreparedScene& scene,
                           const ShaderVariant& variant)
    : defines_(variant.defines()),
      trianglePages_(uploadPages(context, "triangles", scene.triangles, variant.trianglePages)),
      bvhPages_(uploadPages(context, "bvh nodes", scene.bvhPairs, variant.bvhPages)),
      materials_(uploadTable(context, "materials",
                             materialTexels(scene.materials, variant.sheen, variant.shadeKinds))) {
    if (variant.instances)
        instancePages_ = uploadPages(context, "instances", scene.instances, variant.instancePages);
    if (variant.nextEventEstimation)
        emitters_ = uploadTable(context, "emitters",
                                selectionTable(scene.lights, scene.lightTree,
                                               variant.lightSelection, scene.punctualLights));
    if (variant.lightTree()) {
        lightTree_ = uploadTable(context, "light tree", scene.lightTree.nodes);
        lightTreeTrails_ = uploadTable(context, "light tree trails", scene.lightTree.trails);
    }
    if (variant.lightsBuffer())
        lights_ = uploadTable(context, "lights", scene.punctualLights);
    surface_ = SurfaceBuffers(context, scene.surface, variant.surface, variant.trianglePages);
    if (variant.environment) {
        const Environment& env = scene.environment;
        std::vector<glm::vec4> texels(size_t(env.width) * env.height);
        for (size_t i = 0; i < texels.size(); ++i)
            texels[i] = glm::vec4(env.rgb[3 * i], env.rgb[3 * i + 1], env.rgb[3 * i + 2], 0.0f);
        environment_ = uploadTable(context, "environment", texels);
        if (variant.nextEventEstimation)
            environmentAlias_ =
                uploadTable(context, "environment alias", scene.lights.environmentTexels);
    }
    if (variant.rayTracing)
        acceleration_ = buildSceneAcceleration(context, scene, variant);
    if (variant.motion) {
        const uint64_t bytes = scene.motionKeys.size() * sizeof(glm::vec4);
        if (bytes > context.properties().limits.maxStorageBufferRange)
            throw UsageError("--shutter: the moving things' keys need " +
                             std::to_string(bytes >> 20) + " MiB, over this device's " +
                             std::to_string(context.properties().limits.maxStorageBufferRange >> 20) +
                             " MiB per buffer (fewer moving instances, or no --shutter)");
        motionKeys_ = uploadTable(context, "motion keys", scene.motionKeys);
    }
}

void SceneBuffers::appendBindings(
    DescriptorBindings& bindings) const {
    // The tables every ray and shading point reads at scattered indices (compute_program.h).
    bindPages(bindings, trianglePages_, WF_BINDING_TRIANGLES, WF_BINDING_TRIANGLE_PAGE1);
    bindPages(bindings, bvhPages_, WF_BINDING_BVH_NODES, WF_BINDING_BVH_PAGE1);
    bindings.push_back({WF_BINDING_MATERIALS, &materials_, BufferAccess::UintTexels});
    bindPages(bindings, instancePages_, WF_BINDING_INSTANCES, WF_BINDING_INSTANCE_PAGE1);
    if (emitters_)
        bindings.push_back({WF_BINDING_EMITTERS, &emitters_, BufferAccess::UintTexels});
    if (lightTree_) {
        bindings.push_back({WF_BINDING_LIGHT_TREE, &lightTree_, BufferAccess::UintTexels});
        bindings.push_back(
            {WF_BINDING_LIGHT_TREE_TRAILS, &lightTreeTrails_, BufferAccess::UintTexels});
    }
    if (lights_)
        bindings.push_back({WF_BINDING_LIGHTS, &lights_, BufferAccess::UintTexels});
    if (environment_)
        bindings.push_back({WF_BINDING_ENVIRONMENT, &environment_, BufferAccess::UintTexels});
    if (environmentAlias_)
        bindings.push_back(
            {WF_BINDING_ENVIRONMENT_ALIAS, &environmentAlias_, BufferAccess::UintTexels});
    if (motionKeys_)
        bindings.push_back({WF_BINDING_MOTION_KEYS, &motionKeys_});
    surface_.appendBindings(bindings);
}

void SceneBuffers::appendMemoryReport(
    std::vector<std::pair<std::string, uint64_t>>& report) const {
    for (const std::vector<Buffer>* pages : {&trianglePages_, &bvhPages_, &instancePages_})
        for (const Buffer& page : *pages)
            report.emplace_back(page.name(), page.size());
    for (const Buffer* buffer : {&materials_, &emitters_, &lightTree_,
                                 &lightTreeTrails_, &lights_, &environment_, &environmentAlias_,
                                 &motionKeys_})
        if (*buffer)
            report.emplace_back(buffer->name(), buffer->size());
    surface_.appendMemoryReport(report);
    if (acceleration_)
        report.emplace_back("acceleration structures", acceleration_->bytes());
}

} // namespace wf
