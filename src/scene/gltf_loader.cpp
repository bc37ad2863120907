// glTF model to Scene: walks the default scene's node tree, converts materials and the first
// perspective camera, and flattens triangle primitives into world space. tinygltf parses the
// JSON through the hooks in gltf_file_access; nothing in the parsed model is trusted, and the
// accessor bounds checks live in gltf_accessors (tinygltf 2.7.0 checks few of them).
#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>

#include "errors.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_file_access.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

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

// --- Model to Scene. ---

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
    Converter(const tinygltf::Model& model, const std::string& file)
        : model_(model), file_(file), reader_(model, file) {}
    Scene run();

private:
    [[noreturn]] void fail(const std::string& problem) const { gltf::fail(file_, problem); }
    void checkIndex(int index, size_t size, const std::string& what, const std::string& by) const {
        gltf::checkIndex(file_, index, size, what, by);
    }
    void convertMaterials();
    void checkNodeTree();
    std::vector<int> rootNodes() const;
    glm::dmat4 localTransform(int nodeIndex) const;
    void addCamera(int nodeIndex, const glm::dmat4& world);
    void addPrimitive(const tinygltf::Primitive& primitive, const std::string& where,
                      const glm::dmat4& world);
    const tinygltf::Model& model_;
    const std::string& file_;
    Scene scene_;
    std::vector<int> parent_;
    gltf::AccessorReader reader_;
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
    const std::vector<glm::vec3>& points = reader_.positions(position->second, where);
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
        indexed ? reader_.indices(primitive.indices, points.size(), where)
                : std::vector<uint32_t>{};
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
    if (!gltf::readLimited(path, bytes, why)) {
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
    if (gltf::nestedTooDeep(bytes.data() + jsonStart, jsonLength)) {
        throw InputError(path + ": JSON nested more than " + std::to_string(gltf::MAX_JSON_DEPTH) +
                         " levels deep");
    }
    // tinygltf 2.7.0's GLB chunk check forgets the 8-byte chunk header, so it may read up to
    // 8 bytes past the end; zero padding makes that harmless.
    bytes.resize(size + 16, 0);

    std::error_code ec;
    gltf::FsPolicy policy{fs::weakly_canonical(fs::absolute(path).parent_path(), ec), {}};
    if (ec) {
        throw InputError(path + ": cannot resolve the scene's folder: " + ec.message());
    }
    tinygltf::TinyGLTF parser;
    gltf::restrictFileAccess(parser, policy);
    tinygltf::Model model;
    std::string err, warn;
    bool loaded = false;
    try {
        const std::string base = policy.folder.string();
        loaded = binary ? parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                      unsigned(size), base)
                        : parser.LoadASCIIFromString(&model, &err, &warn,
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
