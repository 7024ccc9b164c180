// Bad input on the command line and bad output paths (issue 11): a plain message, exit 2, and
// nothing written; failures while running say what failed (exit 1) and leave whole lines.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/fixture.hpp"
#include "support/npsnet_cli.hpp"

using namespace npsnet;
namespace fs = std::filesystem;

namespace {
using npsnet::test::fresh_dir;
// Every line of `file` is one complete JSON object; returns them.
std::vector<nlohmann::json> json_lines(const fs::path& file) {
  std::vector<nlohmann::json> out;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    EXPECT_TRUE(nlohmann::json::accept(line)) << file << ": not a JSON line: " << line;
    if (nlohmann::json::accept(line)) out.push_back(nlohmann::json::parse(line));
  }
  return out;
}
}  // namespace

TEST(BadInput, NonFiniteNumbersAreRejectedPlainlyAndNothingIsWritten) {
  const auto dir = fresh_dir("bad-numbers");
  const auto events = dir / "e.jsonl";
  for (const std::string flag : {"--seconds", "--dt", "--snapshot-every", "--start-at", "--track-every"})
    for (const std::string v : {"nan", "NaN", "inf", "-inf", "1e999", "abc", "-nan"}) {
      SCOPED_TRACE(flag + " " + v);
      const auto o = test::npsnet_cli("run " + flag + " " + v + " --no-render --quiet --events " + events.string() +
                                      " --snapshots " + (dir / "s").string());
      EXPECT_EQ(o.rc, 2) << o.text;
      EXPECT_NE(o.text.find(flag + ": '" + v + "' is not a"), std::string::npos) << o.text;
      EXPECT_EQ(o.text.find("internal error"), std::string::npos) << o.text;
      EXPECT_FALSE(fs::exists(events));
      EXPECT_FALSE(fs::exists(dir / "s"));
    }
}

TEST(BadInput, RangeErrorsPrintReadableNumbers) {
  const auto o = test::npsnet_cli("run --dt 5 --no-render");
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.text.find("--dt: must be 0.01 to 1 s (got 5)"), std::string::npos) << o.text;
  const auto big = test::npsnet_cli("run --seconds 1.7976931348623157e308 --no-render");
  EXPECT_EQ(big.rc, 2);
  EXPECT_NE(big.text.find("(got 1.79769e+308)"), std::string::npos) << big.text;
  for (const auto* args : {"run --seconds -1", "run --snapshot-every 0", "run --seconds 1e308", "run --dt 0.001"}) {
    const auto r = test::npsnet_cli(std::string(args) + " --no-render");
    EXPECT_EQ(r.rc, 2) << args;
    EXPECT_LT(r.text.size(), 300u) << args << ": " << r.text;  // no 310-digit DBL_MAX
  }
}

TEST(BadInput, UnknownSubcommandOrOptionSaysWhatIsWrong) {
  auto o = test::npsnet_cli("--bogus");
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.text.find("unknown option '--bogus'"), std::string::npos) << o.text;
  EXPECT_EQ(o.text.find("A subcommand is required"), std::string::npos) << o.text;
  o = test::npsnet_cli("frobnicate");
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.text.find("unknown subcommand 'frobnicate' (known: run, check"), std::string::npos) << o.text;
  o = test::npsnet_cli("--seconds 5");
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.text.find("--seconds is an option of 'run'"), std::string::npos) << o.text;
  o = test::npsnet_cli("run --bogus 3");
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.text.find("npsnet run: unknown option or extra argument: "), std::string::npos) << o.text;
  EXPECT_NE(o.text.find("--bogus"), std::string::npos) << o.text;
  o = test::npsnet_cli("");
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.text.find("give a subcommand (run, check"), std::string::npos) << o.text;
}

TEST(BadInput, HelpShowsExamples) {
  for (const auto* args : {"--help", "run --help", "check --help"}) {
    const auto o = test::npsnet_cli(args);
    EXPECT_EQ(o.rc, 0) << args;
    EXPECT_NE(o.text.find("Examples:"), std::string::npos) << args << o.text;
  }
  EXPECT_NE(test::npsnet_cli("run --help").text.find("--max-snapshots"), std::string::npos);
}

