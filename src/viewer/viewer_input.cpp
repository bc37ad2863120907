#include "viewer/viewer_input.h"

#include <GLFW/glfw3.h>

#include "viewer/camera_controller.h"
#include "viewer/overlay.h"
#include "viewer/window.h"

namespace wf {

ViewerInput::ViewerInput(Window& window, const Overlay& overlay)
    : window_(window), overlay_(overlay) {
    glfwGetCursorPos(window.handle(), &lastX_, &lastY_);
}

bool ViewerInput::moveCamera(CameraController& camera, float wheel, float seconds) {
    GLFWwindow* handle = window_.handle();
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(handle, &x, &y);
    const glm::vec2 delta(static_cast<float>(x - lastX_), static_cast<float>(y - lastY_));
    lastX_ = x;
    lastY_ = y;
    for (int button = 0; button < 3; ++button) {
        const bool down = glfwGetMouseButton(handle, button) == GLFW_PRESS;
        if (!down)
            dragging_[button] = false;
        else if (!dragging_[button])
            dragging_[button] = !overlay_.wantsMouse();
    }
    auto held = [&](int key) { return glfwGetKey(handle, key) == GLFW_PRESS; };
    const bool keys = !overlay_.wantsKeyboard();
    const bool shift = held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT);

    CameraInput input;
    input.viewportHeight = window_.windowHeight();
    if (dragging_[GLFW_MOUSE_BUTTON_LEFT])
        (shift ? input.pan : input.orbit) = delta;
    if (dragging_[GLFW_MOUSE_BUTTON_MIDDLE])
        input.pan = delta;
    if (dragging_[GLFW_MOUSE_BUTTON_RIGHT])
        input.look = delta;
    if (!overlay_.wantsMouse())
        input.dolly = wheel;
    if (keys) {
        auto axis = [&](int plus, int minus) {
            return (held(plus) ? 1.0f : 0.0f) - (held(minus) ? 1.0f : 0.0f);
        };
        input.move = {axis(GLFW_KEY_D, GLFW_KEY_A), axis(GLFW_KEY_E, GLFW_KEY_Q),
                      axis(GLFW_KEY_W, GLFW_KEY_S)};
        input.fast = shift;
        input.seconds = seconds;
    }
    return camera.apply(input);
}

} // namespace wf
