// `npsnet record` and `npsnet replay` (DIS exercises in pcap files, src/record/), and the
// capture part of `npsnet check`. add_capture_commands() declares both subcommands and their
// options on the CLI; run_capture_command() runs whichever was chosen (exit 0 ok, 2 bad input
// or a file that is not a capture, 1 internal failure) and returns nullopt when neither was.
#pragma once
#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace npsnet::node {

struct CaptureOptions {
  std::string net = "udp://239.1.2.3:3000", iface = "127.0.0.1";
  std::optional<int> exercise;
  bool aoi = false;       // record: also every area-of-interest cell group
  int aoi_groups = 1024;  // record --aoi: the N of `run --aoi-groups`
  double seconds = 0;  // record: 0 = until SIGINT/SIGTERM
  double speed = 1.0;  // replay
  std::optional<double> from_s, to_s;
  std::filesystem::path file;
  CLI::App* record = nullptr;
  CLI::App* replay = nullptr;
};

void add_capture_commands(CLI::App& app, CaptureOptions& o);
std::optional<int> run_capture_command(const CaptureOptions& o);

struct CaptureProblem {
  std::uint64_t frame = 0;  // 0: the file as a whole
  std::string field, message;
};
// `npsnet check FILE.pcap`: prints what the capture holds to stdout and returns its problems
// (not a capture, cut inside a frame, malformed PDUs with their frame, frames cut short).
bool is_capture_file(const std::filesystem::path& f);
std::vector<CaptureProblem> check_capture(const std::filesystem::path& f);

}  // namespace npsnet::node
