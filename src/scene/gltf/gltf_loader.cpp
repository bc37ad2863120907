// glTF model to Scene: walks the default scene's node tree (gltf_primitives flattens meshes,
// gltf_lights_cameras reads cameras and lights), converts materials (gltf_materials) and
// decodes the images they use (gltf_images). tinygltf parses the JSON through the hooks in
// gltf_file_access; nothing in the parsed model is trusted, and the accessor bounds checks live
// in gltf_accessors (tinygltf 2.7.0 checks few of them).
#include "scene/gltf/gltf_loader.h"

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
#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/gltf_buffer_streaming.h"
#include "scene/gltf/compression/gltf_compression.h"
#include "scene/gltf/gltf_file_access.h"
#include "scene/gltf/gltf_images.h"
#include "scene/gltf/gltf_instancing.h"
#include "scene/gltf/gltf_lights_cameras.h"
#include "scene/gltf/gltf_materials.h"
#include "scene/gltf/gltf_parse_messages.h"
#include "scene/gltf/gltf_primitives.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

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

class Converter {
public:
    Converter(const tinygltf::Model& model, const std::string& file, gltf::FsPolicy& policy,
              const GltfOptions& options)
        : model_(model), file_(file), policy_(policy), options_(options) {}
    Scene run();

private:
    [[noreturn]] void fail(const std::string& problem) const { gltf::fail(file_, problem); }
    void checkIndex(int index, size_t size, const std::string& what, const std::string& by) const {
        gltf::checkIndex(file_, index, size, what, by);
    }
    void checkExtensions() const;
    void checkNodeTree();
    std::vector<int> rootNodes() const;
    glm::dmat4 localTransform(int nodeIndex) const;
    void walkNodes(gltf::PrimitiveBuilder& builder);
    std::vector<std::size_t> countPlacements() const;
    std::size_t checkPlacedTriangles(const std::vector<std::size_t>& placements) const;
    void addDefaultEnvironment();

    const tinygltf::Model& model_;
    const std::string& file_;
    gltf::FsPolicy& policy_;
    const GltfOptions& options_;
    Scene scene_;
    std::vector<int> parent_;
    std::vector<bool> instanced_; // per mesh (gltf_instancing.h)
};

