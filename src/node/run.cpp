#include <chrono>
#include <cstdlib>
#include <memory>
#include <cmath>
#include <cstdio>
#include <thread>

#include "npsnet_dirs.hpp"
#include "core/jobs.hpp"
#include "input/action_file.hpp"
#include "node/options.hpp"
#include "node/pace_stats.hpp"
#include "node/player.hpp"
#ifdef NPSNET_HAVE_RENDER
#include "node/cameras.hpp"
#include "node/player_window.hpp"
#include "node/snapshots.hpp"
#endif
#include "node/simulation.hpp"
#include "node/checkpoint.hpp"
#include "node/state_dump.hpp"
#include "node/track_log.hpp"
// --- network ---
#ifdef NPSNET_HAVE_NET
#include "node/net_bridge.hpp"
#endif
#ifdef NPSNET_HAVE_RECORD
#include "node/replay_feed.hpp"
#endif
// --- network end ---
#include "node/world_summary.hpp"
#include "world/scenario.hpp"

namespace npsnet::node {

std::filesystem::path source_dir() { return NPSNET_SOURCE_DIR; }

namespace {
void print_problems(const world::InputError& e) {
  for (const auto& p : e.problems()) std::fprintf(stderr, "%s\n", p.str().c_str());
}
double wall_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}
// A paced node started this long (s) or more after --start-at joins the running exercise (its past
// caught up headless); one started less late (a slow process start) starts at t = 0 then, as
// before issue 11 (its clock that much behind the exercise's).
constexpr double kJoinAfterS = 2.0;
// A paced node wakes its tick's worker threads this long before the tick's deadline.
constexpr auto kPrewake = std::chrono::microseconds(core::Jobs::kPrewakeUs);
// The whole ticks of dt since the exercise started at start_at (UNIX s): where a late node joins.
long join_ticks(double start_at, double dt) {
  const double n = std::floor((wall_now() - start_at) / dt + 1e-9);
  return n < 1e15 ? static_cast<long>(n) : 1000000000000000L;  // --start-at -1e300: past any run's end
}
}  // namespace

int run_command(const RunOptions& opt) {
  RunOptions o = opt;
  if (o.scenario.empty()) o.scenario = source_dir() / "scenarios" / "default.toml";
#ifndef NPSNET_HAVE_RENDER
  if (o.window || o.snapshot_every) {
    std::fprintf(stderr, "--window/--snapshot-every: this build has no renderer (NPSNET_RENDER=OFF)\n");
    return 2;
  }
#endif
  if (o.window && !std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) {
    std::fprintf(stderr, "--window: no display (DISPLAY is not set); run headless without --window\n");
    return 2;
  }
  // --- network ---
  const bool net_on = o.net != "off";
  const bool replay_on = !o.replay.empty();  // a recording as the remote side, no socket
  if (replay_on && net_on) {
    std::fprintf(stderr, "--replay %s: a replay has no network; leave out --net %s\n", o.replay.string().c_str(), o.net.c_str());
    return 2;
  }
  if (o.aoi_m > 0 && !net_on) {
    std::fprintf(stderr, "--aoi %g: needs --net udp://GROUP:PORT (the cell groups are multicast groups)\n", o.aoi_m);
    return 2;
  }
#ifdef NPSNET_HAVE_NET
  double dis_timeout_s = net::annex_c::kTimeoutS;
  if (net_on || replay_on) {
    if (auto u = net::parse_udp_url(o.net); net_on && !u) {
      std::fprintf(stderr, "--net %s: %s\n", o.net.c_str(), u.error().c_str());
      return 2;
    }
    try {
      dis_timeout_s = dis_timeout_from_env(dis_timeout_s);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 2;
    }
  }
  BridgeOptions net_opt{o.net, o.iface, o.node, o.exercise, o.site, o.app > 0 ? o.app : o.node, dis_timeout_s,
                              o.aoi_m, o.aoi_groups, o.ttl, replay_on, nullptr, nullptr, o.dis_version};
  std::unique_ptr<net::Session> session;  // opened before anything is written
#ifdef NPSNET_HAVE_RECORD
  std::unique_ptr<ReplayFeed> feed;
  if (replay_on) {
    try {
      feed = std::make_unique<ReplayFeed>(o.replay, o.start_at);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s:0: file: %s\n", o.replay.string().c_str(), e.what());
      return 2;
    }
  }
#else
  if (replay_on) {
    std::fprintf(stderr, "--replay: this build cannot read captures (no libpcap or NPSNET_NET=OFF)\n");
    return 2;
  }
#endif
  if (net_on || replay_on) {
    try {
      net_opt.munitions = std::make_shared<const MunitionTable>(MunitionTable::load(MunitionTable::default_file()));
      net_opt.entity_types = std::make_shared<const EntityTypeTable>(EntityTypeTable::load(EntityTypeTable::default_file()));
    } catch (const world::InputError& e) {
      print_problems(e);
      return 2;
    }
    try {
      session = open_session(net_opt);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "npsnet: --net %s --iface %s: %s\n", o.net.c_str(), o.iface.c_str(), e.what());
      return 2;
    }
  }
