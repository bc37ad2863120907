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
#include "scene/gltf/posing/gltf_animation.h"
#include "scene/gltf/io/gltf_buffer_streaming.h"
#include "scene/gltf/compression/gltf_compression.h"
#include "scene/gltf/io/gltf_file_access.h"
#include "scene/gltf/gltf_gpu_instancing.h"
#include "scene/gltf/gltf_images.h"
#include "scene/gltf/gltf_instancing.h"
#include "scene/gltf/gltf_lights_cameras.h"
#include "scene/gltf/posing/gltf_node_pose.h"
#include "scene/gltf/io/gltf_parse_errors.h"
#include "scene/gltf/gltf_materials.h"
#include "scene/gltf/posing/gltf_motion.h"
#include "scene/gltf/gltf_primitives.h"
#include "scene/gltf/gltf_scene_limits.h"
#include "scene/gltf/gltf_texture_refs.h"
#include "scene/gltf/gltf_variants.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

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

class Converter {
public:
    Converter(const tinygltf::Model& model, const std::string& file, gltf::FsPolicy& policy,
              const GltfOptions& options)
        : model_(model), file_(file), policy_(policy), options_(options), reader_(model, file) {}
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
    void addDefaultEnvironment();
    void poseNodes();
    gltf::Deformation deformationOf(int nodeIndex);

    const tinygltf::Model& model_;
    const std::string& file_;
    gltf::FsPolicy& policy_;
    const GltfOptions& options_;
    Scene scene_;
    std::vector<int> parent_;
    std::vector<bool> instanced_; // per mesh (gltf_instancing.h)
    gltf::AccessorReader reader_; // animations and skins
    std::vector<gltf::NodeAnimation> animated_; // per node, at options_.time
    std::vector<glm::dmat4> nodeWorld_;         // per node, every node (joints may be anywhere)
    gltf::ShutterKeys shutter_;                 // motion blur: nodes keyed over the shutter
    std::vector<bool> blurred_;                 // per mesh: its moving placements are keyed
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
        if (!gltf::isSupportedExtension(ext) && !gltf::isReadThroughFallbacks(ext)) {
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
    return gltf::nodeLocalTransform(
        model_, file_, nodeIndex,
        std::size_t(nodeIndex) < animated_.size() ? &animated_[nodeIndex] : nullptr);
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
            placements[node.mesh] += std::max<std::size_t>(
                gltf::gpuInstanceCount(model_, file_, index), 1); // EXT_mesh_gpu_instancing
        stack.insert(stack.end(), node.children.begin(), node.children.end());
    }
    return placements;
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
        const std::size_t cameras = scene_.cameras.size(), lights = scene_.lights.size();
        if (node.camera != -1) {
            gltf::addNodeCamera(model_, file_, index, world, scene_);
        }
        gltf::addNodeLight(model_, file_, index, world, scene_);
        if (node.mesh != -1) {
            checkIndex(node.mesh, model_.meshes.size(), "mesh", name);
            const auto& primitives = model_.meshes[node.mesh].primitives;
            // An instanced mesh is read once, in its own space, at its first placement.
            const bool instanced = instanced_[node.mesh];
            const gltf::Deformation deformation = deformationOf(index);
            // A skinned mesh sits where its joints put it; its node's transform is ignored.
            const glm::dmat4 placed =
                deformation.jointMatrices.empty() ? world : glm::dmat4(1.0);
            const bool keyed =
                shutter_.segments != 0 && blurred_[node.mesh] && shutter_.moves(index);
            // EXT_mesh_gpu_instancing: each instance is placed as a child node with its TRS
            // would be (a skinned mesh's instances move its posed, world-space vertices).
            const gltf::GpuInstances gpu(model_, file_, reader_, index);
            for (std::size_t copy = 0; copy < std::max<std::size_t>(gpu.size(), 1); ++copy) {
                const glm::dmat4 local = gpu.empty() ? glm::dmat4(1.0) : gpu.transform(copy);
                const glm::dmat4 at = gpu.empty() ? world : world * local;
                const glm::dmat4 posed = gpu.empty() ? placed
                                         : deformation.jointMatrices.empty() ? at
                                                                             : local;
                const bool firstPlacement =
                    instanced && meshSlot[node.mesh] == gltf::kWorldGeometry;
                if (firstPlacement)
                    meshSlot[node.mesh] = builder.newMesh();
                for (size_t p = 0; p < primitives.size() && (!instanced || firstPlacement); ++p)
                    builder.add(primitives[p], "mesh " + std::to_string(node.mesh) +
                                " primitive " + std::to_string(p),
                                instanced ? glm::dmat4(1.0) : posed, meshSlot[node.mesh],
                                &deformation);
                if (!instanced)
                    continue;
                std::vector<glm::mat4> keys;
                for (std::size_t k = 0; keyed && k < shutter_.world.size(); ++k)
                    keys.emplace_back(gpu.empty() ? shutter_.world[k][index]
                                                  : shutter_.world[k][index] * local);
                builder.place(meshSlot[node.mesh], at, name, std::move(keys));
            }
        } else if (node.extensions.count("EXT_mesh_gpu_instancing")) {
            gltf::warn(file_, name + " has EXT_mesh_gpu_instancing but no mesh: ignored");
        }
        gltf::keyNodeMotion(shutter_, index, cameras, lights, scene_);
        for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
            stack.emplace_back(*child, world);
        }
    }
}

