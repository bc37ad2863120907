// tinygltf parses the JSON and fetches buffers through the file-system hooks below; nothing
// in the parsed model is trusted: every index, offset, stride and count is checked against
// the arrays and buffer sizes before a byte is read (tinygltf 2.7.0 checks few of them).
#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <unordered_map>

#include "errors.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

constexpr uintmax_t MAX_FILE_BYTES = uintmax_t(1) << 30;
// Far above what the GPU buffers hold; it only stops a small file that instances a big mesh
// from thousands of nodes from exhausting memory here.
constexpr size_t MAX_TRIANGLES = size_t(1) << 26;

// tinygltf's messages become one line; they may quote a whole data: URI, so long ones are
// cut to keep the error readable.
std::string collapseLines(const std::string& text) {
    constexpr size_t MAX_CHARS = 400;
    std::string out;
    for (char c : text) {
        if (out.size() >= MAX_CHARS) {
            out += "...";
            break;
        }
        bool lineBreak = c == '\n' || c == '\r';
        if (lineBreak && !out.empty() && out.back() != ' ') {
            out += "; ";
        } else if (!lineBreak) {
            out += c;
        }
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) {
        out.pop_back();
    }
    return out;
}

// --- File access: tinygltf may read only regular files inside the scene's folder. ---

struct FsPolicy {
    fs::path folder;     // canonical
    std::string refusal; // first refused path and why, for the error message
};

// tinygltf asks for "<base dir>/<uri>" and then "./<uri>"; both are taken relative to the
// scene's folder, never to the working directory.
std::optional<fs::path> resolveInFolder(FsPolicy& policy, const std::string& requested) {
    std::string uri = requested;
    std::string prefix = policy.folder.string();
    if (prefix.empty() || prefix.back() != '/') {
        prefix += '/';
    }
    if (uri.rfind(prefix, 0) == 0) {
        uri.erase(0, prefix.size());
    } else if (uri.rfind("./", 0) == 0) {
        uri.erase(0, 2);
    }
    auto refuse = [&](const std::string& why) -> std::optional<fs::path> {
        if (policy.refusal.empty()) {
            policy.refusal = "refused to read '" + uri + "': " + why;
        }
        return std::nullopt;
    };
    const fs::path relative(uri);
    if (uri.empty() || relative.is_absolute() || relative.has_root_path()) {
        return refuse("only paths relative to the scene's folder are allowed");
    }
    for (const fs::path& part : relative) {
        if (part == "..") {
            return refuse("'..' is not allowed in paths");
        }
    }
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(policy.folder / relative, ec);
    if (ec) {
        return refuse(ec.message());
    }
    // A symbolic link may still lead out of the folder: compare the canonical paths.
    auto [folderEnd, unused] = std::mismatch(policy.folder.begin(), policy.folder.end(),
                                             resolved.begin(), resolved.end());
    if (folderEnd != policy.folder.end()) {
        return refuse("it resolves outside the scene's folder");
    }
    return resolved;
}

bool fileExists(const std::string& path, void* userData) {
    std::optional<fs::path> resolved = resolveInFolder(*static_cast<FsPolicy*>(userData), path);
    std::error_code ec;
    return resolved && fs::is_regular_file(*resolved, ec);
}

std::string expandFilePath(const std::string& path, void*) {
    return path; // no "~" or environment expansion: URIs are plain relative paths
}

// Reads a whole regular file of at most MAX_FILE_BYTES; `error` says why not otherwise.
bool readLimited(const fs::path& path, std::vector<unsigned char>& out, std::string& error) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        error = "not found or not a regular file";
        return false;
    }
    const uintmax_t size = fs::file_size(path, ec);
    if (ec || size > MAX_FILE_BYTES) {
        error = ec ? ec.message() : "larger than 1 GiB";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out.resize(static_cast<size_t>(size));
    if (!in || !in.read(reinterpret_cast<char*>(out.data()), std::streamsize(size))) {
        error = "read failed";
        return false;
    }
    return true;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* userData) {
    std::optional<fs::path> resolved = resolveInFolder(*static_cast<FsPolicy*>(userData), path);
    std::string why = "outside the scene's folder";
    if (resolved && readLimited(*resolved, *out, why)) {
        return true;
    }
    *err += why;
    return false;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    *err += "writing is disabled";
    return false;
}

