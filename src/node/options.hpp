// Command-line contract of `npsnet` (shared/ARCHITECTURE.md): `run` and `check`.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace npsnet::node {

struct RunOptions {
  std::filesystem::path scenario;              // default: <source>/scenarios/default.toml
  std::optional<double> seconds;
  std::optional<long> frames;
  double dt = 0.1;                             // s (the thesis's 10 Hz)
  std::filesystem::path events;                // default: <snapshots>/events.jsonl
  std::filesystem::path state_out;             // --state-out: the world at the end (node/state_dump.hpp)
  std::optional<double> state_at;              // --state-at: ... or at this scenario time (s)
  std::optional<double> track_every;           // --track-every: `track` events every S (node/track_log.hpp)
  std::filesystem::path checkpoint;            // --checkpoint: own vehicles kept on disk for a restart (node/checkpoint.hpp)
  std::filesystem::path snapshots = "screenshots";
  bool window = false, realtime = false;
  std::string net = "off";
  std::string iface = "127.0.0.1";
  int node = 1, exercise = 1, site = 1, app = -1;  // app: default = node
  int dis_version = 7;                         // --dis-version: protocol version we send (6 | 7)
  std::optional<double> start_at;              // with --replay: the recording's UNIX time of t = 0
  std::filesystem::path replay;                // --replay: a recording as the remote side, no network
  double aoi_m = 0;          // --aoi CELL_M: area-of-interest cell groups; 0 = off (one group)
  int aoi_groups = 1024;     // --aoi-groups N: at most N cell groups
  int ttl = 1;               // --ttl: multicast TTL
  std::optional<double> snapshot_every;
  int max_snapshots = 200, max_snapshots_per_minute = 60;  // snapshot budget (snapshots.hpp)
  int width = 960, height = 540;
  bool no_render = false;
  int threads = 0;           // --threads N: threads of the tick's parallel stages; 0 = core::Jobs::default_threads()
  bool quiet = false;
  // The player (shared/ARCHITECTURE.md, "Player"): with --window, --drive, --input or
  // --record-input this node has a player driving one of its vehicles.
  std::string drive;                           // "" = the first vehicle of this node
  std::filesystem::path input, record_input;   // JSON Lines actions to replay / to write
};

// Returns the process exit code: 0 ok, 2 bad input, 1 internal failure.
int run_command(const RunOptions& o);
int check_command(const std::vector<std::string>& files);

std::filesystem::path source_dir();  // where the bundled data lives (scenarios/, models/, shaders/)

}  // namespace npsnet::node
