#include "input/action.hpp"

#include <cmath>

namespace npsnet::input {

namespace {
constexpr const char* kActionNames[] = {"throttle", "steer", "climb", "fire", "switch", "camera", "quit"};
constexpr const char* kCameraNames[] = {"driver", "chase", "orbit", "map"};
}  // namespace

const char* action_name(ActionType a) { return kActionNames[static_cast<int>(a)]; }
const char* camera_name(CameraMode m) { return kCameraNames[static_cast<int>(m)]; }

std::optional<ActionType> action_from_name(const std::string& s) {
  for (int i = 0; i < 7; ++i)
    if (s == kActionNames[i]) return static_cast<ActionType>(i);
  return std::nullopt;
}

std::optional<CameraMode> camera_from_name(const std::string& s) {
  for (int i = 0; i < kCameraModes; ++i)
    if (s == kCameraNames[i]) return static_cast<CameraMode>(i);
  return std::nullopt;
}

CameraMode next_camera(CameraMode m) { return static_cast<CameraMode>((static_cast<int>(m) + 1) % kCameraModes); }

bool is_axis(ActionType a) { return a == ActionType::Throttle || a == ActionType::Steer || a == ActionType::Climb; }

nlohmann::json to_json(const Action& a) {
  nlohmann::json j = {{"t", std::round(a.t * 1e6) / 1e6}, {"action", action_name(a.type)}};
  if (is_axis(a.type)) j["value"] = std::round(a.value * 1e6) / 1e6;
  if (a.type == ActionType::Switch && !a.to.empty()) j["to"] = a.to;
  if (a.type == ActionType::Camera && a.camera) j["mode"] = camera_name(*a.camera);
  return j;
}

void emit_axis(ActionType t, double& cur, double now, std::vector<Action>& out) {
  if (now == cur) return;
  cur = now;
  Action a;
  a.type = t, a.value = now;
  out.push_back(a);
}

}  // namespace npsnet::input
