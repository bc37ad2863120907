// glTF documents with compressed meshes, written by tests: a document whose buffer 0 is built
// piece by piece, and meshopt bufferViews decoding into a fallback buffer. The loader's unit
// tests (tests/unit/test_gltf_compression.cpp) and the GPU render tests
// (tests/gpu/compressed_copy.cpp) both write their files with these.
#pragma once
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "mini_gltf.h"

namespace wf::test {

using Json = nlohmann::json;

// A glTF document whose buffer 0 is `bin`, written as .glb or as .gltf with a data: URI.
struct Document {
    // Json::object and Json::array wherever a brace list has one element: compilers differ on
    // whether {x} copies x or makes a one-element array.
    Json json = {{"asset", Json::object({{"version", "2.0"}})},
                 {"scene", 0},
                 {"scenes", Json::array({Json::object({{"nodes", Json::array({0})}})})},
                 {"bufferViews", Json::array()},
                 {"accessors", Json::array()}};
    std::vector<unsigned char> bin;
    Json moreBuffers = Json::array();

    std::size_t raw(const void* data, std::size_t size) {
        bin.resize((bin.size() + 3) / 4 * 4, 0);
        const std::size_t offset = bin.size();
        bin.insert(bin.end(), static_cast<const unsigned char*>(data),
                   static_cast<const unsigned char*>(data) + size);
        return offset;
    }
    int view(Json v) {
        json["bufferViews"].push_back(std::move(v));
        return int(json["bufferViews"].size() - 1);
    }
    // A bufferView of buffer 0 holding a copy of `data`.
    int rawView(const void* data, std::size_t size) {
        return view({{"buffer", 0}, {"byteOffset", raw(data, size)}, {"byteLength", size}});
    }
    int accessor(Json a) {
        json["accessors"].push_back(std::move(a));
        return int(json["accessors"].size() - 1);
    }
    // Writes `path`: binary glTF when it ends in .glb, else JSON with the buffer inline.
    std::string write(const std::string& path) const {
        Json doc = json;
        doc["buffers"] = Json::array({Json::object({{"byteLength", bin.size()}})});
        for (const Json& b : moreBuffers) {
            doc["buffers"].push_back(b);
        }
        if (path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0) {
            writeBytes(path, glbBytes(doc.dump(), bin));
        } else {
            doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
            std::ofstream(path, std::ios::binary) << doc.dump();
        }
        return path;
    }
};

// One meshopt-compressed bufferView of `extension` (EXT_ or KHR_meshopt_compression) whose
// data sits in buffer 0 and decodes into the fallback buffer (1) at `target`, which it
// advances.
inline int meshoptView(Document& doc, const char* extension,
                       const std::vector<unsigned char>& data, std::size_t stride,
                       std::size_t count, const char* mode, const char* filter,
                       std::size_t& target) {
    Json ext = {{"buffer", 0}, {"byteOffset", doc.raw(data.data(), data.size())},
                {"byteLength", data.size()}, {"byteStride", stride}, {"count", count},
                {"mode", mode}};
    if (filter) {
        ext["filter"] = filter;
    }
    Json view = {{"buffer", 1}, {"byteOffset", target}, {"byteLength", stride * count},
                 {"extensions", Json::object({{extension, ext}})}};
    if (std::string(mode) == "ATTRIBUTES") {
        view["byteStride"] = stride;
    }
    target += (stride * count + 3) / 4 * 4;
    return doc.view(view);
}

// meshopt's vertex codec over `count` elements of `size` bytes.
inline std::vector<unsigned char> encodeVertices(const void* data, std::size_t count,
                                                 std::size_t size) {
    std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, size));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, count, size));
    return out;
}

} // namespace wf::test
