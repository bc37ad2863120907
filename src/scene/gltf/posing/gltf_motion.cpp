#include "scene/gltf/posing/gltf_motion.h"

#include <tiny_gltf.h>

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/gltf_instancing.h"
#include "scene/gltf/gltf_lights_cameras.h"
#include "scene/gltf/posing/gltf_node_pose.h"

namespace wf::gltf {

bool ShutterKeys::moves(int node) const {
    for (std::size_t k = 1; k < world.size(); ++k)
        if (world[k][node] != world[0][node])
            return true;
    return false;
}

bool ShutterKeys::weightsChange(int node) const {
    for (std::size_t k = 1; k < animated.size(); ++k)
        if (animated[k][node].weights != animated[0][node].weights)
            return true;
    return false;
}

std::vector<glm::mat4> ShutterKeys::keysOf(int node) const {
    std::vector<glm::mat4> keys;
    keys.reserve(world.size());
    for (const std::vector<glm::dmat4>& key : world)
        keys.emplace_back(key[node]);
    return keys;
}

ShutterKeys sampleShutter(const tinygltf::Model& model, const std::string& file,
                          AccessorReader& reader, const std::vector<int>& parent, double open,
                          double close, uint32_t segments, const std::string& animation) {
    ShutterKeys keys;
    keys.segments = segments;
    for (uint32_t k = 0; k <= segments; ++k) {
        const double time = open + (close - open) * double(k) / double(segments);
        keys.animated.push_back(sampleAnimations(model, file, reader, time, animation));
        keys.world.push_back(nodeWorldTransforms(model, file, parent, keys.animated.back()));
    }
    return keys;
}

namespace {

// A skinned mesh whose joints move, or a morphed one whose weights change, within the shutter.
bool deformsInShutter(const tinygltf::Model& model, const ShutterKeys& shutter, int index) {
    const tinygltf::Node& node = model.nodes[index];
    if (morphTargetCount(model, node.mesh) > 0 && shutter.weightsChange(index))
        return true;
    if (node.skin >= 0 && std::size_t(node.skin) < model.skins.size())
        for (int joint : model.skins[node.skin].joints)
            if (joint >= 0 && std::size_t(joint) < model.nodes.size() && shutter.moves(joint))
                return true;
    return false;
}

} // namespace

std::vector<bool> meshesToBlur(const tinygltf::Model& model, const std::string& file,
                               const ShutterKeys& shutter, const MaterialTables& materials,
                               std::vector<bool>& instanced) {
    std::vector<bool> blurred(model.meshes.size(), false);
    if (shutter.segments == 0)
        return blurred;
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& node = model.nodes[i];
        if (node.mesh < 0 || std::size_t(node.mesh) >= model.meshes.size())
            continue;
        const std::string name = "node " + std::to_string(i);
        if (deformsInShutter(model, shutter, int(i))) {
            warn(file, name + " deforms within the shutter (skin or morph targets): drawn at "
                              "the shutter's centre, without motion blur");
        } else if (node.skin == -1 && shutter.moves(int(i))) {
            if (meshEmits(model, std::size_t(node.mesh), materials))
                warn(file, name + " moves within the shutter, but its mesh emits light: drawn "
                                  "at the shutter's centre, without motion blur");
            else
                instanced[node.mesh] = blurred[node.mesh] = true;
        }
    }
    return blurred;
}

void keyNodeMotion(const ShutterKeys& shutter, int node, std::size_t cameras, std::size_t lights,
                   Scene& scene) {
    if (shutter.segments == 0 || !shutter.moves(node))
        return;
    const std::vector<glm::mat4> keys = shutter.keysOf(node);
    if (scene.cameras.size() > cameras) {
        // A key whose transform is degenerate leaves the camera still, at the centre's pose.
        std::vector<CameraKey> frames(keys.size());
        bool usable = true;
        for (std::size_t k = 0; k < keys.size(); ++k)
            usable = usable && cameraFrame(glm::dmat4(keys[k]), frames[k]);
        if (usable) {
            if (cameras == 0) // the first camera is also the one to render with
                scene.camera.motion = frames;
            scene.cameras.back().motion = std::move(frames);
        }
    }
    if (scene.lights.size() > lights) {
        scene.lights.back().motion = uint32_t(scene.lightMotionKeys.size()) + 1u;
        for (const glm::mat4& key : keys)
            scene.lightMotionKeys.emplace_back(key[3]);
    }
}

} // namespace wf::gltf
