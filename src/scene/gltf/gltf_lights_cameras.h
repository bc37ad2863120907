// The objects a glTF node may carry besides a mesh: a camera (perspective; orthographic ones
// are skipped) and a KHR_lights_punctual light (point, spot, directional, and the sphere-light
// convention: a point light with extras.radius > 0). Invalid ones are skipped with a warning,
// so one bad light or camera never costs the whole scene; bad indices are refused.
#pragma once
#include <string>

#include <glm/mat4x4.hpp>

#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace wf::gltf {

// A camera's view from its node's world transform: glTF cameras look down -Z with +Y up, shear
// from scaling removed (Gram-Schmidt). False where the transform is degenerate.
bool cameraFrame(const glm::dmat4& world, CameraKey& key);

// Appends node `nodeIndex`'s camera, placed by `world`, to scene.cameras and cameraNames.
void addNodeCamera(const tinygltf::Model& model, const std::string& file, int nodeIndex,
                   const glm::dmat4& world, Scene& scene);

// Appends node `nodeIndex`'s light, if it has one: position = the world translation,
// direction = the node's -Z axis in world space, intensity = colour x intensity (candela for
// point and spot lights, lux for directional ones). glTF lights ignore node scale; so does the
// sphere radius.
void addNodeLight(const tinygltf::Model& model, const std::string& file, int nodeIndex,
                  const glm::dmat4& world, Scene& scene);

} // namespace wf::gltf
