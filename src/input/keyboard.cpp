#include "input/keyboard.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace npsnet::input {

int KeyboardMapper::axis(int plus_a, int plus_b, int minus_a, int minus_b) const {
  const bool plus = held_.count(plus_a) || held_.count(plus_b);
  const bool minus = held_.count(minus_a) || held_.count(minus_b);
  return (plus ? 1 : 0) - (minus ? 1 : 0);
}

void KeyboardMapper::key(int k, int act, std::vector<Action>& out) {
  if (act == GLFW_REPEAT) return;
  const bool press = act == GLFW_PRESS;
  if (press) held_.insert(k);
  else held_.erase(k);
  switch (k) {
    case GLFW_KEY_W: case GLFW_KEY_UP: case GLFW_KEY_S: case GLFW_KEY_DOWN:
      emit_axis(ActionType::Throttle, throttle_, axis(GLFW_KEY_W, GLFW_KEY_UP, GLFW_KEY_S, GLFW_KEY_DOWN), out);
      return;
    case GLFW_KEY_D: case GLFW_KEY_RIGHT: case GLFW_KEY_A: case GLFW_KEY_LEFT:
      emit_axis(ActionType::Steer, steer_, axis(GLFW_KEY_D, GLFW_KEY_RIGHT, GLFW_KEY_A, GLFW_KEY_LEFT), out);
      return;
    case GLFW_KEY_R: case GLFW_KEY_F:
      emit_axis(ActionType::Climb, climb_, axis(GLFW_KEY_R, GLFW_KEY_R, GLFW_KEY_F, GLFW_KEY_F), out);
      return;
    default: break;
  }
  if (!press) return;
  Action a;
  switch (k) {
    case GLFW_KEY_SPACE: a.type = ActionType::Fire; break;
    case GLFW_KEY_TAB: a.type = ActionType::Switch; break;
    case GLFW_KEY_C: a.type = ActionType::Camera; break;
    case GLFW_KEY_ESCAPE: a.type = ActionType::Quit; break;
    default: return;
  }
  out.push_back(a);
}

}  // namespace npsnet::input
