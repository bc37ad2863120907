#include "viewer/viewer_input.h"

#include <GLFW/glfw3.h>

#include "viewer/camera_controller.h"
#include "viewer/overlay.h"
#include "viewer/window.h"

namespace wf {

ViewerInput::ViewerInput(Window& window, const Overlay& overlay)
    : window_(window), overlay_(overlay) {}

bool ViewerInput::moveCamera(CameraController& camera, const WindowEvents& events,
                             float seconds) {
    GLFWwindow* handle = window_.handle();
    // A drag the overlay did not want when the frame first saw its button down is the
    // camera's until the button is released (the release may be in this very batch).
    for (int button = 0; button < 3; ++button) {
        if (!events.buttonDown[button])
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
        (shift ? input.pan : input.orbit) = events.drag[GLFW_MOUSE_BUTTON_LEFT];
    if (dragging_[GLFW_MOUSE_BUTTON_MIDDLE])
        input.pan = events.drag[GLFW_MOUSE_BUTTON_MIDDLE];
    if (dragging_[GLFW_MOUSE_BUTTON_RIGHT])
        input.look = events.drag[GLFW_MOUSE_BUTTON_RIGHT];
    if (!overlay_.wantsMouse())
        input.dolly = events.wheel;
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