#else
  if (net_on || replay_on) {
    std::fprintf(stderr, "--net/--replay: this build has no networking (NPSNET_NET=OFF); use --net off\n");
    return 2;
  }
#endif
  // --- network end ---
  if (o.start_at && (*o.start_at - wall_now() > 3600 || !std::isfinite(*o.start_at))) {
    std::fprintf(stderr, "--start-at %.3f: more than an hour from now\n", *o.start_at);
    return 2;
  }
  // Load and check everything before writing anything.
  world::Scenario sc;
  world::World w;
  try {
    sc = world::load_scenario(o.scenario);
    w = world::build_world(sc);
  } catch (const world::InputError& e) {
    print_problems(e);
    return 2;
  }
  std::vector<input::Action> script;
  if (!o.input.empty()) {
    try {
      script = input::read_actions(o.input);
    } catch (const world::InputError& e) {
      print_problems(e);
      return 2;
    }
  }

  if (const std::string warn = origin_warning(sc, w, raster_crs_name(sc.terrain)); !warn.empty())
    std::fprintf(stderr, "%s\n", warn.c_str());
  const long ticks = o.frames ? *o.frames
                              : static_cast<long>(std::ceil((o.seconds ? *o.seconds : sc.duration_s) / o.dt - 1e-9));
  if (o.events.empty()) o.events = o.snapshots / "events.jsonl";
  const bool paced = o.realtime || o.window || net_on;  // --net: scenario time = wall time
  // Joining a running exercise: a paced run (not --replay) whose --start-at has passed by
  // kJoinAfterS or more starts its clock at now - start (whole ticks; the ticks before are caught
  // up headless, see below).
  const bool joining = o.start_at && paced && !replay_on && wall_now() - *o.start_at >= kJoinAfterS;
  if (joining && join_ticks(*o.start_at, o.dt) >= ticks) {
    std::fprintf(stderr, "--start-at %.15g: the exercise started %.6g s ago, past this run's end (%.6g s of scenario "
                 "time): nothing left to join\n", *o.start_at, wall_now() - *o.start_at, ticks * o.dt);
    return 2;
  }
  // --checkpoint: a join puts back the own vehicles of this exercise's checkpoint (checked here,
  // before anything is written); every run keeps it up to date as it goes.
  const CheckpointKey ck_key{o.exercise, o.node, o.start_at, o.dt, scenario_digest(o.scenario)};
  std::optional<Checkpoint> restore;
  if (!o.checkpoint.empty()) {
    try {
      ensure_writable_dir(o.checkpoint.has_parent_path() ? o.checkpoint.parent_path() : ".", "--checkpoint");
      std::error_code ec;
      if (std::filesystem::is_directory(o.checkpoint, ec))
        throw OutputError("--checkpoint " + o.checkpoint.string() + ": is a directory, not a file");
    } catch (const OutputError& e) {
      std::fprintf(stderr, "npsnet: %s\n", e.what());
      return 2;
    }
    if (joining) {
      try {
        restore = read_checkpoint(o.checkpoint);
        if (restore) checkpoint_slots(w, *restore, o.checkpoint);
      } catch (const world::InputError& e) {
        print_problems(e);
        return 2;
      }
      const std::string why = restore ? checkpoint_unusable(*restore, ck_key, join_ticks(*o.start_at, o.dt)) : "";
      if (!why.empty()) {
        std::fprintf(stderr, "npsnet: --checkpoint %s: not used (%s); it will be overwritten\n", o.checkpoint.string().c_str(),
                     why.c_str());
        restore.reset();
      }
    }
  }
  const bool has_player = o.window || !o.drive.empty() || !o.input.empty() || !o.record_input.empty();
  const auto same_file = [](const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code ea, eb;  // never throws: a name the system cannot resolve is compared as written
    const auto ca = std::filesystem::weakly_canonical(a, ea), cb = std::filesystem::weakly_canonical(b, eb);
    return !ea && !eb ? ca == cb : a.lexically_normal() == b.lexically_normal();
  };
  if (!o.input.empty() && !o.record_input.empty() && same_file(o.record_input, o.input)) {
    std::fprintf(stderr, "--record-input %s: would overwrite the --input file\n", o.record_input.string().c_str());
    return 2;
  }
  int first_driven = -1;
  if (has_player) {
    try {
      // Networked or replayed, other nodes' vehicles are remote: only this node's can be driven.
      first_driven = Player::first_vehicle(w, o.node, !net_on && !replay_on, o.drive, script, o.input.string());
    } catch (const world::InputError& e) {
      print_problems(e);
      return 2;
    }
  }
  std::unique_ptr<input::ActionRecorder> recorder;
  if (!o.record_input.empty()) {
    try {
      recorder = std::make_unique<input::ActionRecorder>(o.record_input);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "--record-input %s\n", e.what());
      return 2;
    }
  }
  // Outputs are checked before anything is written: the snapshot folder (when rendering), the
  // renderer, then the event log is opened (truncated) last.
  EventLog log;
  Simulation sim(std::move(w), sc, log, o.dt);
  sim.set_threads(o.threads > 0 ? o.threads : core::Jobs::default_threads());
  std::unique_ptr<Player> player;
  if (has_player) {
    player = std::make_unique<Player>(sim, log, first_driven, std::move(script));
    if (recorder) player->record_to(std::move(recorder));
    sim.before_dynamics = [&] { player->before_dynamics(); };
  }
