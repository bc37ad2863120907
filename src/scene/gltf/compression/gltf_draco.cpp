// KHR_draco_mesh_compression primitives. The primitive's accessors describe the decoded data
// (count, componentType, type, normalized), so the decoded mesh must match them exactly; its
// values are written in the accessors' own component types, which quantized
// (KHR_mesh_quantization) accessors then read as usual. Decoding itself: draco_decoder.h.
#include <tiny_gltf.h>

#include "scene/gltf/compression/draco_decoder.h"
#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/compression/gltf_codecs.h"

namespace wf::gltf {
namespace {

bool isAttributeType(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT ||
           componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
}

} // namespace

void decodeDraco(tinygltf::Model& model, const DracoPrimitive& d, const std::string& file) {
    tinygltf::Primitive& primitive = model.meshes[d.mesh].primitives[d.primitive];
    const std::string where =
        "mesh " + std::to_string(d.mesh) + " primitive " + std::to_string(d.primitive);
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
        fail(file, where + ": Draco primitives must be triangle lists (mode 4), not mode " +
                       std::to_string(primitive.mode));
    }
    if (d.indices == -1) {
        fail(file, where + ": a Draco primitive needs an indices accessor");
    }
    checkIndex(file, d.indices, model.accessors.size(), "accessor", "indices of " + where);
    const tinygltf::Accessor& indices = model.accessors[d.indices];
    const std::string indexName =
        "accessor " + std::to_string(d.indices) + " (indices of " + where + ")";
    if (indices.type != TINYGLTF_TYPE_SCALAR ||
        (indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        fail(file, indexName + " must be a SCALAR of unsigned 8, 16 or 32-bit integers");
    }
    DracoRequest request;
    request.indexComponentType = indices.componentType;
    request.corners = indices.count;
    std::vector<int> targets{d.indices};
    std::vector<std::string> names;
    for (const auto& [name, id] : d.attributes) {
        const auto found = primitive.attributes.find(name);
        if (found == primitive.attributes.end()) {
            fail(file, where + ": Draco attribute " + name +
                           " is not among the primitive's attributes");
        }
        const int a = found->second;
        checkIndex(file, a, model.accessors.size(), "accessor", name + " of " + where);
        const tinygltf::Accessor& acc = model.accessors[a];
        const std::string accName =
            "accessor " + std::to_string(a) + " (" + name + " of " + where + ")";
        const int components = tinygltf::GetNumComponentsInType(uint32_t(acc.type));
        if (components < 1 || components > 4 || !isAttributeType(acc.componentType)) {
            fail(file, accName + " has a type or componentType that Draco data cannot fill");
        }
        if (targets.size() > 1 && acc.count != request.points) {
            fail(file, accName + " has " + std::to_string(acc.count) +
                           " elements, unlike the primitive's other Draco attributes");
        }
        request.points = acc.count;
        request.attributes.push_back({uint32_t(id), acc.componentType, components});
        targets.push_back(a);
        names.push_back(accName);
    }
    if (names.empty()) {
        fail(file, where + ": its KHR_draco_mesh_compression names no attributes");
    }
    checkIndex(file, d.bufferView, model.bufferViews.size(), "bufferView",
               where + " KHR_draco_mesh_compression");
    const tinygltf::BufferView& view = model.bufferViews[d.bufferView];
    const std::string viewName = "bufferView " + std::to_string(d.bufferView);
    checkIndex(file, view.buffer, model.buffers.size(), "buffer", viewName);
    const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
    if (view.byteLength > data.size() || view.byteOffset > data.size() - view.byteLength) {
        fail(file, viewName + " extends past the end of buffer " + std::to_string(view.buffer) +
                       " (" + std::to_string(data.size()) + " bytes)");
    }

    DracoResult result = decodeDracoMesh(data.data() + view.byteOffset, view.byteLength, request);
    const std::string stream = where + ": the Draco data in " + viewName;
    if (result.countsMismatch) {
        if (result.corners != request.corners) {
            fail(file, stream + " decodes to " + std::to_string(result.corners) +
                           " indices, but " + indexName + " says " +
                           std::to_string(request.corners));
        }
        fail(file, stream + " decodes to " + std::to_string(result.points) + " vertices, but " +
                       names.front() + " says " + std::to_string(request.points));
    }
    if (!result.error.empty()) {
        fail(file, stream + ": " + result.error);
    }
    // Attached after decoding: appending buffers moves `data`.
    model.accessors[d.indices].bufferView = appendBufferView(model, std::move(result.indices));
    model.accessors[d.indices].byteOffset = 0;
    for (std::size_t i = 0; i < result.attributes.size(); ++i) {
        tinygltf::Accessor& acc = model.accessors[targets[i + 1]];
        acc.bufferView = appendBufferView(model, std::move(result.attributes[i]));
        acc.byteOffset = 0;
    }
}

} // namespace wf::gltf