// Textures are not used yet: accepting every image undecoded keeps stb_image (and the
// unchecked image bufferView offsets tinygltf hands it) away from untrusted bytes.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

// tinygltf's JSON parser recurses once per nesting level, so a file of a few megabytes of
// "[[[[..." would overflow the stack; glTF itself needs fewer than ten levels.
bool nestedTooDeep(const unsigned char* text, size_t length) {
    constexpr int MAX_DEPTH = 256;
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < length; ++i) {
        const unsigned char c = text[i];
        if (inString) {
            i += c == '\\' ? 1 : 0; // skip the escaped character
            inString = c != '"';
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > MAX_DEPTH) {
                return true;
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return false;
}

// --- Model to Scene. ---

struct AccessorData {
    const unsigned char* bytes = nullptr;
    size_t count = 0;
    size_t stride = 0;
    int componentType = 0;
};

size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

bool allFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) {
                return false;
            }
        }
    }
    return true;
}

// Row r, column c of the rotation of a unit quaternion (x, y, z, w), as glm's m[c][r].
glm::dmat4 rotationMatrix(double x, double y, double z, double w) {
    glm::dmat4 m(1.0);
    m[0][0] = 1 - 2 * (y * y + z * z);
    m[1][0] = 2 * (x * y - w * z);
    m[2][0] = 2 * (x * z + w * y);
    m[0][1] = 2 * (x * y + w * z);
    m[1][1] = 1 - 2 * (x * x + z * z);
    m[2][1] = 2 * (y * z - w * x);
    m[0][2] = 2 * (x * z - w * y);
    m[1][2] = 2 * (y * z + w * x);
    m[2][2] = 1 - 2 * (x * x + y * y);
    return m;
}

// The GPU normalizes cross(p1 - p0, p2 - p0) in float; a triangle whose float cross product
// has no normal-range length would give it a NaN normal, so such triangles count as zero area.
bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    return !(glm::dot(n, n) >= std::numeric_limits<float>::min());
}

class Converter {
public:
    Converter(const tinygltf::Model& model, const std::string& file) : model_(model), file_(file) {}
    Scene run();

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw InputError(file_ + ": " + problem);
    }
    void checkIndex(int index, size_t size, const std::string& what, const std::string& by) const {
        if (index < 0 || size_t(index) >= size) {
            fail(by + " refers to " + what + " " + std::to_string(index) +
                 ", which does not exist (the file has " + std::to_string(size) + ")");
        }
    }
    void convertMaterials();
    void checkNodeTree();
    std::vector<int> rootNodes() const;
    glm::dmat4 localTransform(int nodeIndex) const;
    void addCamera(int nodeIndex, const glm::dmat4& world);
    void addPrimitive(const tinygltf::Primitive& primitive, const std::string& where,
                      const glm::dmat4& world);
    AccessorData accessorData(int index, const std::string& role, int type);
    const std::vector<glm::vec3>& positions(int accessor, const std::string& where);
    std::vector<uint32_t> indices(int accessor, size_t vertexCount, const std::string& where);

    const tinygltf::Model& model_;
    const std::string& file_;
    Scene scene_;
    std::vector<int> parent_;
    std::unordered_map<int, std::vector<glm::vec3>> positionCache_;
    std::optional<uint32_t> defaultMaterial_;
    size_t skippedPrimitives_ = 0;
    size_t degenerateTriangles_ = 0;
};

void Converter::convertMaterials() {
    for (size_t i = 0; i < model_.materials.size(); ++i) {
        const tinygltf::Material& m = model_.materials[i];
        const std::string name = "material " + std::to_string(i);
        const std::vector<double>& base = m.pbrMetallicRoughness.baseColorFactor;
        const std::vector<double>& emissive = m.emissiveFactor;
        if (base.size() != 4 || emissive.size() != 3) {
            fail(name + ": baseColorFactor needs 4 numbers and emissiveFactor 3");
        }
        double strength = 1.0;
        auto ext = m.extensions.find("KHR_materials_emissive_strength");
        if (ext != m.extensions.end() && ext->second.Has("emissiveStrength")) {
            const tinygltf::Value& value = ext->second.Get("emissiveStrength");
            strength = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
        }
        Material out{};
        for (int c = 0; c < 4; ++c) {
            if (!(base[c] >= 0.0 && base[c] <= 1.0)) { // albedo > 1 would create energy
                fail(name + ": baseColorFactor must lie in [0, 1]");
            }
            out.baseColor[c] = float(base[c]);
        }
        for (int c = 0; c < 3; ++c) {
            out.emission[c] = float(emissive[c] * strength);
            if (!(emissive[c] >= 0.0 && strength >= 0.0 && std::isfinite(out.emission[c]))) {
                fail(name + ": emissiveFactor and emissiveStrength must be finite and >= 0");
            }
        }
        out.flags = m.doubleSided ? WF_MATERIAL_DOUBLE_SIDED : 0u;
        scene_.materials.push_back(out);
    }
}

