// Reads each primitive's accessors back to floats and indices, then writes them again through
// the encoders (tests/unit/draco_test_encoder.h, meshoptimizer), one compressed primitive for
// each original one, in the same order, so the loaded scenes' materials and nodes line up.
#include "compressed_copy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include "unit/draco_test_encoder.h"

namespace wf::test {
namespace {

struct Attribute {
    std::string name;
    int components = 0;
    std::vector<float> values;
};

const unsigned char* accessorData(const Document& doc, const Json& accessor, std::size_t size,
                                  std::size_t& stride) {
    const Json& view = doc.json["bufferViews"][accessor.at("bufferView").get<int>()];
    stride = view.value("byteStride", std::size_t(0));
    stride = stride ? stride : size;
    const std::size_t offset = view.value("byteOffset", std::size_t(0)) +
                               accessor.value("byteOffset", std::size_t(0));
    const std::size_t count = accessor.at("count");
    if (view.value("buffer", 0) != 0 || offset + stride * (count - 1) + size > doc.bin.size()) {
        ADD_FAILURE() << "accessor outside buffer 0: " << accessor.dump();
        return nullptr;
    }
    return doc.bin.data() + offset;
}

std::vector<float> readFloats(const Document& doc, int index, int components) {
    const Json& accessor = doc.json["accessors"][index];
    std::size_t stride = 0;
    const std::size_t count = accessor.at("count");
    const unsigned char* data = accessor.at("componentType") == 5126 && !accessor.count("sparse")
                                    ? accessorData(doc, accessor, 4 * components, stride)
                                    : nullptr;
    if (!data) {
        ADD_FAILURE() << "not a plain float accessor: " << accessor.dump();
        return {};
    }
    std::vector<float> out(count * components);
    for (std::size_t i = 0; i < count; ++i) {
        std::memcpy(&out[i * components], data + i * stride, 4 * components);
    }
    return out;
}

std::vector<uint32_t> readIndices(const Document& doc, const Json& primitive,
                                  std::size_t vertices) {
    std::vector<uint32_t> out;
    if (!primitive.count("indices")) {
        for (uint32_t i = 0; i < vertices; ++i) {
            out.push_back(i);
        }
        return out;
    }
    const Json& accessor = doc.json["accessors"][primitive["indices"].get<int>()];
    const int type = accessor.at("componentType");
    const std::size_t size = type == 5121 ? 1 : type == 5123 ? 2 : 4;
    std::size_t stride = 0;
    const unsigned char* data = accessorData(doc, accessor, size, stride);
    for (std::size_t i = 0; data && i < accessor.at("count").get<std::size_t>(); ++i) {
        uint32_t value = 0;
        std::memcpy(&value, data + i * stride, size); // little-endian, as glTF is
        out.push_back(value);
    }
    return out;
}

void require(Json& json, const char* extension) {
    for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
        Json& list = json[key];
        if (std::find(list.begin(), list.end(), extension) == list.end()) {
            list.push_back(extension);
        }
    }
}

const char* accessorType(int components) {
    return components == 2 ? "VEC2" : "VEC3";
}

void dracoPrimitive(Document& out, Json& primitive, const std::vector<Attribute>& attributes,
                    const std::vector<uint32_t>& indices) {
    DracoInput input;
    for (const Attribute& a : attributes) {
        DracoInput::Attribute& d = input.attributes.emplace_back();
        d.position = a.name == "POSITION";
        d.normal = a.name == "NORMAL";
        d.texcoord = a.name == "TEXCOORD_0";
        d.components = a.components;
        d.floats = a.values;
        d.quantizationBits = d.position ? 14 : d.normal ? 10 : 12;
    }
    input.indices = indices;
    const DracoOutput encoded = encodeDracoMesh(input);
    if (!encoded.error.empty()) {
        ADD_FAILURE() << "Draco: " << encoded.error;
        return;
    }
    Json ids = Json::object();
    for (std::size_t i = 0; i < attributes.size(); ++i) {
        primitive["attributes"][attributes[i].name] =
            out.accessor({{"componentType", 5126}, {"count", encoded.points},
                          {"type", accessorType(attributes[i].components)}});
        ids[attributes[i].name] = encoded.ids[i];
    }
    primitive["indices"] = out.accessor({{"componentType", encoded.points > 65535 ? 5125 : 5123},
                                         {"count", encoded.faces * 3}, {"type", "SCALAR"}});
    const Json draco = {{"bufferView", out.rawView(encoded.bytes.data(), encoded.bytes.size())},
                        {"attributes", ids}};
    primitive["extensions"] = Json::object({{"KHR_draco_mesh_compression", draco}});
}

// `fallback`: bytes of the fallback buffer used so far.
void meshoptPrimitive(Document& out, Json& primitive, const std::vector<Attribute>& attributes,
                      const std::vector<uint32_t>& indices, std::size_t& fallback) {
    const char* ext = "KHR_meshopt_compression";
    const std::size_t n = attributes[0].values.size() / 3;
    for (const Attribute& a : attributes) {
        Json accessor = {{"count", n}, {"type", accessorType(a.components)}};
        int view = 0;
        if (a.name == "NORMAL") {
            std::vector<float> padded(n * 4, 0.0f);
            for (std::size_t i = 0; i < n * 3; ++i) {
                padded[i / 3 * 4 + i % 3] = a.values[i];
            }
            std::vector<int8_t> octahedral(n * 4);
            meshopt_encodeFilterOct(octahedral.data(), n, 4, 8, padded.data());
            view = meshoptView(out, ext, encodeVertices(octahedral.data(), n, 4), 4, n,
                               "ATTRIBUTES", "OCTAHEDRAL", fallback);
            accessor.update({{"componentType", 5120}, {"normalized", true}});
        } else if (a.name == "TEXCOORD_0" &&
                   std::all_of(a.values.begin(), a.values.end(),
                               [](float v) { return v >= 0.0f && v <= 1.0f; })) {
            std::vector<uint16_t> quantized(n * 2);
            for (std::size_t i = 0; i < n * 2; ++i) {
                quantized[i] = uint16_t(std::lround(a.values[i] * 65535.0f));
            }
            view = meshoptView(out, ext, encodeVertices(quantized.data(), n, 4), 4, n,
                               "ATTRIBUTES", nullptr, fallback);
            accessor.update({{"componentType", 5123}, {"normalized", true}});
        } else {
            const std::size_t size = 4 * a.components;
            std::vector<uint32_t> exponential(n * a.components);
            meshopt_encodeFilterExp(exponential.data(), n, size, 16, a.values.data());
            view = meshoptView(out, ext, encodeVertices(exponential.data(), n, size), size, n,
                               "ATTRIBUTES", "EXPONENTIAL", fallback);
            accessor["componentType"] = 5126;
        }
        accessor["bufferView"] = view;
        primitive["attributes"][a.name] = out.accessor(accessor);
    }
    std::vector<unsigned char> triangles(meshopt_encodeIndexBufferBound(indices.size(), n));
    triangles.resize(meshopt_encodeIndexBuffer(triangles.data(), triangles.size(),
                                               indices.data(), indices.size()));
    const std::size_t stride = n > 65535 ? 4 : 2;
    const int view = meshoptView(out, ext, triangles, stride, indices.size(), "TRIANGLES",
                                 nullptr, fallback);
    primitive["indices"] = out.accessor({{"bufferView", view},
                                         {"componentType", stride == 4 ? 5125 : 5123},
                                         {"count", indices.size()},
                                         {"type", "SCALAR"}});
}

} // namespace

