// A scene for the light-agreement tests, described so that both the renderer and a closed form
// can read it: Lambertian receiver quads lit by emissive quads, sphere lights, Dirac lights or a
// row environment, and the per-pixel direct lighting (max depth 2) they must give.
#pragma once
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace wf::test {

// corner + [0,1]^2 of (edgeU, edgeV); the front face is cross(edgeU, edgeV).
struct RigQuad {
    glm::vec3 corner;
    glm::vec3 edgeU;
    glm::vec3 edgeV;
    float value; // albedo of a receiver (two-sided Lambert), radiance of an emitter (front only)
};

struct LightRig {
    std::vector<RigQuad> receivers;
    std::vector<RigQuad> emitters;
    std::vector<PunctualLight> lights;      // sphere, point, spot, directional (grey)
    float (*skyRow)(uint32_t row) = nullptr; // an 8x8 row environment, if set
    Camera camera;
};

// Camera at `eye` looking at `target`, +y up.
Camera lookAt(glm::vec3 eye, glm::vec3 target, float yfov);

Scene rigScene(const LightRig& rig);

// The expected image (channel mean) of rigScene at max depth 2, each pixel the mean of 16x16
// box-filter positions. `valid` marks the pixels whose positions, and those of the 8 pixels
// around them, all see a receiver first: the rest see a light or the sky, or may in a sample
// between the positions, and are not compared. The closed forms ignore occlusion between
// lights: rigs place their lights where none shadows another.
struct ExpectedImage {
    std::vector<double> value;
    std::vector<bool> valid;
    // Chance that a cosine-distributed direction from the pixel's receiver point hits a light:
    // the projected solid angle of the area lights (and sky) over pi.
    std::vector<double> hitProbability;
};

ExpectedImage expectedDirectLight(const LightRig& rig, uint32_t width, uint32_t height);

} // namespace wf::test
