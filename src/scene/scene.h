// The scene as the renderer consumes it: flat world-space triangles and materials, one camera.
// The loader produces it; the BVH builder reorders its triangles; the light table fills in
// each triangle's emitter index.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/surface_data.h"
#include "shaders/shared/light_types.h"
#include "shaders/shared/scene_types.h"

namespace wf {

using gpu_types::BvhNode;
using gpu_types::BvhPair;
using gpu_types::Emitter;
using gpu_types::Material;
using gpu_types::PunctualLight;
using gpu_types::Triangle;

struct Camera {
    glm::vec3 position{0.0f, 0.0f, 0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f}; // unit, world space
    glm::vec3 up{0.0f, 1.0f, 0.0f};       // unit, orthogonal to forward
    float yfov = 0.8f;                    // vertical field of view, radians
    float aspect = 0.0f;                  // width / height from the file; 0 if it gives none
    // Thin lens: the lens's diameter (0: a pinhole) and the distance along `forward` to the
    // plane in focus (0: chosen by loadSceneWithFlags), in scene units; from the camera's
    // extras "aperture" and "focusDistance", or --aperture and --focus-distance.
    float aperture = 0.0f;
    float focusDistance = 0.0f;
};

// An equirectangular environment map (longitude along x, +Y up), linear RGB radiance.
struct Environment {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgb; // width * height * 3, top row first
    bool present() const { return width > 0 && height > 0; }
};

struct Scene {
    std::vector<Triangle> triangles; // world space, degenerate ones already dropped
    std::vector<Material> materials; // never empty: a default grey material is appended if needed
    Camera camera;                   // the one to render with
    bool hasCamera = false;
    std::vector<Camera> cameras;     // every valid camera of the file, in node order
    std::vector<std::string> cameraNames;
    std::vector<PunctualLight> lights; // KHR_lights_punctual (and sphere lights)
    Environment environment;         // --env, or uniform white when the scene has no light
    SurfaceData surface;             // vertex attributes and textures, only what is used
};

} // namespace wf
