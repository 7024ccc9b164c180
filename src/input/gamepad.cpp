#include "input/gamepad.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

namespace npsnet::input {

double shape_axis(double raw) {
  if (!std::isfinite(raw)) return 0;
  const double a = std::abs(raw);
  if (a <= kStickDeadZone) return 0;
  const double v = std::min(1.0, (a - kStickDeadZone) / (1 - kStickDeadZone));
  return std::copysign(std::round(v / kStickStep) * kStickStep, raw);
}

void GamepadMapper::update(const float* axes, const unsigned char* buttons, std::vector<Action>& out) {
  emit_axis(ActionType::Throttle, throttle_, shape_axis(-axes[GLFW_GAMEPAD_AXIS_LEFT_Y]), out);
  emit_axis(ActionType::Steer, steer_, shape_axis(axes[GLFW_GAMEPAD_AXIS_LEFT_X]), out);
  emit_axis(ActionType::Climb, climb_, shape_axis(-axes[GLFW_GAMEPAD_AXIS_RIGHT_Y]), out);
  const bool fire = buttons[GLFW_GAMEPAD_BUTTON_A] == GLFW_PRESS || axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] > 0.5f;
  if (fire && !fire_) out.push_back(Action{0, ActionType::Fire, 0, {}, {}});
  fire_ = fire;
  const bool sw = buttons[GLFW_GAMEPAD_BUTTON_Y] == GLFW_PRESS;
  if (sw && !sw_) out.push_back(Action{0, ActionType::Switch, 0, {}, {}});
  sw_ = sw;
}

}  // namespace npsnet::input
