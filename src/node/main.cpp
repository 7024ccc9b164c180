// npsnet: one NPSNET node. `npsnet run ...` simulates a scenario; `npsnet check FILE...` validates.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "node/capture_commands.hpp"
#include "node/cli.hpp"
#include "node/dr_error.hpp"
#include "node/options.hpp"
#include "world/scenario.hpp"

int main(int argc, char** argv) {
  using npsnet::node::RunOptions;
  using npsnet::node::finite_in;
  CLI::App app{"NPSNET node: networked battlefield simulation with real-time collision detection"};
  app.require_subcommand(1);
  app.footer(R"(Examples:
  npsnet run                                      the default scenario; PNGs + events.jsonl in screenshots/
  npsnet run --scenario my.toml --seconds 30 --snapshots out/
  npsnet run --no-render --events out/e.jsonl     event log only, as fast as the machine goes
  npsnet check my.toml                            validate, and print the world's summary
  npsnet run --net udp://239.1.2.3:3000 --node 2  one node of a networked exercise
Scenario format, kinds and the local frame: README.md ("Your own exercise").
Exit codes: 0 ok, 2 bad input (nothing written), 1 failure while running.)");
  RunOptions o;
  auto* run = app.add_subcommand("run", "run a scenario (headless unless --window)");
  run->add_option("--scenario", o.scenario, "scenario TOML (default scenarios/default.toml)");
  auto* sec = run->add_option("--seconds", o.seconds, "run length in scenario seconds")
                  ->check(finite_in(0, npsnet::world::kMaxDurationS, "s", true));
  run->add_option("--frames", o.frames, "run length in ticks")->check(CLI::Range(1L, 1000000000L))->excludes(sec);
  run->add_option("--dt", o.dt, "fixed step in seconds, 0.01 to 1 (default 0.1)")->check(finite_in(0.01, 1.0, "s"));
  run->add_option("--events", o.events, "event log, JSON Lines (default <snapshots>/events.jsonl)");
  run->add_option("--state-out", o.state_out, "at the end, write the world (vehicles, changed objects, craters) as JSON");
  run->add_option("--state-at", o.state_at, "write --state-out at this scenario time (s) instead of at the end")->check(finite_in(0, 1e7, "s"));
  run->add_option("--track-every", o.track_every,
                  "log every vehicle's position every S scenario seconds (track events; npsnet dr-error)")
      ->check(finite_in(0, npsnet::world::kMaxDurationS, "s", true));
  run->add_option("--checkpoint", o.checkpoint,
                  "keep this node's vehicles in FILE as it runs; a restart that joins the same exercise "
                  "puts them back (damage, wrecks where they stood)");
  run->add_option("--snapshots", o.snapshots, "folder for snapshot PNGs (default screenshots/)");
  run->add_flag("--window", o.window, "show a GLFW window (needs a display)");
  run->add_flag("--realtime", o.realtime, "pace ticks to the wall clock");
  run->add_option("--net", o.net, "off, or udp://ADDR:PORT (default group 239.1.2.3:3000)");
  run->add_option("--iface", o.iface, "local address multicast is sent and joined on (default 127.0.0.1)");
  run->add_option("--node", o.node, "this node's number: drives the vehicles with node = N")->check(CLI::Range(1, 65535));
  run->add_option("--exercise", o.exercise, "DIS exercise id (default 1)")->check(CLI::Range(1, 255));
  run->add_option("--dis-version", o.dis_version, "DIS protocol version we send: 6 or 7 (default 7; both accepted)")
      ->check(CLI::IsMember({6, 7}));
  run->add_option("--site", o.site, "DIS site (default 1)")->check(CLI::Range(1, 65535));
  run->add_option("--app", o.app, "DIS application (default = node)")->check(CLI::Range(1, 65535));
  run->add_option("--aoi", o.aoi_m, "area of interest: cells of CELL_M metres, one multicast group each (default off)")
      ->check(finite_in(0, 1e7, "m", true));
  run->add_option("--aoi-groups", o.aoi_groups, "at most N cell groups from the --net group up (default 1024)")
      ->check(CLI::Range(1, 65536));
  run->add_option("--ttl", o.ttl, "multicast TTL (default 1: one LAN; more to cross multicast routers)")
      ->check(CLI::Range(1, 255));
  run->add_option("--start-at", o.start_at, "start the scenario clock at this UNIX time")->check(finite_in(0, 1e11, "s"));
  run->add_option("--replay", o.replay, "a recorded exercise (pcap) as the remote side, no network; --start-at = its t 0");
  run->add_option("--snapshot-every", o.snapshot_every, "also write a frame every S scenario seconds")
      ->check(finite_in(0, npsnet::world::kMaxDurationS, "s", true));
  run->add_option("--max-snapshots", o.max_snapshots, "snapshot budget: most frames per run (default 200)")
      ->check(CLI::Range(0, 1000000));
  run->add_option("--max-snapshots-per-minute", o.max_snapshots_per_minute,
                  "snapshot budget: most frames in 60 s of scenario time (default 60)")
      ->check(CLI::Range(0, 1000000));
  std::string size;
  run->add_option("--size", size, "snapshot size WxH (default 960x540)");
  run->add_flag("--no-render", o.no_render, "do not render snapshots (event log only)");
  run->add_flag("--quiet", o.quiet, "no progress on stderr");
  run->add_option("--threads", o.threads,
                  "threads for dynamics and collision (default: the cores, at most 8; 1 = one thread); "
                  "the event log is the same for any number")
      ->check(CLI::Range(1, 64));
  run->add_option("--drive", o.drive, "the vehicle the player drives (default: the first vehicle of this node)");
  run->add_option("--input", o.input, "replay the player's actions from this JSON Lines file (works headless)");
  run->add_option("--record-input", o.record_input, "write the player's actions to this JSON Lines file");
  std::vector<std::string> files;
  auto* check = app.add_subcommand("check", "validate scenario, terrain, object, kind and model files");
  check->add_option("FILE", files, "files to check (a .pcap/.pcapng capture: PDUs by type, malformed ones)")->required();
  run->footer(R"(Examples:
  npsnet run --seconds 20 --snapshots out/ --snapshot-every 5
  npsnet run --scenario scenarios/fhl/fhl.toml --no-render --events fhl.jsonl
  npsnet run --max-snapshots 50 --max-snapshots-per-minute 20    bound the PNGs of a dense world)");
  check->footer(R"(Examples:
  npsnet check scenarios/default.toml             problems as FILE:LINE: field: message, or a world summary
  npsnet check my-objects.csv models/tree.obj my-terrain.tif
  npsnet check exercise.pcap                     a recording: PDUs by type, malformed PDUs with their frame)");
  npsnet::node::CaptureOptions capture;
  npsnet::node::add_capture_commands(app, capture);  // record, replay
  npsnet::node::DrErrorOptions dr_error;
  npsnet::node::add_dr_error_command(app, dr_error);
  if (npsnet::node::misplaced_first_argument(app, argc, argv)) return 2;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "%s\n", npsnet::node::parse_error_message(app, e).c_str());
    return 2;
  }
  if (!size.empty()) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 1 || h < 1 ||
        w > 8192 || h > 8192) {
      std::fprintf(stderr, "--size: '%s' must be WxH with 1..8192 each, e.g. 960x540\n", size.c_str());
      return 2;
    }
    o.width = w, o.height = h;
  }
  try {
    if (*run) return npsnet::node::run_command(o);
    if (auto rc = npsnet::node::run_capture_command(capture)) return *rc;
    if (auto rc = npsnet::node::run_dr_error_command(dr_error)) return *rc;
    return npsnet::node::check_command(files);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "npsnet: internal error: %s\n", e.what());
    return 1;
  }
}
