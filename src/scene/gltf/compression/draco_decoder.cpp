// Draco's decoder (Debian 12: 1.5.5), and the conversion of its attributes into glTF component
// types. Draco's ConvertValue checks each value's address against the attribute's buffer and
// integer values against the target type's range.
#include "scene/gltf/compression/draco_decoder.h"

#include <draco/compression/decode.h>

#include <cstring>
#include <exception>
#include <memory>

namespace wf::gltf {
namespace {

template <class T>
bool convert(const draco::PointAttribute& attribute, std::size_t points, int components,
             std::vector<unsigned char>& out) {
    out.resize(points * std::size_t(components) * sizeof(T));
    T value[4];
    for (std::size_t i = 0; i < points; ++i) {
        const draco::AttributeValueIndex index =
            attribute.mapped_index(draco::PointIndex(uint32_t(i)));
        if (!attribute.ConvertValue<T>(index, int8_t(components), value)) {
            return false;
        }
        std::memcpy(out.data() + i * components * sizeof(T), value, components * sizeof(T));
    }
    return true;
}

bool convertTo(int componentType, const draco::PointAttribute& attribute, std::size_t points,
               int components, std::vector<unsigned char>& out) {
    switch (componentType) {
    case 5120: return convert<int8_t>(attribute, points, components, out);
    case 5121: return convert<uint8_t>(attribute, points, components, out);
    case 5122: return convert<int16_t>(attribute, points, components, out);
    case 5123: return convert<uint16_t>(attribute, points, components, out);
    case 5125: return convert<uint32_t>(attribute, points, components, out);
    case 5126: return convert<float>(attribute, points, components, out);
    default: return false;
    }
}

bool indicesTo(const draco::Mesh& mesh, int componentType, std::vector<unsigned char>& out,
               std::string& error) {
    const std::size_t size = componentType == 5121 ? 1 : componentType == 5123 ? 2 : 4;
    const uint64_t limit = size == 4 ? UINT32_MAX : (uint64_t(1) << (8 * size)) - 1;
    out.resize(std::size_t(mesh.num_faces()) * 3 * size);
    for (uint32_t f = 0; f < mesh.num_faces(); ++f) {
        const draco::Mesh::Face& face = mesh.face(draco::FaceIndex(f));
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = face[k].value();
            if (v >= mesh.num_points() || v > limit) {
                error = "it gives index " + std::to_string(v) + ", past its " +
                        std::to_string(mesh.num_points()) + " vertices or the index type";
                return false;
            }
            std::memcpy(out.data() + (std::size_t(f) * 3 + k) * size, &v, size); // little-endian
        }
    }
    return true;
}

void decodeInto(const unsigned char* bytes, std::size_t size, const DracoRequest& request,
                DracoResult& result) {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes), size);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok() || !decoded.value()) {
        result.error = "it does not decode (" + decoded.status().error_msg_string() + ")";
        return;
    }
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    result.points = mesh->num_points();
    result.corners = std::size_t(mesh->num_faces()) * 3;
    if (result.points != request.points || result.corners != request.corners) {
        result.countsMismatch = true;
        return;
    }
    if (!indicesTo(*mesh, request.indexComponentType, result.indices, result.error)) {
        return;
    }
    for (const DracoRequest::Attribute& wanted : request.attributes) {
        const std::string name = "attribute id " + std::to_string(wanted.id);
        const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(wanted.id);
        if (!attribute) {
            result.error = "it has no " + name;
            return;
        }
        if (attribute->num_components() != wanted.components) {
            result.error = name + " has " + std::to_string(attribute->num_components()) +
                           " components, but its accessor " + std::to_string(wanted.components);
            return;
        }
        if (!attribute->is_mapping_identity() &&
            attribute->indices_map_size() < mesh->num_points()) {
            result.error = name + " maps fewer points than the mesh has";
            return;
        }
        // Floats into integers would round silently (or not at all for NaN).
        const bool floats = attribute->data_type() == draco::DT_FLOAT32 ||
                            attribute->data_type() == draco::DT_FLOAT64;
        result.attributes.emplace_back();
        if ((floats && wanted.componentType != 5126) ||
            !convertTo(wanted.componentType, *attribute, mesh->num_points(), wanted.components,
                       result.attributes.back())) {
            result.error = name + " does not convert to its accessor's componentType " +
                           std::to_string(wanted.componentType);
            return;
        }
    }
}

} // namespace

DracoResult decodeDracoMesh(const unsigned char* bytes, std::size_t size,
                            const DracoRequest& request) {
    DracoResult result;
    try {
        decodeInto(bytes, size, request, result);
    } catch (const std::exception& e) { // bad_alloc, length_error: a header asking for any size
        result = DracoResult{};
        result.error = std::string("decoding it failed (") + e.what() + ")";
    }
    return result;
}

} // namespace wf::gltf