// Each node may have one parent, so following parents from any node either reaches a root
// or loops; one walk per node with "seen in walk k" marks finds loops in linear time.
void Converter::checkNodeTree() {
    const size_t n = model_.nodes.size();
    parent_.assign(n, -1);
    for (size_t i = 0; i < n; ++i) {
        const std::string name = "node " + std::to_string(i);
        for (int child : model_.nodes[i].children) {
            checkIndex(child, n, "child node", name);
            if (parent_[child] != -1) {
                fail("node " + std::to_string(child) + " has two parents (nodes " +
                     std::to_string(parent_[child]) + " and " + std::to_string(i) + ")");
            }
            parent_[child] = int(i);
        }
    }
    std::vector<size_t> walk(n, 0);
    for (size_t start = 0; start < n; ++start) {
        int node = int(start);
        while (node != -1 && walk[node] == 0) {
            walk[node] = start + 1;
            node = parent_[node];
        }
        if (node != -1 && walk[node] == start + 1) {
            fail("node " + std::to_string(node) + " is its own ancestor (a cycle of nodes)");
        }
    }
}

std::vector<int> Converter::rootNodes() const {
    int sceneIndex = model_.defaultScene;
    if (sceneIndex >= 0) {
        checkIndex(sceneIndex, model_.scenes.size(), "scene", "the default scene");
    } else if (!model_.scenes.empty()) {
        sceneIndex = 0;
    }
    std::vector<int> roots;
    if (sceneIndex < 0) {
        for (size_t i = 0; i < parent_.size(); ++i) {
            if (parent_[i] == -1) {
                roots.push_back(int(i));
            }
        }
        return roots;
    }
    const std::string name = "scene " + std::to_string(sceneIndex);
    for (int root : model_.scenes[sceneIndex].nodes) {
        checkIndex(root, model_.nodes.size(), "node", name);
        if (parent_[root] != -1) {
            fail(name + " lists node " + std::to_string(root) + ", which is a child of node " +
                 std::to_string(parent_[root]));
        }
        roots.push_back(root);
    }
    return roots;
}

glm::dmat4 Converter::localTransform(int nodeIndex) const {
    const tinygltf::Node& node = model_.nodes[nodeIndex];
    const std::string name = "node " + std::to_string(nodeIndex);
    glm::dmat4 m(1.0);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) {
            fail(name + ": matrix needs 16 numbers");
        }
        for (int i = 0; i < 16; ++i) {
            m[i / 4][i % 4] = node.matrix[i]; // column-major in glTF and glm alike
        }
    } else {
        const auto& t = node.translation;
        const auto& r = node.rotation;
        const auto& s = node.scale;
        if ((!t.empty() && t.size() != 3) || (!r.empty() && r.size() != 4) ||
            (!s.empty() && s.size() != 3)) {
            fail(name + ": translation and scale need 3 numbers, rotation 4");
        }
        if (!t.empty()) {
            m[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
        }
        if (!r.empty()) {
            // Exporters write quaternions rounded to a few digits; renormalize so the
            // rotation stays a rotation.
            const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
            if (!(len > 0.0) || !std::isfinite(len)) {
                fail(name + ": rotation is not a usable quaternion");
            }
            m = m * rotationMatrix(r[0] / len, r[1] / len, r[2] / len, r[3] / len);
        }
        if (!s.empty()) {
            m = m * glm::dmat4(glm::dvec4(s[0], 0, 0, 0), glm::dvec4(0, s[1], 0, 0),
                               glm::dvec4(0, 0, s[2], 0), glm::dvec4(0, 0, 0, 1));
        }
    }
    if (!allFinite(m)) {
        fail(name + ": transform is not finite");
    }
    return m;
}

