// The scene as the renderer consumes it: flat world-space triangles and materials, one camera.
// The loader produces it; the BVH builder reorders its triangles; the light table fills in
// each triangle's emitter index.
#pragma once
#include <string>
#include <vector>

#include "shaders/shared/scene_types.h"

namespace wf {

using gpu_types::BvhNode;
using gpu_types::Emitter;
using gpu_types::Material;
using gpu_types::Triangle;

struct Camera {
    glm::vec3 position{0.0f, 0.0f, 0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f}; // unit, world space
    glm::vec3 up{0.0f, 1.0f, 0.0f};       // unit, orthogonal to forward
    float yfov = 0.8f;                    // vertical field of view, radians
    float aspect = 0.0f;                  // width / height from the file; 0 if it gives none
};

struct Scene {
    std::vector<Triangle> triangles; // world space, degenerate ones already dropped
    std::vector<Material> materials; // never empty: a default grey material is appended if needed
    Camera camera;
    bool hasCamera = false;
};

} // namespace wf
