#include "input/spacenav.hpp"

#include <spnav.h>

#include <algorithm>
#include <cstdio>

#include "input/gamepad.hpp"

namespace npsnet::input {

void SpacenavMapper::motion(const SpacenavMotion& m, std::vector<Action>& out) {
  const auto shaped = [](int raw) { return shape_axis(std::clamp(raw / kSpacenavFullScale, -1.0, 1.0)); };
  emit_axis(ActionType::Throttle, throttle_, shaped(m.z), out);
  emit_axis(ActionType::Steer, steer_, shaped(-m.ry), out);
  emit_axis(ActionType::Climb, climb_, shaped(m.y), out);
}

void SpacenavMapper::button(int number, bool press, std::vector<Action>& out) {
  if (number == 0 && press) out.push_back(Action{0, ActionType::Fire, 0, {}, {}});
}

SpacenavDevice::SpacenavDevice() {
  open_ = spnav_open() == 0;
  if (!open_)
    std::fprintf(stderr, "npsnet: 6-DOF controller: spacenavd is not running; going on with keyboard and gamepad\n");
}

SpacenavDevice::~SpacenavDevice() {
  if (open_) spnav_close();
}

void SpacenavDevice::poll(std::vector<Action>& out) {
  if (!open_) return;
  spnav_event ev;
  SpacenavMotion last;
  bool moved = false;
  while (spnav_poll_event(&ev) > 0) {
    if (ev.type == SPNAV_EVENT_MOTION) {
      last = {ev.motion.x, ev.motion.y, ev.motion.z, ev.motion.rx, ev.motion.ry, ev.motion.rz};
      moved = true;
    } else if (ev.type == SPNAV_EVENT_BUTTON) {
      map_.button(ev.button.bnum, ev.button.press != 0, out);
    }
  }
  if (moved) map_.motion(last, out);
}

}  // namespace npsnet::input