Document readGltf(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    Document doc;
    doc.json = Json::parse(text.str());
    const std::string uri = doc.json.at("buffers").at(0).at("uri");
    EXPECT_EQ(doc.json["buffers"].size(), 1u) << path;
    EXPECT_EQ(uri.rfind("data:", 0), 0u) << path << ": the buffer is no data: URI";
    doc.bin = decodeBase64(uri.substr(uri.find(',') + 1));
    doc.json.erase("buffers");
    return doc;
}

Document compressedCopy(const Document& original, MeshCodec codec) {
    Document out;
    out.json = original.json;
    out.json["accessors"] = Json::array();
    out.json["bufferViews"] = Json::array();
    Json& images = out.json["images"]; // images in bufferViews move to the new ones
    for (Json& image : images) {
        if (image.contains("bufferView")) {
            const Json& view = original.json["bufferViews"][image["bufferView"].get<int>()];
            image["bufferView"] =
                out.rawView(original.bin.data() + view.value("byteOffset", 0), view["byteLength"]);
        }
    }
    if (images.empty()) {
        out.json.erase("images");
    }
    std::size_t fallback = 0;
    for (Json& mesh : out.json["meshes"]) {
        for (Json& primitive : mesh["primitives"]) {
            EXPECT_EQ(primitive.value("mode", 4), 4) << "triangle lists only";
            std::vector<Attribute> attributes;
            for (const auto& [name, components] :
                 {std::pair<std::string, int>{"POSITION", 3}, {"NORMAL", 3}, {"TEXCOORD_0", 2}}) {
                if (primitive["attributes"].count(name)) {
                    const int index = primitive["attributes"][name];
                    attributes.push_back(
                        {name, components, readFloats(original, index, components)});
                }
            }
            if (primitive["attributes"].size() != attributes.size() ||
                attributes.empty() || attributes[0].name != "POSITION") {
                ADD_FAILURE() << "not POSITION and only NORMAL, TEXCOORD_0: " << primitive.dump();
                continue;
            }
            const std::vector<uint32_t> indices =
                readIndices(original, primitive, attributes[0].values.size() / 3);
            if (codec == MeshCodec::Draco) {
                dracoPrimitive(out, primitive, attributes, indices);
            } else {
                meshoptPrimitive(out, primitive, attributes, indices, fallback);
            }
        }
    }
    if (codec == MeshCodec::Draco) {
        require(out.json, "KHR_draco_mesh_compression");
    } else {
        require(out.json, "KHR_meshopt_compression");
        require(out.json, "KHR_mesh_quantization");
        const Json marker = Json::object({{"fallback", true}});
        out.moreBuffers.push_back(
            {{"byteLength", fallback},
             {"extensions", Json::object({{"KHR_meshopt_compression", marker}})}});
    }
    return out;
}

} // namespace wf::test
