// Input files (`--input FILE`, `--record-input FILE`): JSON Lines, one action a line (action.hpp),
// in order of scenario time. Blank lines and lines starting with '#' are skipped.
#pragma once
#include <cstdio>
#include <filesystem>
#include <string_view>
#include <vector>

#include "input/action.hpp"

namespace npsnet::input {

// Reads and checks the whole file. Throws world::InputError with every problem as
// FILE:LINE: field: message (bad JSON, unknown action, t missing/negative/decreasing, value
// outside -1..1, unknown camera mode, ...). Vehicle ids in `switch` are checked by the player.
std::vector<Action> read_actions(const std::filesystem::path& file);
// The same from `text`, the contents of `file` (named in problems).
std::vector<Action> read_actions_text(std::string_view text, const std::filesystem::path& file);

// Writes actions as they are applied, one line each, flushed per line (a crashed or killed
// session keeps what was played). Throws std::runtime_error when the file cannot be opened.
class ActionRecorder {
 public:
  explicit ActionRecorder(const std::filesystem::path& file);
  ~ActionRecorder();
  ActionRecorder(const ActionRecorder&) = delete;
  ActionRecorder& operator=(const ActionRecorder&) = delete;
  void write(const Action& a);

 private:
  std::FILE* f_ = nullptr;
};

}  // namespace npsnet::input