#ifdef NPSNET_HAVE_RENDER
  std::unique_ptr<Snapshots> snaps;
  if (!o.no_render || o.window) {
    try {
      ensure_writable_dir(o.snapshots, "--snapshots");
    } catch (const OutputError& e) {
      std::fprintf(stderr, "npsnet: %s\n", e.what());
      return 2;
    }
    try {
      SnapshotOptions so{o.snapshots, o.width, o.height, o.snapshot_every.value_or(0), o.window};
      so.max_frames = o.max_snapshots, so.max_per_minute = o.max_snapshots_per_minute;
      snaps = std::make_unique<Snapshots>(so, sim.world(), o.dt, log);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "npsnet: renderer: %s\n", e.what());
      return 1;
    }
    sim.before_apply = [&](const world::World& ww, const world::Changes& c) { snaps->before_apply(ww, c); };
    sim.on_tick = [&](const TickReport& r) {
      snaps->set_driven(sim.driven());
      snaps->after_tick(sim.world(), r.changes, r.applied);
    };
  }
#endif
  try {
    log.open(o.events);
  } catch (const OutputError& e) {
    std::fprintf(stderr, "npsnet: --events %s\n", e.what());
    return 2;
  }
  if (!o.quiet)
    std::fprintf(stderr, "npsnet: %s: %zu fixed objects, %zu vehicles, %ld ticks of %.3f s\n", o.scenario.string().c_str(),
                 sim.world().fixed.size(), sim.world().ents.size(), ticks, o.dt);
