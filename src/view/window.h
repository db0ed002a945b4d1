#pragma once
// A GLFW window with a Vulkan surface, and its input as a queue of events in
// view coordinates. The viewer's only contact with the window system.
#include <vulkan/vulkan.h>

#include <deque>
#include <glm/glm.hpp>
#include <stdexcept>
#include <string>
#include <vector>

struct GLFWwindow;

namespace shadelab {

enum class MouseButton { Left, Right, Middle };

struct InputEvent {
  enum class Kind { Key, ButtonDown, ButtonUp, Move, Scroll } kind = Kind::Key;
  int key = 0;  // GLFW key code (ASCII for digits and letters)
  MouseButton button = MouseButton::Left;
  glm::vec2 position{0.0f};  // view coordinates: pixels, origin bottom-left, y up
  float scroll = 0.0f;       // wheel steps, positive away from the user
};

// No window could be opened: the environment's fault (no X server), not the
// user's input nor a Vulkan failure. Exit code 1 with the reason.
class WindowError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Window coordinates have their origin top-left with y down; everything the
// viewer computes uses y up. This is the one place that converts.
glm::vec2 windowToView(glm::dvec2 window, glm::ivec2 windowSize);

class Window {
 public:
  // Throws WindowError naming the reason when no window can be opened (no
  // DISPLAY, no Vulkan-capable GLFW).
  Window(const std::string& title, uint32_t width, uint32_t height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  static std::vector<const char*> requiredInstanceExtensions();
  VkSurfaceKHR createSurface(VkInstance instance) const;

  void pollEvents();
  void waitEvents(double timeoutSeconds);
  bool closeRequested() const;
  glm::ivec2 framebufferSize() const;
  glm::ivec2 windowSize() const;
  bool iconified() const;
  void setSize(uint32_t width, uint32_t height);
  void iconify();
  void restore();

  std::deque<InputEvent>& events() { return events_; }
  // Scripted input goes through the same conversion as real input.
  void injectButton(MouseButton button, bool down, glm::dvec2 windowPosition);
  void injectMove(glm::dvec2 windowPosition);

 private:
  static Window& of(GLFWwindow* window);
  GLFWwindow* window_ = nullptr;
  std::deque<InputEvent> events_;
};

}  // namespace shadelab
