// Rigid motion within a camera shutter (motion blur): every node's world transform keyed at
// evenly spaced times over the shutter, and which nodes move.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/gltf/posing/gltf_animation.h"
#include "scene/gltf/gltf_materials.h"
#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace wf::gltf {

struct ShutterKeys {
    uint32_t segments = 0;                            // keys - 1; 0: no shutter
    std::vector<std::vector<glm::dmat4>> world;       // [key][node]
    std::vector<std::vector<NodeAnimation>> animated; // [key][node]: the morph weights

    // The node's world transform differs between keys.
    bool moves(int node) const;
    // The node's animated morph weights differ between keys.
    bool weightsChange(int node) const;
    // The node's world transform at every key, in float.
    std::vector<glm::mat4> keysOf(int node) const;
};

// Per mesh, whether its moving placements are keyed (and the mesh then instanced, set in
// `instanced`): meshes that a moving node places, except emissive ones (the light table lists
// world-space triangles) and deforming ones (skins and morphs are posed once, on the host),
// which are drawn at the shutter's centre with a warning.
std::vector<bool> meshesToBlur(const tinygltf::Model& model, const std::string& file,
                               const ShutterKeys& shutter, const MaterialTables& materials,
                               std::vector<bool>& instanced);

// Keys the camera and the light that node `node` has just added to `scene` (`cameras` and
// `lights` were the counts before), where the node moves within the shutter. A camera with a
// degenerate transform at some key stays still.
void keyNodeMotion(const ShutterKeys& shutter, int node, std::size_t cameras, std::size_t lights,
                   Scene& scene);

// Keys at open + (close - open) k / segments, k = 0 .. segments, playing `animation` ("" for
// all) as gltf::sampleAnimations does; `parent` as nodeWorldTransforms takes it.
ShutterKeys sampleShutter(const tinygltf::Model& model, const std::string& file,
                          AccessorReader& reader, const std::vector<int>& parent, double open,
                          double close, uint32_t segments, const std::string& animation);

} // namespace wf::gltf
