// Mouse and held keys to camera moves. A drag belongs to the camera only if it started outside
// the overlay, so dragging a slider never also orbits; keys are ignored while the overlay has
// the keyboard (typing a seed).
#pragma once

namespace wf {

class CameraController;
class Overlay;
class Window;

class ViewerInput {
public:
    ViewerInput(Window& window, const Overlay& overlay);

    // Applies this frame's drags, wheel steps (`wheel`) and held fly keys (`seconds` since
    // the last frame) to `camera`; true when it moved.
    bool moveCamera(CameraController& camera, float wheel, float seconds);

private:
    Window& window_;
    const Overlay& overlay_;
    double lastX_ = 0.0;
    double lastY_ = 0.0;
    bool dragging_[3] = {false, false, false}; // left, right, middle (GLFW's button order)
};

} // namespace wf
