// Keyboard -> actions (shared/ARCHITECTURE.md, "Player"): W/S or Up/Down throttle, A/D or
// Left/Right steer, R/F climb, Space fire, Tab switch, C next camera, Esc quit. A held key is its
// axis value from the press and 0 at the release; opposite keys held together cancel. Key codes
// and press/release are GLFW's (GLFW_KEY_*, GLFW_PRESS / GLFW_RELEASE / GLFW_REPEAT).
#pragma once
#include <set>
#include <vector>

#include "input/action.hpp"

namespace npsnet::input {

class KeyboardMapper {
 public:
  // One key event; appends the actions it causes (none for a repeat or an unmapped key).
  void key(int glfw_key, int glfw_action, std::vector<Action>& out);

 private:
  int axis(int plus_a, int plus_b, int minus_a, int minus_b) const;
  std::set<int> held_;
  double throttle_ = 0, steer_ = 0, climb_ = 0;
};

}  // namespace npsnet::input
