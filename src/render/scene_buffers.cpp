#include "render/scene_buffers.h"

#include "shaders/shared/render_types.h"

namespace wf {

PreparedScene prepareScene(Scene scene) {
    PreparedScene prepared;
    prepared.triangles = std::move(scene.triangles);
    prepared.materials = std::move(scene.materials);
    prepared.camera = scene.camera;
    prepared.hasCamera = scene.hasCamera;
    prepared.bvhStats = buildBvh(prepared.triangles, prepared.nodes);
    prepared.lights = buildLightTable(prepared.triangles, prepared.materials);
    return prepared;
}

namespace {

template <typename T>
Buffer uploadTable(const Context& context, const char* name, const std::vector<T>& values) {
    Buffer buffer(context, name, values.size() * sizeof(T));
    buffer.upload(values);
    return buffer;
}

} // namespace

SceneBuffers::SceneBuffers(const Context& context, const PreparedScene& scene)
    : triangles_(uploadTable(context, "triangles", scene.triangles)),
      nodes_(uploadTable(context, "bvh nodes", scene.nodes)),
      materials_(uploadTable(context, "materials", scene.materials)) {
    if (!scene.lights.emitters.empty())
        emitters_ = uploadTable(context, "emitters", scene.lights.emitters);
}

void SceneBuffers::appendBindings(
    std::vector<std::pair<uint32_t, const Buffer*>>& bindings) const {
    bindings.emplace_back(WF_BINDING_TRIANGLES, &triangles_);
    bindings.emplace_back(WF_BINDING_BVH_NODES, &nodes_);
    bindings.emplace_back(WF_BINDING_MATERIALS, &materials_);
    if (emitters_)
        bindings.emplace_back(WF_BINDING_EMITTERS, &emitters_);
}

void SceneBuffers::appendMemoryReport(
    std::vector<std::pair<std::string, uint64_t>>& report) const {
    for (const Buffer* buffer : {&triangles_, &nodes_, &materials_, &emitters_})
        if (*buffer)
            report.emplace_back(buffer->name(), buffer->size());
}

} // namespace wf