// Unknown extensions: one warning each, refused when required (the file says it cannot be
// drawn correctly without them).
void Converter::checkExtensions() const {
    for (const std::string& ext : model_.extensionsRequired) {
        if (!gltf::isSupportedExtension(ext)) {
            fail("requires glTF extension " + ext + ", which is not supported");
        }
    }
    for (const std::string& ext : model_.extensionsUsed) {
        if (!gltf::isSupportedExtension(ext)) {
            gltf::warn(file_, "ignoring glTF extension " + ext + " (not supported)");
        }
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

// How many of the nodes the roots reach place each mesh (out-of-range meshes are left to
// walkNodes, which names them).
std::vector<std::size_t> Converter::countPlacements() const {
    std::vector<std::size_t> placements(model_.meshes.size(), 0);
    std::vector<int> stack = rootNodes();
    std::vector<bool> seen(model_.nodes.size(), false);
    while (!stack.empty()) {
        const int index = stack.back();
        stack.pop_back();
        if (index < 0 || std::size_t(index) >= model_.nodes.size() || seen[index])
            continue;
        seen[index] = true;
        const tinygltf::Node& node = model_.nodes[index];
        if (node.mesh >= 0 && std::size_t(node.mesh) < model_.meshes.size())
            ++placements[node.mesh];
        stack.insert(stack.end(), node.children.begin(), node.children.end());
    }
    return placements;
}

// Counts the triangles the scene keeps (flattened copies, and instanced meshes once) from the
// accessors' counts alone, before any is read, so that a small file placing a big mesh at many
// nodes is refused at once rather than after filling memory. Returns the count.
std::size_t Converter::checkPlacedTriangles(const std::vector<std::size_t>& placements) const {
    double total = 0.0, instances = 0.0;
    for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
        double triangles = 0.0;
        for (const tinygltf::Primitive& primitive : model_.meshes[m].primitives)
            triangles += double(gltf::estimatedTriangles(model_, primitive));
        total += triangles * (instanced_[m] ? std::min<double>(placements[m], 1.0)
                                            : double(placements[m]));
        instances += instanced_[m] ? double(placements[m]) : 0.0;
    }
    if (total > double(gltf::maxSceneTriangles()))
        fail("its nodes place more than " + std::to_string(gltf::maxSceneTriangles()) +
             " triangles, " + gltf::sceneTriangleLimitReason());
    if (instances > double(gltf::kMaxInstances))
        fail("its nodes place more than " + std::to_string(gltf::kMaxInstances) +
             " instances, the most the renderer keeps");
    return std::size_t(total);
}

// Depth-first, children in file order, without recursion so deep trees cannot overflow the
// stack; checkNodeTree guarantees each node is reached at most once from the roots.
void Converter::walkNodes(gltf::PrimitiveBuilder& builder) {
    std::vector<std::pair<int, glm::dmat4>> stack;
    const std::vector<int> roots = rootNodes();
    std::vector<bool> visited(model_.nodes.size(), false);
    std::vector<uint32_t> meshSlot(model_.meshes.size(), gltf::kWorldGeometry);
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
            gltf::addNodeCamera(model_, file_, index, world, scene_);
        }
        gltf::addNodeLight(model_, file_, index, world, scene_);
        if (node.mesh != -1) {
            checkIndex(node.mesh, model_.meshes.size(), "mesh", name);
            const auto& primitives = model_.meshes[node.mesh].primitives;
            // An instanced mesh is read once, in its own space, at its first placement.
            const bool instanced = instanced_[node.mesh];
            const bool firstPlacement = instanced && meshSlot[node.mesh] == gltf::kWorldGeometry;
            if (firstPlacement)
                meshSlot[node.mesh] = builder.newMesh();
            for (size_t p = 0; p < primitives.size() && (!instanced || firstPlacement); ++p) {
                builder.add(primitives[p], "mesh " + std::to_string(node.mesh) + " primitive " +
                            std::to_string(p), instanced ? glm::dmat4(1.0) : world,
                            meshSlot[node.mesh]);
            }
            if (instanced)
                builder.place(meshSlot[node.mesh], world, name);
        }
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
            stack.emplace_back(*child, world);
        }
    }
}

// "A scene without any light gets a uniform white environment": no emissive triangle and no
// punctual light means the file relies on the viewer's lighting, so give it the furnace sky.
void Converter::addDefaultEnvironment() {
    for (const Triangle& t : scene_.triangles) {
        const glm::vec3 e = scene_.materials[t.material].emission;
        if (e.x > 0.0f || e.y > 0.0f || e.z > 0.0f) {
            return;
        }
    }
    if (scene_.lights.empty()) {
        scene_.environment.width = scene_.environment.height = 1;
        scene_.environment.rgb = {1.0f, 1.0f, 1.0f};
    }
}

Scene Converter::run() {
    checkExtensions();
    gltf::MaterialTables tables = gltf::convertMaterials(model_, file_);
    checkNodeTree();
    const uint32_t defaultIndex = uint32_t(tables.materials.size());
    gltf::PrimitiveBuilder builder(model_, file_, tables, defaultIndex);
    const std::vector<std::size_t> placements = countPlacements();
    instanced_ = gltf::meshesToInstance(model_, placements, tables, options_.instancing);
    builder.reserve(checkPlacedTriangles(placements));
    walkNodes(builder);
    builder.finish(scene_);
    gltf::loadImages(model_, file_, policy_.images, tables, scene_.surface);
    scene_.materials = std::move(tables.materials);
    if (builder.usedDefaultMaterial() || scene_.materials.empty()) {
        scene_.materials.push_back(gltf::defaultMaterial());
    }
    // Images no triangle samples are not kept: a scene whose textured primitives are all
    // skipped has no texture code (the UV arrays are already empty then).
    if (scene_.surface.uv0.empty() && scene_.surface.uv1.empty()) {
        scene_.surface.textureRefs.clear();
        scene_.surface.refImage.clear();
        scene_.surface.images.clear();
        for (Material& m : scene_.materials) {
            m.baseColorTexture = m.metallicRoughnessTexture = m.normalTexture =
                m.emissiveTexture = m.transmissionTexture = m.specularTexture =
                    m.specularColorTexture = WF_NO_TEXTURE;
        }
    }
    addDefaultEnvironment();
    return std::move(scene_);
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) {
        return char(std::tolower(c));
    });
    return ext;
}

