#include "scene/gltf/gltf_instancing.h"

#include <tiny_gltf.h>

#include "errors.h"
#include "scene/gltf/gltf_primitives.h"
#include "scene/gltf/gltf_scene_limits.h"

namespace wf {

Instancing parseInstancing(const std::string& name) {
    if (name == "auto")
        return Instancing::Auto;
    if (name == "on")
        return Instancing::On;
    if (name == "off")
        return Instancing::Off;
    throw UsageError("--instancing " + name + ": expected auto, on or off");
}

const char* instancingName(Instancing mode) {
    return mode == Instancing::On ? "on" : mode == Instancing::Off ? "off" : "auto";
}

namespace gltf {

std::size_t estimatedTriangles(const tinygltf::Model& model, const tinygltf::Primitive& primitive) {
    auto countOf = [&](int index) -> std::size_t {
        if (index < 0 || std::size_t(index) >= model.accessors.size())
            return 0;
        const tinygltf::Accessor& accessor = model.accessors[index];
        if (accessor.bufferView < 0 || std::size_t(accessor.bufferView) >= model.bufferViews.size())
            return 0;
        const int component = tinygltf::GetComponentSizeInBytes(accessor.componentType);
        const int components = tinygltf::GetNumComponentsInType(accessor.type);
        if (component <= 0 || components <= 0)
            return 0;
        const std::size_t element = std::size_t(component) * std::size_t(components);
        const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
        if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size() ||
            view.byteLength > model.buffers[view.buffer].data.size())
            return 0;
        return accessor.count <= view.byteLength / element ? accessor.count : 0;
    };
    auto position = primitive.attributes.find("POSITION");
    const std::size_t corners = primitive.indices >= 0 ? countOf(primitive.indices)
                                : position != primitive.attributes.end() ? countOf(position->second)
                                                                         : 0;
    return trianglesOfPrimitive(primitive.mode, corners);
}

bool meshEmits(const tinygltf::Model& model, std::size_t mesh, const MaterialTables& materials) {
    for (const tinygltf::Primitive& primitive : model.meshes[mesh].primitives) {
        if (primitive.material >= 0 && std::size_t(primitive.material) < materials.materials.size()) {
            const glm::vec3 e = materials.materials[primitive.material].emission;
            if (e.x > 0.0f || e.y > 0.0f || e.z > 0.0f)
                return true;
        }
    }
    return false;
}

std::vector<bool> meshesToInstance(const tinygltf::Model& model,
                                   const std::vector<std::size_t>& placements,
                                   const MaterialTables& materials, Instancing mode) {
    std::vector<bool> instanced(model.meshes.size(), false);
    if (mode == Instancing::Off)
        return instanced;
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        if (placements[m] < 2)
            continue;
        const bool emissive = meshEmits(model, m, materials);
        std::size_t triangles = 0;
        for (const tinygltf::Primitive& primitive : model.meshes[m].primitives)
            triangles += estimatedTriangles(model, primitive);
        const bool pays = mode == Instancing::On ||
                          triangles * (placements[m] - 1) >= kAutoInstancingCopies;
        instanced[m] = !emissive && triangles > 0 && pays;
    }
    return instanced;
}

} // namespace gltf
} // namespace wf
