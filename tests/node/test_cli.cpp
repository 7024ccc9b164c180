// The npsnet binary's contract: exit codes, `check` output, nothing written on bad input.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "support/fixture.hpp"
#include "support/npsnet_cli.hpp"

using namespace npsnet;

namespace {
test::CliOut run(const std::string& args) { return test::npsnet_cli(args); }
}  // namespace

TEST(Cli, CheckBundledFilesIsClean) {
  const auto o = run("check " + test::source("scenarios/default.toml").string() + " " +
                     test::source("models/kinds.toml").string() + " " + test::source("terrain/default-objects.csv").string() +
                     " " + test::source("models/tree.obj").string() + " " + test::source("terrain/default.tif").string());
  EXPECT_EQ(o.rc, 0) << o.text;
  EXPECT_NE(o.text.find("ok: 5 file(s)"), std::string::npos) << o.text;
}

TEST(Cli, CheckReportsEveryProblemAndExits2) {
  const auto f = test::write_file("cli-objs.csv", "id,kind,x_m,y_m,heading_deg\nTOOLONGID1234,tree,1,1,0\nX,oak,1,1,0\n");
  const auto o = run("check " + f.string() + " /nonexistent/file.toml");
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.text.find(f.string() + ":2: id: 'TOOLONGID1234' must be 1 to 11 characters"), std::string::npos) << o.text;
  EXPECT_NE(o.text.find(f.string() + ":3: kind: unknown kind 'oak'"), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("/nonexistent/file.toml:0: file: file not found"), std::string::npos) << o.text;
}

TEST(Cli, BadScenarioExits2AndWritesNothing) {
  const auto f = test::write_file("cli-bad.toml", "[world]\nterrain = \"missing.tif\"\n");
  const auto events = npsnet::test::scratch_dir() / "cli-bad-events.jsonl";
  std::filesystem::remove(events);
  const auto o = run("run --scenario " + f.string() + " --events " + events.string() + " --no-render");
  EXPECT_EQ(o.rc, 2) << o.text;
  EXPECT_NE(o.text.find(":2: world.terrain: file not found"), std::string::npos) << o.text;
  EXPECT_FALSE(std::filesystem::exists(events));
}

TEST(Cli, BadFlagsExit2) {
  EXPECT_EQ(run("run --dt 5").rc, 2);
  EXPECT_EQ(run("run --size 0x10 --no-render").rc, 2);
  EXPECT_EQ(run("frobnicate").rc, 2);
}

TEST(Cli, HeadlessRunWritesEventLog) {
  const auto dir = npsnet::test::scratch_dir() / "cli-run";
  std::filesystem::remove_all(dir);
  const auto o = run("run --seconds 10 --no-render --quiet --events " + (dir / "e.jsonl").string());
  EXPECT_EQ(o.rc, 0) << o.text;
  std::ifstream in(dir / "e.jsonl");
  std::string line;
  int n = 0;
  while (std::getline(in, line)) n += line.find("\"event\"") != std::string::npos;
  EXPECT_GT(n, 10);
}