#ifdef NPSNET_HAVE_RENDER
  std::unique_ptr<PlayerWindow> window;
  if (o.window && snaps) window = std::make_unique<PlayerWindow>(*snaps, player.get());
  auto more = [&] { return snaps && snaps->pending(); };
  // The views this node renders after each tick (the window's camera, the snapshot frames due)
  // go to the detector first: pairs seen there get the exact tier (scene-aware auto tier).
  std::vector<render::Camera> cams;
  std::vector<collision::ViewVolume> views;
  if (snaps)
    sim.before_detect = [&](const world::World& ww) {
      cams.clear();
      if (window) cams.push_back(window->camera(sim));
      snaps->cameras_due(ww, cams);
      views.clear();
      for (const auto& c : cams) views.push_back(view_volume(c, snaps->options().width, snaps->options().height));
      sim.set_views(views);
    };
#else
  auto more = [] { return false; };
#endif
  // --- network ---
#ifdef NPSNET_HAVE_NET
  std::unique_ptr<NetBridge> bridge;
  if (net_on || replay_on) {
    try {
      net_opt.paced = paced;
      bridge = std::make_unique<NetBridge>(net_opt, std::move(session), sim, log);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "npsnet: --net %s --iface %s: %s\n", o.net.c_str(), o.iface.c_str(), e.what());
      return 2;
    }
    bridge->attach();
#ifdef NPSNET_HAVE_RECORD
    if (feed) bridge->set_source([&feed](double now_s, NetBridge& b) { feed->feed(now_s, b); });
#endif
  }
#endif
  // --- network end ---
  if (o.start_at && !replay_on) {  // with --replay, --start-at is the recording's t = 0: no wait
    while (wall_now() < *o.start_at) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    // Ready later than --start-at but less than kJoinAfterS (a slow start): t = 0 is now, so this
    // node's clock runs behind the exercise's all run long. Say by how much (tests read it).
    if (const double late = wall_now() - *o.start_at; paced && !joining && late > o.dt && !o.quiet)
      std::fprintf(stderr, "npsnet: started %.3f s past --start-at (under %.0f s: not a join); this node's clock "
                   "runs that much behind the exercise's\n", late, kJoinAfterS);
  }
  std::unique_ptr<TrackLog> track;  // --track-every
  if (o.track_every) track = std::make_unique<TrackLog>(*o.track_every, o.dt);
  std::unique_ptr<CheckpointWriter> checkpoint;  // --checkpoint
#ifdef NPSNET_HAVE_NET
  if (!o.checkpoint.empty()) checkpoint = std::make_unique<CheckpointWriter>(o.checkpoint, ck_key, round_identities(bridge.get()));
#else
  if (!o.checkpoint.empty()) checkpoint = std::make_unique<CheckpointWriter>(o.checkpoint, ck_key);
