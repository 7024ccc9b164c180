// Six-degree-of-freedom controller -> actions through libspnav and spacenavd (the thesis's
// SpaceBall: pressure adds thrust in that direction, the pick button fires). spacenavd's axes: x
// right, y up, z forward (push away from you = +z), rotations right-handed about them. Push
// forward/back = throttle, twist about the vertical (clockwise seen from above = right) = steer,
// lift/press = climb, button 0 (the first, the pick button) = fire. Full deflection is
// kSpacenavFullScale device units; axes go through the gamepad's dead zone and quantisation.
#pragma once
#include <vector>

#include "input/action.hpp"

namespace npsnet::input {

inline constexpr double kSpacenavFullScale = 350.0;

struct SpacenavMotion {
  int x = 0, y = 0, z = 0, rx = 0, ry = 0, rz = 0;
};

class SpacenavMapper {
 public:
  void motion(const SpacenavMotion& m, std::vector<Action>& out);
  void button(int number, bool press, std::vector<Action>& out);

 private:
  double throttle_ = 0, steer_ = 0, climb_ = 0;
};

// The device: connects to spacenavd on first use. When spacenavd is not running it says so once
// on stderr and stays quiet afterwards (poll does nothing).
class SpacenavDevice {
 public:
  SpacenavDevice();
  ~SpacenavDevice();
  SpacenavDevice(const SpacenavDevice&) = delete;
  SpacenavDevice& operator=(const SpacenavDevice&) = delete;
  bool connected() const { return open_; }
  void poll(std::vector<Action>& out);

 private:
  bool open_ = false;
  SpacenavMapper map_;
};

}  // namespace npsnet::input