void Converter::addCamera(int nodeIndex, const glm::dmat4& world) {
    const tinygltf::Node& node = model_.nodes[nodeIndex];
    const std::string name = "node " + std::to_string(nodeIndex);
    checkIndex(node.camera, model_.cameras.size(), "camera", name);
    const tinygltf::Camera& camera = model_.cameras[node.camera];
    if (scene_.hasCamera || camera.type != "perspective") {
        return;
    }
    const double yfov = camera.perspective.yfov;
    const double aspect = camera.perspective.aspectRatio;
    if (!(yfov > 0.0 && yfov < M_PI) || !(aspect >= 0.0 && std::isfinite(aspect))) {
        fail("camera " + std::to_string(node.camera) + ": yfov must lie in (0, pi) and " +
             "aspectRatio be positive");
    }
    // glTF cameras look down -Z with +Y up; Gram-Schmidt removes any shear from scaling.
    const glm::dvec3 forward = glm::normalize(-glm::dvec3(world[2]));
    const glm::dvec3 upRaw = glm::dvec3(world[1]);
    const glm::dvec3 up = glm::normalize(upRaw - glm::dot(upRaw, forward) * forward);
    if (!std::isfinite(forward.x + forward.y + forward.z + up.x + up.y + up.z)) {
        fail(name + ": the camera's transform is degenerate");
    }
    scene_.camera.position = glm::vec3(world[3]);
    scene_.camera.forward = glm::vec3(forward);
    scene_.camera.up = glm::vec3(up);
    scene_.camera.yfov = float(yfov);
    scene_.camera.aspect = float(aspect);
    scene_.hasCamera = true;
}

AccessorData Converter::accessorData(int index, const std::string& role, int type) {
    checkIndex(index, model_.accessors.size(), "accessor", role);
    const tinygltf::Accessor& acc = model_.accessors[index];
    const std::string name = "accessor " + std::to_string(index) + " (" + role + ")";
    const bool vec3 = type == TINYGLTF_TYPE_VEC3;
    if (acc.type != type) {
        fail(name + " has the wrong type (" + (vec3 ? "VEC3" : "SCALAR") + " expected)");
    }
    if (acc.sparse.isSparse) {
        fail(name + " is sparse, which is not supported");
    }
    if (acc.bufferView == -1) {
        fail(name + " has no bufferView, which is not supported");
    }
    checkIndex(acc.bufferView, model_.bufferViews.size(), "bufferView", name);
    const tinygltf::BufferView& view = model_.bufferViews[acc.bufferView];
    const std::string viewName = "bufferView " + std::to_string(acc.bufferView);
    checkIndex(view.buffer, model_.buffers.size(), "buffer", viewName);
    const size_t bufferSize = model_.buffers[view.buffer].data.size();
    if (view.byteLength > bufferSize || view.byteOffset > bufferSize - view.byteLength) {
        fail(viewName + " extends past the end of buffer " + std::to_string(view.buffer) + " (" +
             std::to_string(bufferSize) + " bytes)");
    }
    const size_t elementSize = componentSize(acc.componentType) * (vec3 ? 3 : 1);
    const size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (elementSize == 0 || stride < elementSize) {
        fail(name + ": bad componentType or byteStride smaller than one element");
    }
    const size_t length = view.byteLength;
    if (acc.count > 0 &&
        (acc.byteOffset > length || elementSize > length - acc.byteOffset ||
         (acc.count - 1) > (length - acc.byteOffset - elementSize) / stride)) {
        fail(name + ": " + std::to_string(acc.count) + " elements extend past the end of " +
             viewName + " (" + std::to_string(length) + " bytes)");
    }
    const unsigned char* base = model_.buffers[view.buffer].data.data() + view.byteOffset;
    return {base + acc.byteOffset, acc.count, stride, acc.componentType};
}

const std::vector<glm::vec3>& Converter::positions(int accessor, const std::string& where) {
    auto cached = positionCache_.find(accessor);
    if (cached != positionCache_.end()) {
        return cached->second;
    }
    AccessorData data = accessorData(accessor, "POSITION of " + where, TINYGLTF_TYPE_VEC3);
    if (data.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
        fail("accessor " + std::to_string(accessor) + " (POSITION of " + where +
             ") must hold floats");
    }
    std::vector<glm::vec3> points(data.count);
    for (size_t i = 0; i < data.count; ++i) {
        float xyz[3];
        std::memcpy(xyz, data.bytes + i * data.stride, sizeof(xyz)); // may be unaligned
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
            fail("accessor " + std::to_string(accessor) + " (POSITION of " + where +
                 ") has a NaN or infinite coordinate in element " + std::to_string(i));
        }
        points[i] = glm::vec3(xyz[0], xyz[1], xyz[2]);
    }
    return positionCache_.emplace(accessor, std::move(points)).first->second;
}