#endif
  bool state_written = o.state_out.empty();  // --state-out: written once, at --state-at or the end
  const auto write_state_due = [&] {
    if (!state_written && o.state_at && sim.world().t >= *o.state_at - 1e-9) {
      write_state(o.state_out, sim.world(), sim.craters());
      state_written = true;
    }
  };
  // Joining late (--start-at passed): the node replays its own scenario from t = 0 to now - start
  // headless and at full speed: no network (remote entities absent), no event log, no snapshots,
  // no fire (its earlier rounds are not fired again: the network brings their craters); its
  // vehicles follow their routes, and what they do to each other and to fixed objects happens as
  // it did. Then it goes live (every local Entity State at once) at the exercise's current time.
  const long first = joining ? std::min(join_ticks(*o.start_at, o.dt), ticks) : 0;
  if (first > 0) {
    const auto before_apply = std::move(sim.before_apply);
    const auto before_detect = std::move(sim.before_detect);
    sim.before_apply = nullptr, sim.before_detect = nullptr;
    log.mute(true);
    sim.hold_fire(true);
#ifdef NPSNET_HAVE_NET
    if (bridge) bridge->catch_up(true);
#endif
    try {
      for (long i = 0; i < first; ++i) {
        sim.tick();
        if (restore && sim.world().frame == restore->frame) {
          const std::vector<int> rounds = restore_checkpoint(sim, *restore, o.checkpoint);
#ifdef NPSNET_HAVE_NET
          adopt_rounds(bridge.get(), *restore, rounds);
#endif
          std::fprintf(stderr, "npsnet: --checkpoint %s: %zu vehicle(s) and %zu round(s) in flight put back as they were at t = %.2f s\n",
                         o.checkpoint.string().c_str(), restore->vehicles.size(), rounds.size(), restore->t);
        }
        write_state_due();
      }
    } catch (const OutputError& e) {
      std::fprintf(stderr, "npsnet: t = %.1f s: %s; run stopped\n", sim.world().t, e.what());
      return 1;
    }
#ifdef NPSNET_HAVE_NET
    if (bridge) bridge->catch_up(false);
#endif
    sim.hold_fire(false);
    log.mute(false);
    sim.before_apply = before_apply, sim.before_detect = before_detect;
    log.write({{"event", "exercise_joined"}, {"t", std::round(sim.world().t * 1000) / 1000}, {"frame", sim.world().frame},
               {"start_at", *o.start_at}, {"caught_up_ticks", first}});
    if (!o.quiet)
      std::fprintf(stderr, "npsnet: joined the exercise at t = %.2f s (%ld ticks caught up headless)\n", sim.world().t, first);
  }
  // The scenario clock: tick i ends at t0 + (i + 1) dt (joining: t0 is the exercise's start, so the
  // ticks due since the headless catch-up began are caught up live, as any late tick).
  auto t0 = std::chrono::steady_clock::now();
  if (first > 0)
    t0 -= std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(wall_now() - *o.start_at));
  long next_progress = ticks / 10;
  while (ticks >= 10 && next_progress <= first) next_progress += ticks / 10;
  // The run goes on past its length (at most kResultDelayS more) until every result frame is written.
  const long extra = static_cast<long>(std::ceil(2.0 / o.dt)) + 1;
  long done = 0;
  // Quit (Esc, a quit action) or the window closed: the run ends after this tick, but first,
  // unpaced and without the window, the ticks that write the result frames still due (at most
  // kResultDelayS), so every imminent frame in the log has its result, as at the run's end.
  const char* ended_by = nullptr;
  long end_by = 0;
  double ended_t = 0;
  const auto end_now = [&](const char* why, long i) {
    if (!ended_by) ended_by = why, end_by = i + extra, ended_t = sim.world().t;
  };
  const auto go_on = [&](long i) {
    return ended_by ? more() && i < end_by : i < ticks || (more() && i < ticks + extra);
  };
  PaceStats pace;  // paced runs: how far behind the wall clock the ticks ran (printed at the end)
  try {
    for (long i = first; go_on(i); ++i, ++done) {
#ifdef NPSNET_HAVE_NET
      if (bridge && bridge->frozen()) {  // Stop/Freeze: the run loop's clock stands still
        const auto f0 = std::chrono::steady_clock::now();
        while (bridge->frozen()) bridge->idle();
        t0 += std::chrono::steady_clock::now() - f0;
      }
#endif
      const auto tick_start = std::chrono::steady_clock::now();  // (after a freeze: not its time)
      const auto deadline = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                     std::chrono::duration<double>((i + 1) * o.dt));
#ifdef NPSNET_HAVE_RENDER
      if (window && !ended_by) window->before_tick();
      sim.tick();
      if (window && !ended_by && !window->present(sim)) end_now("the window was closed", i);
      if (paced && window && !ended_by) window->wait_until(deadline);
#else
      sim.tick();
#endif
      if (track) track->after_tick(sim.world(), log);
      if (checkpoint) checkpoint->after_tick(sim.world());
      write_state_due();
      if (paced) {  // the tick's work ended this long past its deadline (0: on time)
        const auto now = std::chrono::steady_clock::now();
        pace.add(i, std::chrono::duration<double>(now - tick_start).count(), std::chrono::duration<double>(now - deadline).count());
      }
      if (player && player->quit()) end_now("quit", i);  // Esc, or a quit action
      if (paced && !ended_by) {
        // The pool's workers sleep between paced ticks; woken here, just before the next tick's
        // deadline, they spin into its first stage, and the tick's thread does not pay the wake-up.
        if (core::Jobs* jobs = sim.jobs(); jobs && std::chrono::steady_clock::now() < deadline - kPrewake) {
          std::this_thread::sleep_until(deadline - kPrewake);
          jobs->wake();
        }
        std::this_thread::sleep_until(deadline);
      }
      if (!o.quiet && i + 1 >= next_progress && ticks >= 10) {
        std::fprintf(stderr, "npsnet: t = %.1f s (%ld%%)\n", sim.world().t, (i + 1) * 100 / ticks);
        next_progress += ticks / 10;
      }
    }
    if (checkpoint) checkpoint->flush();  // the last one taken is on disk (its thread writes them)
  } catch (const OutputError& e) {
    // A snapshot or the event log could not be written: say so, and end the log with it.
    std::fprintf(stderr, "npsnet: t = %.1f s: %s; run stopped\n", sim.world().t, e.what());
    try {
      log.write({{"event", "error"}, {"t", std::round(sim.world().t * 1000) / 1000}, {"frame", sim.world().frame},
                 {"message", e.what()}});
      log.flush();
    } catch (const OutputError&) {
    }
    return 1;
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (ended_by && !o.quiet) std::fprintf(stderr, "npsnet: %s at t = %.1f s\n", ended_by, ended_t);
  // --- network ---
#ifdef NPSNET_HAVE_NET
  if (bridge) {
    bridge->leave();
    std::fprintf(stderr, "%s\n", bridge->summary().c_str());
#ifdef NPSNET_HAVE_RECORD
    if (feed) std::fprintf(stderr, "%s\n", feed->summary().c_str());
#endif
  }
#endif
  // --- network end ---
  try {
    log.flush();
    if (!state_written) write_state(o.state_out, sim.world(), sim.craters());
  } catch (const OutputError& e) {
    std::fprintf(stderr, "npsnet: %s\n", e.what());
    return 1;
  }
#ifdef NPSNET_HAVE_RENDER
  if (snaps && snaps->skipped() > 0)
    std::fprintf(stderr, "npsnet: warning: %d snapshot frame(s) skipped by the budget (%d written; --max-snapshots %d, "
                 "--max-snapshots-per-minute %d); see the snapshot_skipped events\n",
                 snaps->skipped(), snaps->written(), o.max_snapshots, o.max_snapshots_per_minute);
#endif
  if (!o.quiet) {
    std::fprintf(stderr, "npsnet: done: %ld ticks in %.2f s wall (%.3f ms/tick); events -> %s\n", done, wall,
                 1000 * wall / std::max(1L, done), o.events.string().c_str());
    if (paced) std::fprintf(stderr, "npsnet: paced: %s\n", pace.summary().c_str());
    for (const auto& [k, n] : log.counts()) std::fprintf(stderr, "  %-12s %d\n", k.c_str(), n);
    const auto& s = sim.stats();
    std::fprintf(stderr, "  collision method %s: fixed tests %lld, L1 %lld, L2 %lld, L3 %lld (rejected %lld), contacts %lld\n", sc.collision_method.c_str(),
                 (long long)s.fixed_tests, (long long)s.l1_pairs, (long long)s.l2_pairs, (long long)s.l3_tests,
                 (long long)s.l3_rejects, (long long)s.contacts);
  }
  return 0;
}

}  // namespace npsnet::node
