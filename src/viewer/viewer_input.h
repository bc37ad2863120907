// Mouse and held keys to camera moves. A drag belongs to the camera only if it started outside
// the overlay, so dragging a slider never also orbits; keys are ignored while the overlay has
// the keyboard (typing a seed).
#pragma once

namespace wf {

class CameraController;
class Overlay;
class Window;
struct WindowEvents;

class ViewerInput {
public:
    ViewerInput(Window& window, const Overlay& overlay);

    // Applies the drags and wheel steps gathered since the last frame (`events`) and the held
    // fly keys (`seconds` since the last frame) to `camera`; true when it moved.
    bool moveCamera(CameraController& camera, const WindowEvents& events, float seconds);

private:
    Window& window_;
    const Overlay& overlay_;
    bool dragging_[3] = {false, false, false}; // left, right, middle (GLFW's button order)
};

} // namespace wf
