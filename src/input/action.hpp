// The player's actions (shared/ARCHITECTURE.md, "Player"): one small set with the same meaning
// from every source (keyboard, gamepad, 6-DOF controller, an input file). Axes are -1..1:
// throttle (+ forward), steer (+ right), climb (+ up, aircraft). A held key or a deflected stick
// is its value while held and 0 when released; a device sends an action only when a value changes.
#pragma once
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace npsnet::input {

enum class ActionType : uint8_t { Throttle, Steer, Climb, Fire, Switch, Camera, Quit };
enum class CameraMode : uint8_t { Driver, Chase, Orbit, Map };
inline constexpr int kCameraModes = 4;

struct Action {
  double t = 0;                       // scenario time (s) it takes effect; devices: set when applied
  ActionType type = ActionType::Throttle;
  double value = 0;                   // throttle / steer / climb, -1..1
  std::string to;                     // switch: vehicle id; empty = the next live vehicle
  std::optional<CameraMode> camera;   // camera: the mode; none = the next mode
  int line = 0;                       // its line in an input file (0: from a device)
};

const char* action_name(ActionType a);
const char* camera_name(CameraMode m);
std::optional<ActionType> action_from_name(const std::string& s);
std::optional<CameraMode> camera_from_name(const std::string& s);
CameraMode next_camera(CameraMode m);
bool is_axis(ActionType a);

// One JSON Lines object: {"t": 2.0, "action": "throttle", "value": 1.0}, {"t": 5.0,
// "action": "fire"}, {"t": 6.0, "action": "switch", "to": "tank2"}, {"t": 7.0, "action":
// "camera", "mode": "chase"}, {"t": 9.0, "action": "quit"}. t is rounded to the microsecond.
nlohmann::json to_json(const Action& a);

// Appends an axis action when `now` differs from `cur` (a device's last sent value), then cur = now.
void emit_axis(ActionType t, double& cur, double now, std::vector<Action>& out);

}  // namespace npsnet::input
