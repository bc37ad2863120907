// Small glTF files written by tests: a temporary folder per test and a document built piece
// by piece (the loader's tests break its members on purpose; render tests make scenes).
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace wf::test {

constexpr int U8 = 5121, U16 = 5123, U32 = 5125, F32 = 5126;

// A fresh folder per test under the system temp dir, removed afterwards.
class TempDir {
public:
    TempDir() {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string("wf_gltf_") + test->test_suite_name() + "_" +
                           test->name() + "_" + std::to_string(::getpid());
        for (char& c : name) {
            c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        }
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    std::string path() const { return path_.string(); }

private:
    std::filesystem::path path_;
};

inline void writeBytes(const std::string& path, const std::vector<uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

inline std::string base64(const std::vector<uint8_t>& in) {
    static const char* digits =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        uint32_t v = uint32_t(in[i]) << 16;
        v |= i + 1 < in.size() ? uint32_t(in[i + 1]) << 8 : 0;
        v |= i + 2 < in.size() ? uint32_t(in[i + 2]) : 0;
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < in.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? digits[v & 63] : '=';
    }
    return out;
}

// The inverse of base64(); stops at the first character that is no digit ('=' or the end).
inline std::vector<uint8_t> decodeBase64(const std::string& in) {
    std::vector<uint8_t> out;
    uint32_t bits = 0;
    int count = 0;
    for (char c : in) {
        const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        const char* at = c ? std::strchr(digits, c) : nullptr;
        if (!at) {
            break;
        }
        bits = bits << 6 | uint32_t(at - digits);
        if ((count += 6) >= 8) {
            out.push_back(uint8_t(bits >> (count -= 8)));
        }
    }
    return out;
}

// A binary glTF: the JSON chunk (space-padded) and the BIN chunk (zero-padded).
inline std::vector<uint8_t> glbBytes(std::string json, std::vector<uint8_t> bin) {
    json.append((4 - json.size() % 4) % 4, ' ');
    bin.resize((bin.size() + 3) / 4 * 4, 0);
    auto u32 = [](std::vector<uint8_t>& out, uint32_t v) {
        for (int i = 0; i < 4; ++i) {
            out.push_back(uint8_t(v >> (8 * i)));
        }
    };
    std::vector<uint8_t> out = {'g', 'l', 'T', 'F'};
    u32(out, 2);
    u32(out, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    u32(out, uint32_t(json.size()));
    u32(out, 0x4E4F534A); // "JSON"
    out.insert(out.end(), json.begin(), json.end());
    u32(out, uint32_t(bin.size()));
    u32(out, 0x004E4942); // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

inline std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& item : items) {
        out += (out.empty() ? "" : ",") + item;
    }
    return "[" + out + "]";
}

// Builds a glTF document piece by piece; members are JSON text, so a test can break any of
// them on purpose.
struct MiniGltf {
    std::vector<uint8_t> bin;
    std::vector<std::string> views, accessors, meshes, nodes, materials, cameras;
    std::vector<std::string> images, textures; // written only when a test adds some
    std::string scenes = R"([{"nodes":[0]}])";
    std::string bufferUri; // empty: the buffer is embedded as a data: URI
    std::string extra;     // more top-level members, e.g. ",\"animations\":[...]"

    int addView(const void* data, size_t bytes, size_t stride = 0) {
        while (bin.size() % 4) {
            bin.push_back(0);
        }
        views.push_back("{\"buffer\":0,\"byteOffset\":" + std::to_string(bin.size()) +
                        ",\"byteLength\":" + std::to_string(bytes) +
                        (stride ? ",\"byteStride\":" + std::to_string(stride) : "") + "}");
        const auto* p = static_cast<const uint8_t*>(data);
        bin.insert(bin.end(), p, p + bytes);
        return int(views.size()) - 1;
    }
    int addAccessor(int view, int componentType, size_t count, const std::string& type,
                    size_t offset = 0) {
        accessors.push_back("{\"bufferView\":" + std::to_string(view) + ",\"byteOffset\":" +
                            std::to_string(offset) + ",\"componentType\":" +
                            std::to_string(componentType) + ",\"count\":" +
                            std::to_string(count) + ",\"type\":\"" + type + "\"}");
        return int(accessors.size()) - 1;
    }
    int addPositions(const std::vector<float>& xyz) {
        int view = addView(xyz.data(), xyz.size() * sizeof(float));
        return addAccessor(view, F32, xyz.size() / 3, "VEC3");
    }
    template <class T> int addIndices(const std::vector<T>& indices, int componentType) {
        int view = addView(indices.data(), indices.size() * sizeof(T));
        return addAccessor(view, componentType, indices.size(), "SCALAR");
    }
    // `attributes`: more members of the attributes object, e.g. ",\"NORMAL\":3".
    int addMesh(int positions, int indices = -1, int material = -1, int mode = 4,
                const std::string& attributes = "") {
        meshes.push_back("{\"primitives\":[{\"attributes\":{\"POSITION\":" +
                         std::to_string(positions) + attributes + "}" +
                         (indices >= 0 ? ",\"indices\":" + std::to_string(indices) : "") +
                         (material >= 0 ? ",\"material\":" + std::to_string(material) : "") +
                         ",\"mode\":" + std::to_string(mode) + "}]}");
        return int(meshes.size()) - 1;
    }
    std::string json(bool glb = false) const {
        std::string buffer = "{\"byteLength\":" + std::to_string(bin.size());
        if (!glb) {
            buffer += ",\"uri\":\"" +
                      (bufferUri.empty() ? "data:application/octet-stream;base64," + base64(bin)
                                         : bufferUri) +
                      "\"";
        }
        return "{\"asset\":{\"version\":\"2.0\"},\"scenes\":" + scenes +
               ",\"nodes\":" + join(nodes) + ",\"meshes\":" + join(meshes) +
               ",\"materials\":" + join(materials) + ",\"cameras\":" + join(cameras) +
               (images.empty() ? "" : ",\"images\":" + join(images)) +
               (textures.empty() ? "" : ",\"textures\":" + join(textures)) + extra +
               ",\"accessors\":" + join(accessors) + ",\"bufferViews\":" + join(views) +
               ",\"buffers\":[" + buffer + "}]}";
    }
    // Writes <dir>/<name>, and the buffer beside it when bufferUri names a plain file.
    std::string write(const TempDir& dir, const std::string& name = "scene.gltf") const {
        std::ofstream(dir.file(name)) << json();
        if (!bufferUri.empty() && bufferUri.find('/') == std::string::npos) {
            writeBytes(dir.file(bufferUri), bin);
        }
        return dir.file(name);
    }
    std::string writeGlb(const TempDir& dir, const std::string& name = "scene.glb") const {
        writeBytes(dir.file(name), glbBytes(json(true), bin));
        return dir.file(name);
    }
};

} // namespace wf::test