TEST(BadInput, UnwritableOutputsAreBadInputFoundBeforeAnythingIsWritten) {
  const auto dir = fresh_dir("bad-outputs");
  const auto afile = dir / "afile";
  std::ofstream(afile) << "x";
  const auto events = dir / "e.jsonl";
  struct Case {
    std::string args, says;
  };
  const Case cases[] = {
      {"--no-render --events /proc/npsnet-test.jsonl", "--events /proc/npsnet-test.jsonl: cannot write the event log"},
      {"--no-render --events " + dir.string(), "it is a directory"},
      {"--no-render --events /sys/kernel/npsnet.jsonl", "--events /sys/kernel/npsnet.jsonl: cannot write the event log"},
      {"--snapshots /proc/npsnet-snaps --events " + events.string(), "--snapshots /proc/npsnet-snaps: cannot create the folder"},
      {"--snapshots " + afile.string() + " --events " + events.string(), "not a folder"},
      {"--snapshots /sys/kernel --events " + events.string(), "--snapshots /sys/kernel: cannot write there"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto o = test::npsnet_cli("run --seconds 2 --quiet " + c.args);
    EXPECT_EQ(o.rc, 2) << o.text;
    EXPECT_NE(o.text.find(c.says), std::string::npos) << o.text;
    EXPECT_EQ(o.text.find("internal error"), std::string::npos) << o.text;
    EXPECT_FALSE(fs::exists(events));
  }
}

TEST(BadInput, FullDeviceIsAnErrorThatSaysSo) {
  const auto o = test::npsnet_cli("run --seconds 5 --no-render --quiet --events /dev/full");
  EXPECT_EQ(o.rc, 1) << o.text;
  EXPECT_NE(o.text.find("/dev/full: cannot write the event log: No space left on device"), std::string::npos) << o.text;
}

#ifdef NPSNET_HAVE_RENDER
TEST(BadInput, SnapshotThatCannotBeWrittenMidRunStopsTheRunAndSaysSo) {
  // A folder where the third case's result PNG should go: that rename fails at t = 7 s.
  const auto dir = fresh_dir("png-fails");
  fs::create_directories(dir / "0003-detonation-m518-ground-result.png" / "in-the-way");
  const auto o = test::npsnet_cli("run --quiet --snapshots " + dir.string() + " --size 160x90");
  EXPECT_EQ(o.rc, 1) << o.text;
  EXPECT_NE(o.text.find("0003-detonation-m518-ground-result.png: cannot write the snapshot"), std::string::npos) << o.text;
  const auto lines = json_lines(dir / "events.jsonl");
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.back()["event"], "error");  // the log itself says where it ends, and why
  EXPECT_NE(lines.back()["message"].get<std::string>().find("cannot write the snapshot"), std::string::npos);
  for (const auto& e : fs::directory_iterator(dir))  // no temporary file left behind
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}
#endif

TEST(BadInput, ObjVertexThatIsNotAFiniteNumberIsRejectedWithItsLine) {
  for (const std::string bad : {"nan", "abc", "inf", "1e999"}) {
    const auto f = test::write_file("bad-vertex-" + bad + ".obj", "# a triangle\nv 0 0 0\nv " + bad + " 1 0\nv 0 1 0\nf 1 2 3\n");
    const auto o = test::npsnet_cli("check " + f.string());
    EXPECT_EQ(o.rc, 2) << o.text;
    EXPECT_NE(o.text.find(f.string() + ":3: v: '" + bad + "' is not a finite number"), std::string::npos) << o.text;
  }
  const auto big = test::write_file("bad-vertex-big.obj", "v 0 0 0\nv 1e30 1 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(test::npsnet_cli("check " + big.string()).text.find(":2: v: coordinate must be -10000 to 10000 m (got 1e+30)"),
            std::string::npos);
}

// A path the system cannot even look up (a 5,000-character name) is "file not found", exit 2:
// std::filesystem threw filesystem_error there ("internal error"; the kinds fuzz target found it,
// fuzz/regressions/kinds/name-too-long-983f90bd).
TEST(BadInput, PathTooLongToLookUpIsFileNotFound) {
  const std::string longname = std::string(5000, 'x') + ".tif";
  const auto sc = test::write_file("too-long-terrain.toml", "[world]\nterrain = \"" + longname +
                                                                "\"\norigin_geodetic = [35.98, -121.25, 0.0]\n");
  for (const std::string cmd : {"check ", "run --no-render --quiet --scenario "}) {
    const auto o = test::npsnet_cli(cmd + sc.string());
    EXPECT_EQ(o.rc, 2) << cmd << o.text.substr(0, 400);
    EXPECT_NE(o.text.find("file not found"), std::string::npos) << o.text.substr(0, 400);
    EXPECT_EQ(o.text.find("internal error"), std::string::npos) << o.text.substr(0, 400);
  }
  const auto kinds = test::write_file("too-long-model.toml", "[x]\nmodels = [\"" + std::string(5000, 'm') +
                                                                 ".obj\"]\n");
  const auto o = test::npsnet_cli("check " + kinds.string());
  EXPECT_EQ(o.rc, 2) << o.text.substr(0, 400);
  EXPECT_EQ(o.text.find("internal error"), std::string::npos) << o.text.substr(0, 400);
}
