#include "input/devices.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cmath>

#include "input/gamepad.hpp"
#include "input/keyboard.hpp"
#include "input/spacenav.hpp"

namespace npsnet::input {

namespace {
constexpr double kOrbitDegPerPixel = 0.3;
constexpr double kOrbitDegPerKey = 10.0;
constexpr double kZoomPerWheelStep = 0.85;
}  // namespace

double steady_now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Devices::Impl {
  GLFWwindow* win = nullptr;
  KeyboardMapper keys;
  GamepadMapper pads[GLFW_JOYSTICK_LAST + 1];
  std::unique_ptr<SpacenavDevice> spacenav;
  std::vector<TimedAction> pending;
  std::vector<Action> scratch;
  bool dragging = false;
  double last_x = 0, orbit_deg = 0, zoom = 1;

  void add_scratch() {
    const double now = steady_now_s();
    for (auto& a : scratch) pending.push_back({a, now});
    scratch.clear();
  }
  static Impl& of(GLFWwindow* w) { return *static_cast<Impl*>(glfwGetWindowUserPointer(w)); }
};

Devices::Devices(void* glfw_window) : p_(std::make_unique<Impl>()) {
  p_->win = static_cast<GLFWwindow*>(glfw_window);
  glfwSetWindowUserPointer(p_->win, p_.get());
  glfwSetKeyCallback(p_->win, [](GLFWwindow* w, int key, int, int action, int) {
    Impl& p = Impl::of(w);
    if (key == GLFW_KEY_Q || key == GLFW_KEY_E) {
      if (action != GLFW_RELEASE) p.orbit_deg += key == GLFW_KEY_E ? kOrbitDegPerKey : -kOrbitDegPerKey;
      return;
    }
    p.keys.key(key, action, p.scratch);
    p.add_scratch();
  });
  glfwSetMouseButtonCallback(p_->win, [](GLFWwindow* w, int button, int action, int) {
    Impl& p = Impl::of(w);
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    p.dragging = action == GLFW_PRESS;
    double y = 0;
    glfwGetCursorPos(w, &p.last_x, &y);
  });
  glfwSetCursorPosCallback(p_->win, [](GLFWwindow* w, double x, double) {
    Impl& p = Impl::of(w);
    if (p.dragging) p.orbit_deg += (x - p.last_x) * kOrbitDegPerPixel;
    p.last_x = x;
  });
  glfwSetScrollCallback(p_->win, [](GLFWwindow* w, double, double dy) {
    Impl::of(w).zoom *= std::pow(kZoomPerWheelStep, dy);
  });
  p_->spacenav = std::make_unique<SpacenavDevice>();
}

Devices::~Devices() {
  glfwSetKeyCallback(p_->win, nullptr);
  glfwSetMouseButtonCallback(p_->win, nullptr);
  glfwSetCursorPosCallback(p_->win, nullptr);
  glfwSetScrollCallback(p_->win, nullptr);
  glfwSetWindowUserPointer(p_->win, nullptr);
}

std::vector<TimedAction> Devices::take() {
  Impl& p = *p_;
  for (int j = GLFW_JOYSTICK_1; j <= GLFW_JOYSTICK_LAST; ++j) {
    GLFWgamepadstate st;
    if (glfwJoystickIsGamepad(j) && glfwGetGamepadState(j, &st)) p.pads[j].update(st.axes, st.buttons, p.scratch);
  }
  p.spacenav->poll(p.scratch);
  p.add_scratch();
  std::vector<TimedAction> out;
  out.swap(p.pending);
  return out;
}

double Devices::take_orbit_deg() {
  const double d = p_->orbit_deg;
  p_->orbit_deg = 0;
  return d;
}

double Devices::take_zoom() {
  const double z = p_->zoom;
  p_->zoom = 1;
  return z;
}

}  // namespace npsnet::input
