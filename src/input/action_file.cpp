#include "input/action_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "world/error.hpp"
#include "world/text_file.hpp"

namespace npsnet::input {

namespace {
// Parses one line into `a`; on failure returns the field and message.
std::optional<std::pair<std::string, std::string>> parse_line(const std::string& line, Action& a) {
  const auto j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_discarded()) return std::pair<std::string, std::string>{"json", "not a JSON object"};
  if (!j.is_object()) return std::pair<std::string, std::string>{"json", "each line must be one JSON object"};
  for (const auto& [k, v] : j.items())
    if (k != "t" && k != "action" && k != "value" && k != "to" && k != "mode")
      return std::pair<std::string, std::string>{k, "unknown field (t, action, value, to, mode)"};
  if (!j.contains("t") || !j["t"].is_number()) return std::pair<std::string, std::string>{"t", "needs a number (scenario seconds)"};
  a.t = j["t"].get<double>();
  if (!std::isfinite(a.t) || a.t < 0) return std::pair<std::string, std::string>{"t", "must be finite and not negative"};
  if (!j.contains("action") || !j["action"].is_string())
    return std::pair<std::string, std::string>{"action", "needs one of throttle, steer, climb, fire, switch, camera, quit"};
  const auto type = action_from_name(j["action"].get<std::string>());
  if (!type)
    return std::pair<std::string, std::string>{"action", "unknown action '" + j["action"].get<std::string>() +
                                                             "' (throttle, steer, climb, fire, switch, camera, quit)"};
  a.type = *type;
  if (is_axis(a.type)) {
    if (!j.contains("value") || !j["value"].is_number()) return std::pair<std::string, std::string>{"value", "needs a number from -1 to 1"};
    a.value = j["value"].get<double>();
    if (!(a.value >= -1 && a.value <= 1)) return std::pair<std::string, std::string>{"value", "must be from -1 to 1"};
  } else if (j.contains("value")) {
    return std::pair<std::string, std::string>{"value", std::string("only throttle, steer and climb take a value")};
  }
  if (j.contains("to")) {
    if (a.type != ActionType::Switch) return std::pair<std::string, std::string>{"to", "only switch takes a vehicle id"};
    if (!j["to"].is_string() || j["to"].get<std::string>().empty())
      return std::pair<std::string, std::string>{"to", "must be a vehicle id"};
    a.to = j["to"].get<std::string>();
  }
  if (j.contains("mode")) {
    if (a.type != ActionType::Camera) return std::pair<std::string, std::string>{"mode", "only camera takes a mode"};
    const auto m = j["mode"].is_string() ? camera_from_name(j["mode"].get<std::string>()) : std::nullopt;
    if (!m) return std::pair<std::string, std::string>{"mode", "must be driver, chase, orbit or map"};
    a.camera = m;
  }
  return std::nullopt;
}
}  // namespace

std::vector<Action> read_actions(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw world::InputError(name, 0, "file", world::file_exists(file) ? "cannot be read" : "file not found");
  std::ostringstream text;
  text << in.rdbuf();
  return read_actions_text(text.str(), file);
}

std::vector<Action> read_actions_text(std::string_view text, const std::filesystem::path& file) {
  const std::string name = file.string();
  std::istringstream in{std::string(text)};
  std::vector<world::Problem> problems;
  std::vector<Action> out;
  std::string line;
  int n = 0;
  double last_t = 0;
  while (std::getline(in, line)) {
    ++n;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    Action a;
    if (auto err = parse_line(line, a)) {
      problems.push_back({name, n, err->first, err->second});
      continue;
    }
    if (a.t < last_t) {
      problems.push_back({name, n, "t", "goes back in time (" + std::to_string(a.t) + " after " + std::to_string(last_t) + ")"});
      continue;
    }
    last_t = a.t;
    a.line = n;
    out.push_back(std::move(a));
  }
  if (!problems.empty()) throw world::InputError(std::move(problems));
  return out;
}

ActionRecorder::ActionRecorder(const std::filesystem::path& file) {
  f_ = std::fopen(file.string().c_str(), "w");
  if (!f_) throw std::runtime_error(file.string() + ": cannot be written");
}

ActionRecorder::~ActionRecorder() {
  if (f_) std::fclose(f_);
}

void ActionRecorder::write(const Action& a) {
  const std::string s = to_json(a).dump() + "\n";
  std::fwrite(s.data(), 1, s.size(), f_);
  std::fflush(f_);
}

}  // namespace npsnet::input