std::vector<uint32_t> Converter::indices(int accessor, size_t vertexCount,
                                         const std::string& where) {
    AccessorData data = accessorData(accessor, "indices of " + where, TINYGLTF_TYPE_SCALAR);
    const size_t size = componentSize(data.componentType);
    if (data.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        data.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        data.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        fail("accessor " + std::to_string(accessor) + " (indices of " + where +
             ") must hold unsigned 8, 16 or 32-bit integers");
    }
    std::vector<uint32_t> out(data.count);
    for (size_t i = 0; i < data.count; ++i) {
        const unsigned char* p = data.bytes + i * data.stride;
        uint32_t u32 = 0;
        if (size == 1) {
            u32 = p[0];
        } else if (size == 2) {
            uint16_t u16 = 0;
            std::memcpy(&u16, p, 2); // little-endian file, little-endian host
            u32 = u16;
        } else {
            std::memcpy(&u32, p, 4);
        }
        if (u32 >= vertexCount) {
            fail("accessor " + std::to_string(accessor) + " (indices of " + where +
                 "): element " + std::to_string(i) + " is " + std::to_string(u32) +
                 ", but there are only " + std::to_string(vertexCount) + " vertices");
        }
        out[i] = u32;
    }
    return out;
}

void Converter::addPrimitive(const tinygltf::Primitive& primitive, const std::string& where,
                             const glm::dmat4& world) {
    if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
        ++skippedPrimitives_;
        return;
    }
    auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) {
        fail(where + " has no POSITION attribute");
    }
    const std::vector<glm::vec3>& points = positions(position->second, where);
    uint32_t material = 0;
    if (primitive.material == -1) {
        if (!defaultMaterial_) {
            defaultMaterial_ = uint32_t(model_.materials.size());
        }
        material = *defaultMaterial_;
    } else {
        checkIndex(primitive.material, model_.materials.size(), "material", where);
        material = uint32_t(primitive.material);
    }
    const bool indexed = primitive.indices != -1;
    const std::vector<uint32_t> order =
        indexed ? indices(primitive.indices, points.size(), where) : std::vector<uint32_t>{};
    const size_t count = indexed ? order.size() : points.size();
    if (count % 3 != 0) {
        fail(where + ": " + std::to_string(count) + " vertices do not make whole triangles");
    }
    // A mirroring transform turns counter-clockwise into clockwise; swapping two vertices
    // keeps the front face where the file meant it.
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    auto vertex = [&](size_t i) {
        const glm::dvec4 p = world * glm::dvec4(points[indexed ? order[i] : i], 1.0);
        const glm::vec3 v(p);
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
            fail(where + ": a vertex is not finite after the node transforms");
        }
        return v;
    };
    for (size_t i = 0; i < count; i += 3) {
        glm::vec3 a = vertex(i), b = vertex(i + 1), c = vertex(i + 2);
        if (mirrored) {
            std::swap(b, c);
        }
        if (isDegenerate(a, b, c)) {
            ++degenerateTriangles_;
            continue;
        }
        if (scene_.triangles.size() >= MAX_TRIANGLES) {
            fail("more than " + std::to_string(MAX_TRIANGLES) + " triangles");
        }
        scene_.triangles.push_back(Triangle{a, material, b, WF_NO_EMITTER, c, 0u});
    }
}

