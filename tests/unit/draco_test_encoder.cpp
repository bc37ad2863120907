// Builds a draco::Mesh point by point (identity mapping, one value per point) and encodes it.
#include "draco_test_encoder.h"

#include <draco/compression/encode.h>

namespace wf::test {

DracoOutput encodeDracoMesh(const DracoInput& input) {
    DracoOutput out;
    if (input.attributes.empty() || input.indices.size() % 3 != 0) {
        out.error = "need attributes and whole triangles";
        return out;
    }
    const DracoInput::Attribute& first = input.attributes[0];
    const std::size_t points =
        (first.floats.empty() ? first.u16.size() : first.floats.size()) / first.components;
    draco::Mesh mesh;
    mesh.set_num_points(uint32_t(points));
    draco::Encoder encoder;
    for (const DracoInput::Attribute& a : input.attributes) {
        const auto type = a.position ? draco::GeometryAttribute::POSITION
                          : a.normal   ? draco::GeometryAttribute::NORMAL
                          : a.texcoord ? draco::GeometryAttribute::TEX_COORD
                                       : draco::GeometryAttribute::GENERIC;
        const bool floats = !a.floats.empty();
        const int size = floats ? 4 : 2;
        draco::GeometryAttribute ga;
        ga.Init(type, nullptr, uint8_t(a.components), floats ? draco::DT_FLOAT32 : draco::DT_UINT16,
                !floats, size * a.components, 0);
        const int id = mesh.AddAttribute(ga, true, uint32_t(points));
        for (std::size_t i = 0; i < points; ++i) {
            const void* value = floats ? static_cast<const void*>(&a.floats[i * a.components])
                                       : static_cast<const void*>(&a.u16[i * a.components]);
            mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)), value);
        }
        out.ids.push_back(mesh.attribute(id)->unique_id());
        if (floats && a.quantizationBits > 0) {
            encoder.SetAttributeQuantization(type, a.quantizationBits);
        }
    }
    const std::size_t faces = input.indices.size() / 3;
    mesh.SetNumFaces(faces);
    for (std::size_t f = 0; f < faces; ++f) {
        draco::Mesh::Face face;
        for (int k = 0; k < 3; ++k) {
            face[k] = draco::PointIndex(input.indices[f * 3 + k]);
        }
        mesh.SetFace(draco::FaceIndex(uint32_t(f)), face);
    }
    encoder.SetTrackEncodedProperties(true);
    draco::EncoderBuffer buffer;
    const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &buffer);
    if (!status.ok()) {
        out.error = status.error_msg_string();
        return out;
    }
    out.bytes.assign(buffer.data(), buffer.data() + buffer.size());
    out.points = encoder.num_encoded_points();
    out.faces = encoder.num_encoded_faces();
    return out;
}

} // namespace wf::test
