// Gamepad -> actions through GLFW's gamepad mappings (SDL_GameControllerDB layout): left stick
// throttle (up = +) and steer (right = +), right stick climb (up = +), right trigger or A fire,
// Y switch. Sticks have a dead zone and are quantised to steps of 0.05 so that a resting or
// trembling stick sends nothing; buttons fire on the press.
#pragma once
#include <array>
#include <vector>

#include "input/action.hpp"

namespace npsnet::input {

inline constexpr double kStickDeadZone = 0.15;
inline constexpr double kStickStep = 0.05;

// Dead zone, rescaled to -1..1 outside it, quantised.
double shape_axis(double raw);

class GamepadMapper {
 public:
  // axes / buttons as in GLFWgamepadstate (6 axes -1..1, 15 buttons 0/1).
  void update(const float* axes, const unsigned char* buttons, std::vector<Action>& out);

 private:
  double throttle_ = 0, steer_ = 0, climb_ = 0;
  bool fire_ = false, sw_ = false;
};

}  // namespace npsnet::input
