#include "viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace wf {
namespace {

// A drag across the full viewport height turns the view by half a turn.
constexpr float kRadiansPerViewport = 3.14159265f;
// Elevation stays this far from straight up or down (about 0.6 degrees).
constexpr float kMaxElevation = 1.5603f;
constexpr float kDollyFactor = 0.85f;  // per wheel step
constexpr float kFlySpeed = 0.5f;      // scene radii per second

} // namespace

glm::vec3 nearestAxis(glm::vec3 up) {
    glm::vec3 a = glm::abs(up);
    glm::vec3 axis(0.0f);
    int i = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    axis[i] = up[i] < 0.0f ? -1.0f : 1.0f;
    return axis;
}

CameraController::CameraController(const Camera& start, glm::vec3 sceneCenter,
                                   float sceneRadius)
    : sceneCenter_(sceneCenter), sceneRadius_(std::max(sceneRadius, 1e-6f)) {
    setCamera(start);
}

void CameraController::setCamera(const Camera& camera) {
    camera_ = camera;
    worldUp_ = nearestAxis(camera.up);
    // Orbit about the point of the view axis nearest the scene's centre; a camera looking
    // away from the scene orbits a point one scene radius ahead instead.
    float along = glm::dot(sceneCenter_ - camera.position, camera.forward);
    distance_ = along > 1e-3f * sceneRadius_ ? along : sceneRadius_;
}

bool CameraController::apply(const CameraInput& input) {
    const Camera before = camera_;
    const float perUnit = kRadiansPerViewport / std::max(input.viewportHeight, 1.0f);
    if (input.orbit != glm::vec2(0.0f))
        orbit(-input.orbit.x * perUnit, input.orbit.y * perUnit);
    if (input.look != glm::vec2(0.0f))
        look(-input.look.x * perUnit, -input.look.y * perUnit);
    if (input.pan != glm::vec2(0.0f))
        pan(input.pan, input.viewportHeight);
    if (input.dolly != 0.0f)
        dolly(input.dolly);
    if (input.move != glm::vec3(0.0f) && input.seconds > 0.0f)
        fly(input.move, kFlySpeed * sceneRadius_ * input.seconds * (input.fast ? 4.0f : 1.0f));
    return camera_.position != before.position || camera_.forward != before.forward ||
           camera_.up != before.up;
}

void CameraController::turn(float yaw, float pitch) {
    const glm::vec3 f = camera_.forward;
    float elevation = std::asin(std::clamp(glm::dot(f, worldUp_), -1.0f, 1.0f));
    glm::vec3 horizontal = f - worldUp_ * glm::dot(f, worldUp_);
    if (glm::length(horizontal) < 1e-6f) // looking straight along the axis: use the camera's up
        horizontal = camera_.up * (elevation > 0.0f ? -1.0f : 1.0f);
    horizontal = glm::normalize(horizontal - worldUp_ * glm::dot(horizontal, worldUp_));
    // Rodrigues about worldUp for a vector perpendicular to it.
    horizontal = horizontal * std::cos(yaw) + glm::cross(worldUp_, horizontal) * std::sin(yaw);
    elevation = std::clamp(elevation + pitch, -kMaxElevation, kMaxElevation);
    camera_.forward = glm::normalize(horizontal * std::cos(elevation) +
                                     worldUp_ * std::sin(elevation));
    // Recomputed from the world up: an orbit levels a rolled file camera, as users expect.
    const glm::vec3 right = glm::normalize(glm::cross(camera_.forward, worldUp_));
    camera_.up = glm::normalize(glm::cross(right, camera_.forward));
}

void CameraController::orbit(float yaw, float pitch) {
    const glm::vec3 pivot = target();
    // Turntable, as in Blender: dragging down raises the camera to look down on the target.
    turn(yaw, -pitch);
    camera_.position = pivot - camera_.forward * distance_;
}

void CameraController::look(float yaw, float pitch) { turn(yaw, pitch); }

void CameraController::pan(glm::vec2 screenDelta, float viewportHeight) {
    // World units per screen unit at the target's depth, so the target follows the cursor.
    const float scale =
        2.0f * distance_ * std::tan(0.5f * camera_.yfov) / std::max(viewportHeight, 1.0f);
    const glm::vec3 right = glm::normalize(glm::cross(camera_.forward, camera_.up));
    camera_.position += (-right * screenDelta.x + camera_.up * screenDelta.y) * scale;
}

void CameraController::dolly(float steps) {
    const glm::vec3 pivot = target();
    distance_ = std::max(distance_ * std::pow(kDollyFactor, steps), 1e-4f * sceneRadius_);
    camera_.position = pivot - camera_.forward * distance_;
}

void CameraController::fly(glm::vec3 move, float worldDistance) {
    const glm::vec3 right = glm::normalize(glm::cross(camera_.forward, camera_.up));
    camera_.position +=
        (right * move.x + worldUp_ * move.y + camera_.forward * move.z) * worldDistance;
}

} // namespace wf
