// The player's actions: one meaning from every source. Input files parse and round-trip, bad
// lines are reported as FILE:LINE: field: message; keyboard, gamepad and 6-DOF map to the same
// actions (held key = value at the press, 0 at the release).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/scratch.hpp"
#include "input/action_file.hpp"
#include "input/gamepad.hpp"
#include "input/keyboard.hpp"
#include "input/spacenav.hpp"
#include "world/error.hpp"

using namespace npsnet::input;

namespace {
std::filesystem::path write(const std::string& name, const std::string& text) {
  const auto dir = npsnet::test::scratch_dir();
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}
std::vector<std::string> problems_of(const std::filesystem::path& f) {
  try {
    read_actions(f);
  } catch (const npsnet::world::InputError& e) {
    std::vector<std::string> out;
    for (const auto& p : e.problems()) out.push_back(p.str());
    return out;
  }
  return {};
}
}  // namespace

TEST(ActionFile, ReadsEveryActionKind) {
  const auto f = write("actions-ok.jsonl",
                       "# a played session\n"
                       "{\"t\": 0.5, \"action\": \"throttle\", \"value\": 1.0}\n"
                       "\n"
                       "{\"t\": 1.0, \"action\": \"steer\", \"value\": -0.5}\n"
                       "{\"t\": 1.0, \"action\": \"climb\", \"value\": 0.25}\n"
                       "{\"t\": 2.0, \"action\": \"fire\"}\n"
                       "{\"t\": 3.0, \"action\": \"switch\", \"to\": \"tank2\"}\n"
                       "{\"t\": 3.5, \"action\": \"switch\"}\n"
                       "{\"t\": 4.0, \"action\": \"camera\", \"mode\": \"chase\"}\n"
                       "{\"t\": 4.5, \"action\": \"camera\"}\n"
                       "{\"t\": 9.0, \"action\": \"quit\"}\n");
  const auto a = read_actions(f);
  ASSERT_EQ(a.size(), 9u);
  EXPECT_EQ(a[0].type, ActionType::Throttle);
  EXPECT_DOUBLE_EQ(a[0].value, 1.0);
  EXPECT_DOUBLE_EQ(a[1].value, -0.5);
  EXPECT_EQ(a[2].type, ActionType::Climb);
  EXPECT_EQ(a[3].type, ActionType::Fire);
  EXPECT_EQ(a[4].to, "tank2");
  EXPECT_TRUE(a[5].to.empty());
  EXPECT_EQ(a[6].camera, CameraMode::Chase);
  EXPECT_FALSE(a[7].camera.has_value());
  EXPECT_EQ(a[8].type, ActionType::Quit);
  EXPECT_DOUBLE_EQ(a[8].t, 9.0);
}

TEST(ActionFile, RecorderOutputReadsBackEqual) {
  const auto dir = npsnet::test::scratch_dir();
  std::filesystem::create_directories(dir);
  const auto f = dir / "actions-rec.jsonl";
  std::vector<Action> in = {{0.1, ActionType::Throttle, 1, {}, {}},     {0.2, ActionType::Steer, -0.35, {}, {}},
                            {0.30000000000000004, ActionType::Fire, 0, {}, {}}, {0.4, ActionType::Switch, 0, "apc1", {}},
                            {0.5, ActionType::Camera, 0, {}, CameraMode::Map}, {0.6, ActionType::Quit, 0, {}, {}}};
  {
    ActionRecorder rec(f);
    for (const auto& a : in) rec.write(a);
  }
  const auto out = read_actions(f);
  ASSERT_EQ(out.size(), in.size());
  for (size_t i = 0; i < in.size(); ++i) {
    EXPECT_NEAR(out[i].t, in[i].t, 1e-6);
    EXPECT_EQ(out[i].type, in[i].type);
    EXPECT_DOUBLE_EQ(out[i].value, in[i].value);
    EXPECT_EQ(out[i].to, in[i].to);
    EXPECT_EQ(out[i].camera, in[i].camera);
  }
}

TEST(ActionFile, EveryBadLineIsReportedWithItsPlace) {
  const auto f = write("actions-bad.jsonl",
                       "{\"t\": 1.0, \"action\": \"throttle\", \"value\": 1.0}\n"
                       "{\"t\": 1.0, \"action\": \"throttle\"\n"
                       "{\"t\": 2.0, \"action\": \"jump\"}\n"
                       "{\"t\": 2.0, \"action\": \"steer\", \"value\": 3}\n"
                       "{\"action\": \"fire\"}\n"
                       "{\"t\": 0.5, \"action\": \"fire\"}\n"
                       "{\"t\": 3.0, \"action\": \"camera\", \"mode\": \"cockpit\"}\n"
                       "{\"t\": 3.0, \"action\": \"fire\", \"speed\": 2}\n"
                       "[1, 2]\n"
                       "{\"t\": -1, \"action\": \"fire\"}\n");
  const auto p = problems_of(f);
  const std::string n = f.string();
  ASSERT_EQ(p.size(), 9u) << ::testing::PrintToString(p);
  EXPECT_EQ(p[0], n + ":2: json: not a JSON object");
  EXPECT_EQ(p[1], n + ":3: action: unknown action 'jump' (throttle, steer, climb, fire, switch, camera, quit)");
  EXPECT_EQ(p[2], n + ":4: value: must be from -1 to 1");
  EXPECT_EQ(p[3], n + ":5: t: needs a number (scenario seconds)");
  EXPECT_EQ(p[4].rfind(n + ":6: t: goes back in time", 0), 0u) << p[4];
  EXPECT_EQ(p[5], n + ":7: mode: must be driver, chase, orbit or map");
  EXPECT_EQ(p[6], n + ":8: speed: unknown field (t, action, value, to, mode)");
  EXPECT_EQ(p[7], n + ":9: json: each line must be one JSON object");
  EXPECT_EQ(p[8], n + ":10: t: must be finite and not negative");
}

