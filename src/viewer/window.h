// The viewer's window (GLFW, with no client API: Vulkan presents to it). Owns GLFW's
// initialisation, turns GLFW errors into InternalError with a hint, and gathers the input
// between frames from GLFW's events (key presses, wheel steps, drags), so that a press, move
// and release within one slow frame still count; held fly keys are polled.
#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace wf {

struct WindowEvents {
    std::vector<int> keysPressed; // GLFW_KEY_*, in order (auto-repeat ignored)
    std::vector<int> keyMods;     // GLFW_MOD_* of each press
    float wheel = 0.0f;           // vertical scroll steps
    // Per mouse button (GLFW's order: left, right, middle): whether it was down at some time
    // since the last frame, and how far the cursor moved while it was held (screen units).
    bool buttonDown[3] = {false, false, false};
    glm::vec2 drag[3] = {glm::vec2(0.0f), glm::vec2(0.0f), glm::vec2(0.0f)};
};

struct WindowSize {
    int width;
    int height;
};

class Window {
public:
    // `size` in screen coordinates; the framebuffer may be larger (HiDPI).
    Window(const std::string& title, WindowSize size);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    // What vkCreateInstance needs for this window system's surfaces.
    std::vector<const char*> instanceExtensions() const;
    VkSurfaceKHR createSurface(VkInstance instance) const;

    VkExtent2D framebufferSize() const;
    float contentScale() const; // 1 on a normal screen, 2 on a typical HiDPI one
    float windowHeight() const; // screen coordinates, the unit of the cursor
    void setSize(int width, int height);

    bool shouldClose() const;
    void requestClose();
    void pollEvents();
    void waitEvents(double timeoutSeconds);
    // The events since the last call.
    WindowEvents takeEvents();

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
    static void onScroll(GLFWwindow* window, double x, double y);
    static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
    static void onCursor(GLFWwindow* window, double x, double y);

    GLFWwindow* window_ = nullptr;
    WindowEvents events_;
    bool buttonHeld_[3] = {false, false, false};
    glm::vec2 cursor_ = glm::vec2(0.0f); // where the last cursor event left it
};

} // namespace wf