Scene Converter::run() {
    for (const std::string& ext : model_.extensionsRequired) {
        if (ext != "KHR_materials_emissive_strength") {
            fail("requires glTF extension " + ext + ", which is not supported");
        }
    }
    convertMaterials();
    checkNodeTree();
    // Depth-first, children in file order, without recursion so deep trees cannot overflow
    // the stack; checkNodeTree guarantees each node is reached at most once from the roots.
    std::vector<std::pair<int, glm::dmat4>> stack;
    const std::vector<int> roots = rootNodes();
    std::vector<bool> visited(model_.nodes.size(), false);
    for (auto root = roots.rbegin(); root != roots.rend(); ++root) {
        stack.emplace_back(*root, glm::dmat4(1.0));
    }
    while (!stack.empty()) {
        auto [index, parentWorld] = stack.back();
        stack.pop_back();
        if (visited[index]) {
            fail("node " + std::to_string(index) + " is listed twice in the scene");
        }
        visited[index] = true;
        const glm::dmat4 world = parentWorld * localTransform(index);
        const tinygltf::Node& node = model_.nodes[index];
        const std::string name = "node " + std::to_string(index);
        if (node.camera != -1) {
            addCamera(index, world);
        }
        if (node.mesh != -1) {
            checkIndex(node.mesh, model_.meshes.size(), "mesh", name);
            const auto& primitives = model_.meshes[node.mesh].primitives;
            for (size_t p = 0; p < primitives.size(); ++p) {
                addPrimitive(primitives[p], "mesh " + std::to_string(node.mesh) + " primitive " +
                             std::to_string(p), world);
            }
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
            stack.emplace_back(*child, world);
        }
    }
    if (defaultMaterial_ || scene_.materials.empty()) {
        const Material grey{glm::vec4(0.8f, 0.8f, 0.8f, 1.0f), glm::vec3(0.0f), 0u};
        scene_.materials.push_back(grey);
    }
    if (skippedPrimitives_ > 0) {
        std::cerr << "warning: " << file_ << ": skipped " << skippedPrimitives_
                  << " primitives that are not triangle lists (mode 4)\n";
    }
    if (degenerateTriangles_ > 0) {
        std::cerr << "note: " << file_ << ": dropped " << degenerateTriangles_
                  << " degenerate triangles\n";
    }
    return std::move(scene_);
}

} // namespace

Scene loadGltf(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) {
        return char(std::tolower(c));
    });
    if (ext != ".gltf" && ext != ".glb") {
        throw InputError(path + ": expected a .gltf or .glb file");
    }
    std::vector<unsigned char> bytes;
    std::string why;
    if (!readLimited(path, bytes, why)) {
        throw InputError(path + ": cannot read scene: " + why);
    }
    const size_t size = bytes.size();
    const bool binary = size >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (ext == ".glb" && !binary) {
        throw InputError(path + ": not a binary glTF file (no 'glTF' magic)");
    }
    size_t jsonStart = 0, jsonLength = size;
    if (binary && size >= 20) {
        uint32_t chunkLength = 0; // the JSON chunk's length; tinygltf checks it against size
        std::memcpy(&chunkLength, bytes.data() + 12, 4);
        jsonStart = 20;
        jsonLength = std::min<size_t>(chunkLength, size - 20);
    }
    if (nestedTooDeep(bytes.data() + jsonStart, jsonLength)) {
        throw InputError(path + ": JSON nested more than 256 levels deep");
    }
    // tinygltf 2.7.0's GLB chunk check forgets the 8-byte chunk header, so it may read up to
    // 8 bytes past the end; zero padding makes that harmless.
    bytes.resize(size + 16, 0);

    std::error_code ec;
    FsPolicy policy{fs::weakly_canonical(fs::absolute(path).parent_path(), ec), {}};
    if (ec) {
        throw InputError(path + ": cannot resolve the scene's folder: " + ec.message());
    }
    tinygltf::TinyGLTF gltf;
    gltf.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &refuseWrite, &policy});
    gltf.SetImageLoader(&skipImage, nullptr);
    tinygltf::Model model;
    std::string err, warn;
    bool loaded = false;
    try {
        const std::string base = policy.folder.string();
        loaded = binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                    unsigned(size), base)
                        : gltf.LoadASCIIFromString(&model, &err, &warn,
                                                   reinterpret_cast<const char*>(bytes.data()),
                                                   unsigned(size), base);
    } catch (const std::exception& e) {
        err += e.what();
    }
    const std::string messages = collapseLines(err + "\n" + warn);
    if (!loaded) {
        // A refused path explains a "File not found" better than tinygltf can.
        std::string problem = messages.empty() ? "cannot parse glTF" : messages;
        if (!policy.refusal.empty()) {
            problem = policy.refusal + " (tinygltf: " + problem + ")";
        }
        throw InputError(path + ": " + problem);
    }
    if (!messages.empty()) {
        std::cerr << "warning: " << path << ": " << messages << "\n";
    }
    return Converter(model, path).run();
}

} // namespace wf