// Samples the animations at the time, then every node's world transform (joints outside the
// scene's tree included), parents before children via the checked parent links.
void Converter::poseNodes() {
    const bool atRest = options_.time == 0.0 && options_.animation.empty() &&
                        !(options_.shutterClose > options_.shutterOpen);
    animated_ = gltf::sampleAnimations(model_, file_, reader_, options_.time, options_.animation,
                                       &scene_.animationSeconds, atRest);
    nodeWorld_ = gltf::nodeWorldTransforms(model_, file_, parent_, animated_);
}

// The node's morph weights (animated, else the node's, else the mesh's) and its skin's joint
// matrices; empty when the mesh has neither.
gltf::Deformation Converter::deformationOf(int nodeIndex) {
    const tinygltf::Node& node = model_.nodes[nodeIndex];
    gltf::Deformation out;
    const std::string name = "node " + std::to_string(nodeIndex);
    const std::size_t targets = gltf::morphTargetCount(model_, node.mesh);
    if (targets > 0) {
        const gltf::NodeAnimation& a = animated_[nodeIndex];
        const std::vector<double>& meshWeights = model_.meshes[node.mesh].weights;
        out.morphWeights = a.weights             ? *a.weights
                           : !node.weights.empty() ? node.weights
                                                   : meshWeights;
        if (out.morphWeights.size() > targets)
            fail(name + ": " + std::to_string(out.morphWeights.size()) + " morph weights for " +
                 std::to_string(targets) + " targets of mesh " + std::to_string(node.mesh));
        out.morphWeights.resize(targets, 0.0);
        for (double w : out.morphWeights)
            if (!std::isfinite(w))
                fail(name + ": a morph weight is not finite");
    }
    if (node.skin != -1) {
        checkIndex(node.skin, model_.skins.size(), "skin", name);
        out.jointMatrices = gltf::jointMatrices(model_, file_, reader_, node.skin, nodeWorld_);
    }
    return out;
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
    poseNodes();
    if (options_.shutterClose > options_.shutterOpen && options_.motionSegments > 0)
        shutter_ = gltf::sampleShutter(model_, file_, reader_, parent_, options_.shutterOpen,
                                       options_.shutterClose, options_.motionSegments,
                                       options_.animation);
    const uint32_t defaultIndex = uint32_t(tables.materials.size());
    gltf::PrimitiveBuilder builder(model_, file_, tables, defaultIndex);
    const std::vector<std::size_t> placements = countPlacements();
    instanced_ = gltf::meshesToInstance(model_, placements, tables, options_.instancing);
    // Skinned and morphed meshes are posed per node, so each placement is its own copy.
    for (const tinygltf::Node& node : model_.nodes)
        if (node.mesh >= 0 && std::size_t(node.mesh) < instanced_.size() &&
            (node.skin != -1 || gltf::morphTargetCount(model_, node.mesh) > 0))
            instanced_[node.mesh] = false;
    blurred_ = gltf::meshesToBlur(model_, file_, shutter_, tables, instanced_);
    builder.reserve(gltf::checkPlacedTriangles(model_, file_, placements, instanced_));
    walkNodes(builder);
    builder.finish(scene_);
    bool moves = !scene_.lightMotionKeys.empty();
    for (const Camera& camera : scene_.cameras)
        moves |= !camera.motion.empty();
    for (const MeshPlacement& placement : scene_.placements)
        moves |= !placement.motion.empty();
    scene_.motionSegments = moves ? shutter_.segments : 0;
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
        for (Material& m : scene_.materials)
            for (uint32_t* field : gltf::textureFields(m))
                *field = WF_NO_TEXTURE;
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
    tinygltf::TinyGLTF parser;
    gltf::restrictFileAccess(parser, policy);
    tinygltf::Model model;
    std::string err, warn;
    bool loaded = false;
    size_t size = bytes.size();
    auto parse = [&] {
        // tinygltf 2.7.0's GLB chunk check forgets the 8-byte chunk header, so it may read up
        // to 8 bytes past the end; zero padding makes that harmless.
        bytes.resize(size + 16, 0);
        model = tinygltf::Model();
        err.clear();
        warn.clear();
        loaded = false;
        try {
            const std::string base = policy.folder.string();
            loaded = binary ? parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                          unsigned(size), base)
                            : parser.LoadASCIIFromString(
                                  &model, &err, &warn,
                                  reinterpret_cast<const char*>(bytes.data()), unsigned(size),
                                  base);
        } catch (const std::exception& e) {
            err += e.what();
        }
        // tinygltf drops some broken objects (an animation channel without its sampler) and
        // goes on, saying so in `err`: such a file is refused like the others.
        return loaded && gltf::droppedByTinygltf(err).empty();
    };
    if (!parse()) {
        // Valid glTF that tinygltf refuses is mended and parsed once more (gltf_parse_errors.h);
        // the first refusal stands when that does not help.
        const bool wasLoaded = loaded;
        const std::string firstErr = err;
        bool mended = false;
        std::vector<unsigned char> copy(bytes.begin(), bytes.begin() + long(size));
        const std::vector<std::string> mends = gltf::mendForTinygltf(copy, size, binary, mended);
        if (mended) {
            std::swap(bytes, copy);
            size = bytes.size();
            if (parse()) {
                for (const std::string& line : mends)
                    gltf::warn(path, line);
            } else {
                loaded = wasLoaded;
                err = firstErr;
            }
        }
    }
    const std::string kept = loaded ? gltf::keptByTinygltf(err) : std::string();
    if (loaded)
        err = gltf::droppedByTinygltf(err);
    if (!loaded || !err.empty()) {
        // A path the policy refused explains a "File not found" better than tinygltf can; the
        // rest is tinygltf's and its JSON parser's, in the project's words.
        const bool unreadFile = err.find("File not found") != std::string::npos &&
                                err.find("'uri' is missing") == std::string::npos;
        const std::string problem = !policy.refusal.empty() && unreadFile
                                        ? policy.refusal
                                        : collapseLines(gltf::parseFailureInOwnWords(err));
        throw InputError(path + ": " + problem);
    }
    for (const std::string& line : gltf::parseWarningsInOwnWords(kept + warn))
        gltf::warn(path, collapseLines(line));
    std::vector<unsigned char>().swap(bytes); // tinygltf holds no pointer into the document
    gltf::returnBuffers(model, taken, path);
    gltf::decompress(model, compression, path);
    const gltf::VariantChoice variants = gltf::applyMaterialVariant(model, path, options.variant);
    Scene scene = Converter(model, path, policy, options).run();
    scene.variantNames = variants.names;
    scene.variant = variants.chosen;
    return scene;
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
