// The scene as the renderer consumes it: triangles and materials, one camera. Meshes placed once
// are flattened into world space; meshes the loader instances (gltf_instancing.h) are kept once,
// in their own space, and placed by transforms. The loader produces it; the BVH builder
// reorders its triangles; the light table fills in each triangle's emitter index.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/surface_data.h"
#include "shaders/types/light_types.h"
#include "shaders/types/scene_types.h"

namespace wf {

using gpu_types::BvhNode;
using gpu_types::BvhPair;
using gpu_types::Emitter;
using gpu_types::Instance;
using gpu_types::Material;
using gpu_types::PunctualLight;
using gpu_types::Triangle;

// Where a moving camera is at one key of the shutter (motion blur).
struct CameraKey {
    glm::vec3 position;
    glm::vec3 forward; // unit
    glm::vec3 up;      // unit, orthogonal to forward
};

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
    // Orthographic (glTF ymag): half the view's height in scene units, rays parallel to
    // `forward` (the lens is not used); 0 is a perspective camera.
    float orthoHalfHeight = 0.0f;
    // A camera that moves within the shutter: Scene::motionSegments + 1 keys evenly spaced
    // over it (the fields above are its pose at the shutter's centre); empty when still.
    std::vector<CameraKey> motion;
};

// An equirectangular environment map (longitude along x, +Y up), linear RGB radiance.
struct Environment {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgb; // width * height * 3, top row first
    bool present() const { return width > 0 && height > 0; }
};

// A mesh kept once for its instances: a range of Scene::triangles, in the mesh's own space.
struct MeshRange {
    uint32_t firstTriangle = 0;
    uint32_t triangleCount = 0;
};

// One node's placement of a MeshRange.
struct MeshPlacement {
    glm::mat4 worldFromObject{1.0f}; // at the shutter's centre where it moves
    uint32_t mesh = 0; // index into Scene::meshes
    // A placement that moves within the shutter: Scene::motionSegments + 1 worldFromObject
    // keys evenly spaced over it; empty when still.
    std::vector<glm::mat4> motion;
};

// An axis-aligned box; empty (lo > hi) until something grows it.
struct Bounds {
    glm::vec3 lo{3.0e38f};
    glm::vec3 hi{-3.0e38f};
    bool empty() const { return lo.x > hi.x; }
    void grow(glm::vec3 p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
};

struct Scene {
    // Degenerate ones already dropped. [0, worldTriangleCount()) in world space, then the
    // meshes' ranges in their own space.
    std::vector<Triangle> triangles;
    std::vector<MeshRange> meshes;        // empty unless the loader instanced some mesh
    std::vector<MeshPlacement> placements; // each instanced mesh's placements
    std::vector<Material> materials; // never empty: a default grey material is appended if needed
    Camera camera;                   // the one to render with
    bool hasCamera = false;
    std::vector<Camera> cameras;     // every valid camera of the file, in node order
    std::vector<std::string> cameraNames;
    // KHR_materials_variants: the file's variants and the one whose materials were taken (-1:
    // none, the primitives' own).
    std::vector<std::string> variantNames;
    int variant = -1;
    std::vector<PunctualLight> lights; // KHR_lights_punctual (and sphere lights)
    Environment environment;         // --env, or uniform white when the scene has no light
    SurfaceData surface;             // vertex attributes and textures, only what is used
    // The last key time of the animations played (--animation's choice, else all): 0 for a
    // static scene. The viewer's time slider spans [0, animationSeconds].
    double animationSeconds = 0.0;
    // Motion blur (--shutter): what moves within the shutter has motionSegments + 1 keys
    // evenly spaced over it (placements' and cameras' `motion`, and here the moving lights'
    // positions: PunctualLight::motion is 1 + its first key); 0 when nothing moves.
    uint32_t motionSegments = 0;
    std::vector<glm::vec3> lightMotionKeys;

    size_t worldTriangleCount() const {
        return meshes.empty() ? triangles.size() : meshes.front().firstTriangle;
    }
    // Triangles as rendered: the world ones plus each placement's mesh.
    uint64_t instancedTriangleCount() const;
};

// The box of `box` (in object space) after `worldFromObject`.
Bounds transformedBounds(const Bounds& box, const glm::mat4& worldFromObject);
// The world-space bounds of the scene's triangles: world ones and every placement's mesh.
Bounds triangleBounds(const Scene& scene);

} // namespace wf
