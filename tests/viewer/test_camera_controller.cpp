// The viewer's camera moves, on the CPU: an untouched controller is the start camera bit for
// bit (the viewer's first image is the render command's), orbits keep the target and
// distance, pans keep the direction, dollies keep the target, and the basis stays orthonormal.
#include <cmath>

#include <gtest/gtest.h>

#include "viewer/camera_controller.h"

namespace wf {
namespace {

constexpr float kEps = 1e-4f;

Camera tiltedCamera() {
    Camera camera;
    camera.position = {0.0f, 2.0f, 5.0f};
    camera.forward = glm::normalize(glm::vec3(0.0f, -0.4f, -1.0f));
    const glm::vec3 right = glm::normalize(glm::cross(camera.forward, glm::vec3(0, 1, 0)));
    camera.up = glm::normalize(glm::cross(right, camera.forward));
    return camera;
}

void expectNear(glm::vec3 a, glm::vec3 b, float eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

void expectOrthonormal(const Camera& camera) {
    EXPECT_NEAR(glm::length(camera.forward), 1.0f, kEps);
    EXPECT_NEAR(glm::length(camera.up), 1.0f, kEps);
    EXPECT_NEAR(glm::dot(camera.forward, camera.up), 0.0f, kEps);
}

TEST(CameraController, UntouchedIsTheStartCameraExactly) {
    const Camera start = tiltedCamera();
    CameraController controller(start, glm::vec3(0.0f), 1.0f);
    EXPECT_FALSE(controller.apply(CameraInput{}));
    EXPECT_EQ(controller.camera().position, start.position);
    EXPECT_EQ(controller.camera().forward, start.forward);
    EXPECT_EQ(controller.camera().up, start.up);
    EXPECT_EQ(controller.camera().yfov, start.yfov);
}

TEST(CameraController, TargetIsTheViewAxisPointNearestTheScene) {
    CameraController controller(tiltedCamera(), glm::vec3(0.0f), 1.0f);
    const glm::vec3 toCenter = -tiltedCamera().position;
    EXPECT_NEAR(controller.distance(), glm::dot(toCenter, tiltedCamera().forward), kEps);
    EXPECT_EQ(controller.worldUp(), glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST(CameraController, OrbitKeepsTargetAndDistanceAndFullTurnReturns) {
    CameraController controller(tiltedCamera(), glm::vec3(0.0f), 1.0f);
    const glm::vec3 target = controller.target();
    const float distance = controller.distance();
    for (int i = 0; i < 4; ++i) {
        controller.orbit(0.5f * 3.14159265f, 0.0f);
        expectNear(controller.target(), target);
        EXPECT_NEAR(glm::length(controller.camera().position - target), distance, kEps);
        expectOrthonormal(controller.camera());
    }
    expectNear(controller.camera().position, tiltedCamera().position);
}

TEST(CameraController, OrbitStopsShortOfThePole) {
    CameraController controller(tiltedCamera(), glm::vec3(0.0f), 1.0f);
    controller.orbit(0.0f, 10.0f); // far more than a quarter turn
    const float elevation = std::asin(glm::dot(controller.camera().forward, glm::vec3(0, 1, 0)));
    EXPECT_GT(elevation, -1.5708f);
    EXPECT_LT(elevation, -1.55f); // looking almost straight down on the target
    expectOrthonormal(controller.camera());
}

TEST(CameraController, PanMovesCameraAndTargetAlike) {
    CameraController controller(tiltedCamera(), glm::vec3(0.0f), 1.0f);
    const glm::vec3 offset = controller.camera().position - controller.target();
    controller.pan({30.0f, -10.0f}, 600.0f);
    expectNear(controller.camera().forward, tiltedCamera().forward);
    expectNear(controller.camera().position - controller.target(), offset);
    // Dragging right moves the scene right: the camera moves left.
    const glm::vec3 right = glm::cross(tiltedCamera().forward, tiltedCamera().up);
    EXPECT_LT(glm::dot(controller.camera().position - tiltedCamera().position, right), 0.0f);
}

TEST(CameraController, DollyKeepsTheTarget) {
    CameraController controller(tiltedCamera(), glm::vec3(0.0f), 1.0f);
    const glm::vec3 target = controller.target();
    const float distance = controller.distance();
    controller.dolly(2.0f);
    expectNear(controller.target(), target);
    EXPECT_NEAR(controller.distance(), distance * 0.85f * 0.85f, kEps);
    controller.dolly(1000.0f); // never through the target
    EXPECT_GT(controller.distance(), 0.0f);
}

TEST(CameraController, FlyMovesAlongTheViewAndLookTurnsInPlace) {
    CameraController controller(tiltedCamera(), glm::vec3(0.0f), 1.0f);
    controller.fly({0.0f, 0.0f, 1.0f}, 2.0f);
    expectNear(controller.camera().position,
               tiltedCamera().position + 2.0f * tiltedCamera().forward);
    const glm::vec3 position = controller.camera().position;
    controller.look(0.3f, 0.1f);
    EXPECT_EQ(controller.camera().position, position);
    expectOrthonormal(controller.camera());
}

TEST(CameraController, InputDragsMoveAndSetCameraResets) {
    CameraController controller(tiltedCamera(), glm::vec3(0.0f), 1.0f);
    CameraInput input;
    input.orbit = {40.0f, 0.0f};
    input.viewportHeight = 600.0f;
    EXPECT_TRUE(controller.apply(input));
    controller.setCamera(tiltedCamera());
    EXPECT_EQ(controller.camera().position, tiltedCamera().position);
    EXPECT_EQ(controller.camera().forward, tiltedCamera().forward);
}

TEST(CameraController, NearestAxis) {
    EXPECT_EQ(nearestAxis({0.1f, 0.9f, 0.3f}), glm::vec3(0, 1, 0));
    EXPECT_EQ(nearestAxis({0.1f, 0.2f, -0.9f}), glm::vec3(0, 0, -1));
}

} // namespace
} // namespace wf
