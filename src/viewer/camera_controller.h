// The viewer's camera: orbit around a target, pan, dolly, and fly (look around + move). Pure
// math on wf::Camera, no window system, so that tests/viewer/test_camera_controller.cpp checks
// it on the CPU. The target always lies on the view axis at `distance()`; a controller that has
// not been moved hands back the camera it started with, bit for bit, so the first image of the
// viewer is the render command's.
#pragma once
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace wf {

// One frame of input, already stripped of what the overlay took.
struct CameraInput {
    glm::vec2 orbit{0.0f};  // cursor motion (screen units) of an orbit drag (left button)
    glm::vec2 pan{0.0f};    // ... of a pan drag (middle button, or shift + left)
    glm::vec2 look{0.0f};   // ... of a fly-look drag (right button)
    float dolly = 0.0f;     // wheel steps, positive towards the target
    glm::vec3 move{0.0f};   // fly: x right, y up, z forward, each in [-1, 1] (WASD, E/Q)
    bool fast = false;      // shift: fly four times as fast
    float seconds = 0.0f;   // time the fly keys were held this frame
    float viewportHeight = 1.0f; // screen units, so a pan follows the cursor
};

class CameraController {
public:
    // `sceneCenter` and `sceneRadius` set the orbit target of a camera that does not look at
    // the scene's centre, the fly speed and the closest dolly distance.
    CameraController(const Camera& start, glm::vec3 sceneCenter, float sceneRadius);

    // Jumps to `camera` (reset, or another of the file's cameras).
    void setCamera(const Camera& camera);
    const Camera& camera() const { return camera_; }
    glm::vec3 target() const { return camera_.position + camera_.forward * distance_; }
    float distance() const { return distance_; }
    glm::vec3 worldUp() const { return worldUp_; }

    // Applies a frame of input; true when the camera changed.
    bool apply(const CameraInput& input);

    // The primitive moves, in radians and world units.
    void orbit(float yaw, float pitch);
    void look(float yaw, float pitch);
    void pan(glm::vec2 screenDelta, float viewportHeight);
    void dolly(float steps);
    void fly(glm::vec3 move, float worldDistance);

private:
    // Turns the view direction by `yaw` about the world up and `pitch` towards it, keeping it
    // off the poles so that the basis stays defined.
    void turn(float yaw, float pitch);

    Camera camera_;
    glm::vec3 worldUp_{0.0f, 1.0f, 0.0f};
    glm::vec3 sceneCenter_;
    float sceneRadius_;
    float distance_ = 1.0f;
};

// The world axis (+-X, +-Y, +-Z) nearest to `up`: orbits turn about it. glTF is Y-up, but a
// file camera may have any roll.
glm::vec3 nearestAxis(glm::vec3 up);

} // namespace wf