Scene loadModel(std::vector<unsigned char> bytes, const std::string& path,
                const GltfOptions& options) {
    const std::string ext = lowerExtension(path);
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (ext == ".glb" && !binary) {
        throw InputError(path + ": not a binary glTF file (no 'glTF' magic)");
    }
    size_t jsonStart = 0, jsonLength = bytes.size();
    if (binary && bytes.size() >= 20) {
        uint32_t chunkLength = 0; // the JSON chunk's length; tinygltf checks it against size
        std::memcpy(&chunkLength, bytes.data() + 12, 4);
        jsonStart = 20;
        jsonLength = std::min<size_t>(chunkLength, bytes.size() - 20);
    }
    if (gltf::nestedTooDeep(bytes.data() + jsonStart, jsonLength)) {
        throw InputError(path + ": JSON nested more than " + std::to_string(gltf::MAX_JSON_DEPTH) +
                         " levels deep");
    }
    std::error_code ec;
    gltf::FsPolicy policy{fs::weakly_canonical(fs::absolute(path).parent_path(), ec), {}};
    if (ec) {
        throw InputError(path + ": cannot resolve the scene's folder: " + ec.message());
    }
    // May rewrite the JSON into what tinygltf accepts (gltf_compression.h); its stand-ins for
    // decoded buffers are then taken like any other buffer.
    const gltf::CompressionPlan compression = gltf::planDecompression(bytes, binary, path);
    gltf::TakenBuffers taken = gltf::takeBuffers(bytes, binary, policy, path);
    const size_t size = bytes.size();
    // tinygltf 2.7.0's GLB chunk check forgets the 8-byte chunk header, so it may read up to
    // 8 bytes past the end; zero padding makes that harmless.
    bytes.resize(size + 16, 0);
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
    const std::string messages = gltf::rewordParserMessages(err + "\n" + warn);
    if (!loaded) {
        // A refused path explains a "does not exist" better than the parser can; an empty
        // URI is a missing one, which the parser's own message says.
        std::string problem =
            messages.empty() ? "the parser refused the file without naming the rule it breaks"
                             : messages;
        if (!policy.refusal.empty() && policy.refusal.rfind("refused to read '':", 0) != 0) {
            problem = policy.refusal;
        }
        throw InputError(path + ": " + problem);
    }
    if (!messages.empty()) {
        gltf::warn(path, messages);
    }
    std::vector<unsigned char>().swap(bytes); // tinygltf holds no pointer into the document
    gltf::returnBuffers(model, taken, path);
    gltf::decompress(model, compression, path);
    return Converter(model, path, policy, options).run();
}

} // namespace

Scene loadGltf(const std::string& path, std::vector<std::string>* warnings,
               const GltfOptions& options) {
    const std::string ext = lowerExtension(path);
    if (ext != ".gltf" && ext != ".glb") {
        throw InputError(path + ": expected a .gltf or .glb file");
    }
    std::vector<unsigned char> bytes;
    std::string why;
    if (!gltf::readLimited(path, bytes, why)) {
        throw InputError(path + ": cannot read scene: " + why);
    }
    gltf::WarningSink sink;
    Scene scene = loadModel(std::move(bytes), path, options);
    for (std::string& line : sink.take()) {
        if (warnings) {
            warnings->push_back(std::move(line));
        } else {
            std::cerr << line << "\n";
        }
    }
    return scene;
}

Scene loadGltfFromMemory(const unsigned char* data, size_t size, const std::string& path,
                         const GltfOptions& options) {
    gltf::WarningSink sink; // the caller (a fuzzer) wants no output
    return loadModel(std::vector<unsigned char>(data, data + size), path, options);
}

} // namespace wf
