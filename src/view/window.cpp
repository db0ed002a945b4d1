#include "view/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include "core/base/errors.h"
#include "core/vulkan/vk_check.h"

namespace shadelab {
namespace {

std::string lastGlfwError;

void onGlfwError(int, const char* description) {
  lastGlfwError = description;
}

MouseButton buttonOf(int glfwButton) {
  if (glfwButton == GLFW_MOUSE_BUTTON_RIGHT) return MouseButton::Right;
  if (glfwButton == GLFW_MOUSE_BUTTON_MIDDLE) return MouseButton::Middle;
  return MouseButton::Left;
}

}  // namespace

glm::vec2 windowToView(glm::dvec2 window, glm::ivec2 windowSize) {
  return {float(window.x), float(double(windowSize.y) - window.y)};
}

Window::Window(const std::string& title, uint32_t width, uint32_t height) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit())
    throw WindowError("cannot open a window (" + lastGlfwError +
                      "); run under an X server, e.g. Xvfb :1 & DISPLAY=:1");
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw WindowError("GLFW finds no Vulkan loader for windows");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw WindowError("cannot create a window: " + lastGlfwError);
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_PRESS) of(w).events_.push_back({InputEvent::Kind::Key, key});
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    double x, y;
    glfwGetCursorPos(w, &x, &y);
    of(w).injectButton(buttonOf(button), action == GLFW_PRESS, {x, y});
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    of(w).injectMove({x, y});
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double y) {
    InputEvent event{InputEvent::Kind::Scroll};
    event.scroll = float(y);
    of(w).events_.push_back(event);
  });
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

Window& Window::of(GLFWwindow* window) {
  return *static_cast<Window*>(glfwGetWindowUserPointer(window));
}

std::vector<const char*> Window::requiredInstanceExtensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw VulkanError("GLFW reports no Vulkan surface extensions: " + lastGlfwError);
  return {names, names + count};
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
  return surface;
}

void Window::pollEvents() {
  glfwPollEvents();
}
void Window::waitEvents(double timeoutSeconds) {
  glfwWaitEventsTimeout(timeoutSeconds);
}
bool Window::closeRequested() const {
  return glfwWindowShouldClose(window_);
}

glm::ivec2 Window::framebufferSize() const {
  glm::ivec2 size;
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

glm::ivec2 Window::windowSize() const {
  glm::ivec2 size;
  glfwGetWindowSize(window_, &size.x, &size.y);
  return size;
}

bool Window::iconified() const {
  return glfwGetWindowAttrib(window_, GLFW_ICONIFIED);
}
void Window::setSize(uint32_t width, uint32_t height) {
  glfwSetWindowSize(window_, int(width), int(height));
}
void Window::iconify() {
  glfwIconifyWindow(window_);
}
void Window::restore() {
  glfwRestoreWindow(window_);
}

void Window::injectButton(MouseButton button, bool down, glm::dvec2 windowPosition) {
  InputEvent event{down ? InputEvent::Kind::ButtonDown : InputEvent::Kind::ButtonUp};
  event.button = button;
  event.position = windowToView(windowPosition, windowSize());
  events_.push_back(event);
}

void Window::injectMove(glm::dvec2 windowPosition) {
  InputEvent event{InputEvent::Kind::Move};
  event.position = windowToView(windowPosition, windowSize());
  events_.push_back(event);
}

}  // namespace shadelab