TEST(ActionFile, MissingFileIsAProblem) {
  const auto p = problems_of("/nonexistent/input.jsonl");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0], "/nonexistent/input.jsonl:0: file: file not found");
}

TEST(Keyboard, HeldKeyIsItsValueUntilReleased) {
  KeyboardMapper k;
  std::vector<Action> a;
  k.key(GLFW_KEY_W, GLFW_PRESS, a);
  k.key(GLFW_KEY_W, GLFW_REPEAT, a);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].type, ActionType::Throttle);
  EXPECT_EQ(a[0].value, 1);
  k.key(GLFW_KEY_DOWN, GLFW_PRESS, a);  // both held: they cancel
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[1].value, 0);
  k.key(GLFW_KEY_W, GLFW_RELEASE, a);  // only Down held: reverse
  EXPECT_EQ(a[2].value, -1);
  k.key(GLFW_KEY_DOWN, GLFW_RELEASE, a);
  EXPECT_EQ(a[3].value, 0);
  k.key(GLFW_KEY_A, GLFW_PRESS, a);
  EXPECT_EQ(a[4].type, ActionType::Steer);
  EXPECT_EQ(a[4].value, -1);
  k.key(GLFW_KEY_RIGHT, GLFW_PRESS, a);
  k.key(GLFW_KEY_A, GLFW_RELEASE, a);
  EXPECT_EQ(a.back().value, 1);
  k.key(GLFW_KEY_R, GLFW_PRESS, a);
  EXPECT_EQ(a.back().type, ActionType::Climb);
  EXPECT_EQ(a.back().value, 1);
  k.key(GLFW_KEY_R, GLFW_RELEASE, a);
  EXPECT_EQ(a.back().value, 0);
}

TEST(Keyboard, ButtonsActOnThePressOnly) {
  KeyboardMapper k;
  std::vector<Action> a;
  for (int key : {GLFW_KEY_SPACE, GLFW_KEY_TAB, GLFW_KEY_C, GLFW_KEY_ESCAPE}) {
    k.key(key, GLFW_PRESS, a);
    k.key(key, GLFW_RELEASE, a);
  }
  k.key(GLFW_KEY_Z, GLFW_PRESS, a);  // unmapped
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0].type, ActionType::Fire);
  EXPECT_EQ(a[1].type, ActionType::Switch);
  EXPECT_EQ(a[2].type, ActionType::Camera);
  EXPECT_FALSE(a[2].camera.has_value());
  EXPECT_EQ(a[3].type, ActionType::Quit);
}

TEST(Gamepad, SticksAndButtonsGiveTheSameActions) {
  GamepadMapper g;
  float axes[6] = {0, 0, 0, 0, -1, -1};
  unsigned char buttons[15] = {};
  std::vector<Action> a;
  g.update(axes, buttons, a);
  EXPECT_TRUE(a.empty());
  axes[GLFW_GAMEPAD_AXIS_LEFT_Y] = -1.0f;  // stick up: full throttle
  axes[GLFW_GAMEPAD_AXIS_LEFT_X] = 0.1f;   // inside the dead zone
  axes[GLFW_GAMEPAD_AXIS_RIGHT_Y] = 0.575f;  // right stick down: dive at half
  g.update(axes, buttons, a);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].type, ActionType::Throttle);
  EXPECT_DOUBLE_EQ(a[0].value, 1.0);
  EXPECT_EQ(a[1].type, ActionType::Climb);
  EXPECT_NEAR(a[1].value, -0.5, 1e-9);
  g.update(axes, buttons, a);  // nothing changed: nothing sent
  EXPECT_EQ(a.size(), 2u);
  axes[GLFW_GAMEPAD_AXIS_RIGHT_TRIGGER] = 1.0f;
  buttons[GLFW_GAMEPAD_BUTTON_Y] = GLFW_PRESS;
  g.update(axes, buttons, a);
  g.update(axes, buttons, a);  // still held: no repeat
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[2].type, ActionType::Fire);
  EXPECT_EQ(a[3].type, ActionType::Switch);
}

TEST(Spacenav, PushTwistLiftAndPickButton) {
  SpacenavMapper s;
  std::vector<Action> a;
  s.motion({0, 0, 350, 0, 0, 0}, a);  // pushed forward all the way
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].type, ActionType::Throttle);
  EXPECT_DOUBLE_EQ(a[0].value, 1.0);
  s.motion({0, 350, 350, 0, -350, 0}, a);  // lifted and twisted clockwise
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[1].type, ActionType::Steer);
  EXPECT_DOUBLE_EQ(a[1].value, 1.0);
  EXPECT_EQ(a[2].type, ActionType::Climb);
  s.motion({0, 0, 0, 0, 0, 0}, a);  // let go
  EXPECT_EQ(a.size(), 6u);
  s.button(0, true, a);
  s.button(0, false, a);
  s.button(1, true, a);
  ASSERT_EQ(a.size(), 7u);
  EXPECT_EQ(a[6].type, ActionType::Fire);
}
