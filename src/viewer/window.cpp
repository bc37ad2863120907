#include "viewer/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "errors.h"
#include "gpu/vk_check.h"

namespace wf {
namespace {

std::string lastGlfwError;

void onGlfwError(int, const char* description) { lastGlfwError = description; }

[[noreturn]] void throwWindowError(const std::string& what) {
    std::string message = "cannot open the viewer window: " + what;
    if (!lastGlfwError.empty())
        message += ": " + lastGlfwError;
    message += ". wavefront view needs a display (X11 or Wayland); on a headless machine run it "
               "under xvfb-run.";
    throw InternalError(message);
}

} // namespace

Window::Window(const std::string& title, WindowSize size) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit())
        throwWindowError("glfwInit failed");
    if (!glfwVulkanSupported()) {
        glfwTerminate();
        throwWindowError("GLFW found no Vulkan loader");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    // On HiDPI X11 and Windows, --width/--height are in logical pixels, like everything else.
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    window_ = glfwCreateWindow(size.width, size.height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throwWindowError("glfwCreateWindow failed");
    }
    glfwSetWindowUserPointer(window_, this);
    // Installed before the overlay's, which chains to these.
    glfwSetKeyCallback(window_, onKey);
    glfwSetScrollCallback(window_, onScroll);
    glfwSetMouseButtonCallback(window_, onMouseButton);
    glfwSetCursorPosCallback(window_, onCursor);
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    cursor_ = glm::vec2(static_cast<float>(x), static_cast<float>(y));
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

std::vector<const char*> Window::instanceExtensions() const {
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    if (!names)
        throwWindowError("no Vulkan surface extensions for this window system");
    return {names, names + count};
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
    VkSurfaceKHR surface = VK_NULL_HANDLE;
    VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
    return surface;
}

VkExtent2D Window::framebufferSize() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {static_cast<uint32_t>(width), static_cast<uint32_t>(height)};
}

float Window::contentScale() const {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(window_, &x, &y);
    return y > 0.0f ? y : 1.0f;
}

float Window::windowHeight() const {
    int width = 0, height = 0;
    glfwGetWindowSize(window_, &width, &height);
    return static_cast<float>(height);
}

void Window::setSize(int width, int height) { glfwSetWindowSize(window_, width, height); }

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }

void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void Window::pollEvents() { glfwPollEvents(); }

void Window::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }

WindowEvents Window::takeEvents() {
    WindowEvents events = std::move(events_);
    events_ = {};
    for (int button = 0; button < 3; ++button)
        events_.buttonDown[button] = buttonHeld_[button];
    return events;
}

void Window::onKey(GLFWwindow* window, int key, int, int action, int mods) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    if (action == GLFW_PRESS) {
        self->events_.keysPressed.push_back(key);
        self->events_.keyMods.push_back(mods);
    }
}

void Window::onScroll(GLFWwindow* window, double, double y) {
    static_cast<Window*>(glfwGetWindowUserPointer(window))->events_.wheel +=
        static_cast<float>(y);
}

void Window::onMouseButton(GLFWwindow* window, int button, int action, int) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    if (button < 0 || button >= 3)
        return;
    if (action == GLFW_PRESS) {
        // The drag starts at the last cursor event, the press's place in the event order (not
        // glfwGetCursorPos: the pointer may be further on by the time a slow frame reads its
        // queue), so movement before the press is not part of it.
        self->buttonHeld_[button] = true;
        self->events_.buttonDown[button] = true;
    } else if (action == GLFW_RELEASE) {
        self->buttonHeld_[button] = false;
    }
}

void Window::onCursor(GLFWwindow* window, double x, double y) {
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    const glm::vec2 cursor(static_cast<float>(x), static_cast<float>(y));
    for (int button = 0; button < 3; ++button)
        if (self->buttonHeld_[button])
            self->events_.drag[button] += cursor - self->cursor_;
    self->cursor_ = cursor;
}

} // namespace wf
