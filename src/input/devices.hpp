// The live input devices of a windowed node: the GLFW window's keyboard (keyboard.hpp) and mouse,
// every connected gamepad through GLFW's gamepad mappings (gamepad.hpp), and a 6-DOF controller
// through spacenavd (spacenav.hpp). The window's events arrive while the renderer polls them
// (glfwPollEvents / glfwWaitEventsTimeout); take() then polls gamepads and spacenavd and hands
// over every action since the last call, each with the wall time it arrived.
// Orbit-camera control is a view setting, not an action: left-drag or Q/E turn the orbit, the
// wheel zooms it.
#pragma once
#include <memory>
#include <vector>

#include "input/action.hpp"

namespace npsnet::input {

struct TimedAction {
  Action action;
  double wall_s = 0;  // steady clock (s) when the device event arrived
};

double steady_now_s();

class Devices {
 public:
  // glfw_window: the GLFWwindow* of the node's window; its key, mouse button, cursor and scroll
  // callbacks are taken over.
  explicit Devices(void* glfw_window);
  ~Devices();
  Devices(const Devices&) = delete;
  Devices& operator=(const Devices&) = delete;

  std::vector<TimedAction> take();
  // Orbit camera: degrees turned (+ = clockwise seen from above) and zoom factor since the last call.
  double take_orbit_deg();
  double take_zoom();

 private:
  struct Impl;
  std::unique_ptr<Impl> p_;
};

}  // namespace npsnet::input
