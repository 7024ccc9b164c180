// The own vehicles' checkpoint file (node/checkpoint.hpp): what is written is read back bit for
// bit, bad files are refused with FILE:LINE: field: message, a checkpoint of another exercise is
// told apart, and the writer writes when a vehicle's damage changes and every second otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "support/dirs.hpp"
#include "node/checkpoint.hpp"
#include "node/event_log.hpp"
#include "node/simulation.hpp"
#include "support/scratch.hpp"
#include "world/error.hpp"
#include "world/scenario.hpp"

using namespace npsnet;

namespace {

const std::string kLan = std::string(npsnet::dirs::source()) + "/tests/multinode/data/lan.toml";

std::filesystem::path write_text(const std::string& name, const std::string& text) {
  const auto p = test::scratch_dir() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::string problem_of(const std::filesystem::path& p) {
  try {
    (void)node::read_checkpoint(p);
  } catch (const world::InputError& e) {
    return e.what();
  }
  return "";
}

node::CheckpointKey key_of(int node) { return {1, node, 1.7e9, 0.1, node::scenario_digest(kLan)}; }

}  // namespace

TEST(Checkpoint, WhatIsWrittenIsReadBackBitForBit) {
  const auto sc = world::load_scenario(kLan);
  node::EventLog log;
  node::Simulation sim(world::build_world(sc), sc, log, 0.1);
  for (int i = 0; i < 17; ++i) sim.tick();  // odd positions, headings, pitches
  const auto key = key_of(2);
  const node::Checkpoint c = node::take_checkpoint(sim.world(), key);
  ASSERT_EQ(c.vehicles.size(), 3u) << "lan.toml: node 2 has a2, h2 and a2b";
  // Signed zeros and extreme values keep their bits too.
  node::Checkpoint odd = c;
  odd.vehicles[0].vel = Vec3(-0.0, 4.9406564584124654e-324, -13888.888888888889);
  odd.vehicles[0].roll = -0.0f, odd.vehicles[0].pitch = 1.17549435e-38f;
  const auto odd_file = test::scratch_dir() / "ckpt_odd.jsonl";
  node::write_checkpoint(odd_file, odd);
  const auto odd_back = node::read_checkpoint_text(
      [&] { std::ifstream in(odd_file); return std::string(std::istreambuf_iterator<char>(in), {}); }(), "odd");
  EXPECT_EQ(std::signbit(odd_back.vehicles[0].vel.x()), true) << "-0.0 stays -0.0";
  EXPECT_EQ(odd_back.vehicles[0].vel.y(), 4.9406564584124654e-324) << "the smallest subnormal";
  EXPECT_EQ(odd_back.vehicles[0].vel.z(), -13888.888888888889);
  EXPECT_EQ(std::signbit(odd_back.vehicles[0].roll), true);
  EXPECT_EQ(odd_back.vehicles[0].pitch, 1.17549435e-38f);
  const auto file = test::scratch_dir() / "ckpt_roundtrip.jsonl";
  node::write_checkpoint(file, c);
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp")) << "renamed into place";
  const auto r = node::read_checkpoint(file);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->key, key);
  EXPECT_EQ(r->frame, 17);
  EXPECT_EQ(r->t, sim.world().t);
  EXPECT_EQ(node::checkpoint_mismatch(*r, key), "");
  ASSERT_EQ(r->vehicles.size(), c.vehicles.size());
  for (size_t i = 0; i < c.vehicles.size(); ++i) {
    const auto &a = c.vehicles[i], &b = r->vehicles[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.pos, b.pos);
    EXPECT_EQ(a.vel, b.vel);
    EXPECT_EQ(a.heading, b.heading);
    EXPECT_EQ(a.pitch, b.pitch);
    EXPECT_EQ(a.roll, b.roll);
    EXPECT_EQ(a.cruise_mps, b.cruise_mps);
    EXPECT_EQ(a.max_mps, b.max_mps);
    EXPECT_EQ(a.fuel_l, b.fuel_l);
    EXPECT_EQ(a.rounds, b.rounds);
    EXPECT_EQ(a.leg, b.leg);
  }
  // Put back into a fresh world at frame 0: the vehicles are where the checkpoint has them.
  node::Simulation fresh(world::build_world(sc), sc, log, 0.1);
  EXPECT_EQ(node::restore_checkpoint(fresh, *r, file).size(), 0u) << "no rounds in flight";
  const int a2 = fresh.find_entity("a2");
  EXPECT_EQ(fresh.world().ents.pos[a2], sim.world().ents.pos[sim.find_entity("a2")]);
  EXPECT_EQ(fresh.world().ents.heading_deg[a2], sim.world().ents.heading_deg[sim.find_entity("a2")]);
}

TEST(Checkpoint, AnotherExercisesCheckpointIsToldApart) {
  node::Checkpoint c;
  c.key = key_of(2);
  auto k = c.key;
  EXPECT_EQ(node::checkpoint_mismatch(c, k), "");
  k.start_at = 1.8e9;
  EXPECT_NE(node::checkpoint_mismatch(c, k).find("--start-at"), std::string::npos);
  k = c.key, k.node = 3;
  EXPECT_NE(node::checkpoint_mismatch(c, k).find("node 2, not 3"), std::string::npos);
  k = c.key, k.scenario = "0000000000000000";
  EXPECT_NE(node::checkpoint_mismatch(c, k).find("another scenario"), std::string::npos);
  k = c.key, k.dt = 0.05;
  EXPECT_NE(node::checkpoint_mismatch(c, k).find("--dt"), std::string::npos);
}

TEST(Checkpoint, BadFilesAreRefusedWithTheirLineAndField) {
  EXPECT_FALSE(node::read_checkpoint(test::scratch_dir() / "no_such_checkpoint.jsonl")) << "none: nothing to put back";
  const std::string head =
      R"({"checkpoint":1,"exercise":1,"node":2,"start_at":null,"dt":0.1,"scenario":"x","frame":5,"t":0.5,"vehicles":1})";
  const std::string veh =
      R"({"id":"a2","kind":"bmp","state":0,"active":true,"pos":[1,2,3],"vel":[0,0,0],"hpr":[0,0,0],"cruise_mps":11,"max_mps":18,"fuel_l":100,"rounds":10,"leg":0,"flee_until":0,"calm_until":0})";
  EXPECT_EQ(problem_of(write_text("ck_ok.jsonl", head + "\n" + veh + "\n")), "");
  EXPECT_NE(problem_of(write_text("ck_empty.jsonl", "")).find("ck_empty.jsonl:0: file: empty"), std::string::npos);
  EXPECT_NE(problem_of(write_text("ck_text.jsonl", "hello\n")).find("ck_text.jsonl:1: line: not a JSON object"), std::string::npos);
  std::string bad = veh;
  bad.replace(bad.find("[1,2,3]"), 7, "[1,2]");
  EXPECT_NE(problem_of(write_text("ck_pos.jsonl", head + "\n" + bad + "\n")).find("ck_pos.jsonl:2: pos: must be [a, b, c]"),
            std::string::npos);
  bad = veh;
  bad.replace(bad.find("\"state\":0"), 9, "\"state\":-1");
  EXPECT_NE(problem_of(write_text("ck_state.jsonl", head + "\n" + bad + "\n")).find(":2: state: must be 0 to 255"),
            std::string::npos);
  bad = veh;
  bad.replace(bad.find("\"cruise_mps\":11"), 15, "\"cruise_mps\":1e999");
  EXPECT_NE(problem_of(write_text("ck_inf.jsonl", head + "\n" + bad + "\n")).find(":2:"), std::string::npos);
  EXPECT_NE(problem_of(write_text("ck_count.jsonl", head + "\n")).find(":1: vehicles: says 1, the file has 0"),
            std::string::npos);
  std::string h2 = head;
  h2.replace(h2.find("\"checkpoint\":1"), 14, "\"checkpoint\":7");
  EXPECT_NE(problem_of(write_text("ck_format.jsonl", h2 + "\n" + veh + "\n")).find(":1: checkpoint: format 7 is not 1"),
            std::string::npos);
  // A vehicle the world does not have as node 2's: the restore names it, before anything moves.
  const auto sc = world::load_scenario(kLan);
  node::EventLog log;
  node::Simulation sim(world::build_world(sc), sc, log, 0.1);
  std::string other = veh;
  other.replace(other.find("\"a2\""), 4, "\"t1\"");
  const auto f = write_text("ck_t1.jsonl", head + "\n" + other + "\n");
  const auto c = node::read_checkpoint(f);
  ASSERT_TRUE(c);
  try {
    node::restore_checkpoint(sim, *c, f);
    ADD_FAILURE() << "t1 is node 1's";
  } catch (const world::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ck_t1.jsonl:2: id: 't1' is no vehicle of node 2 here"), std::string::npos) << e.what();
  }
}

TEST(Checkpoint, TheWriterWritesOnADamageChangeAndEverySecond) {
  const auto sc = world::load_scenario(kLan);
  node::EventLog log;
  node::Simulation sim(world::build_world(sc), sc, log, 0.1);
  const auto file = test::scratch_dir() / "ckpt_writer.jsonl";
  std::filesystem::remove(file);
  node::CheckpointWriter writer(file, key_of(2));
  int writes_at_kill = -1;
  for (int i = 0; i < 50; ++i) {
    const int before = sim.world().ents.state[sim.find_entity("a2")];
    sim.tick();
    const int w0 = writer.writes();
    writer.after_tick(sim.world());
    if (sim.world().ents.state[sim.find_entity("a2")] != before) {
      writes_at_kill = writer.writes();
      EXPECT_EQ(writer.writes(), w0 + 1) << "a2's damage changed at tick " << i << ": written at once";
      writer.flush();  // its thread writes it
      const auto c = node::read_checkpoint(file);
      ASSERT_TRUE(c);
      EXPECT_EQ(c->frame, sim.world().frame);
    }
  }
  EXPECT_GT(writes_at_kill, 0) << "t1 and a2 collide in lan.toml";
  // One at the first tick, one a second after each, one for the kill: 5 s -> 6 or 7.
  EXPECT_GE(writer.writes(), 6);
  EXPECT_LE(writer.writes(), 7);
}

namespace {
std::string bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

// The writer's own thread writes what the tick took: the same bytes as write_checkpoint on the
// tick's thread, each checkpoint whole; a write that fails there is thrown on the tick's thread.
TEST(Checkpoint, TheWriterThreadWritesWhatTheTickTookAndReportsItsFailure) {
  const auto sc = world::load_scenario(kLan);
  node::EventLog log;
  node::Simulation sim(world::build_world(sc), sc, log, 0.1);
  const auto file = test::scratch_dir() / "ckpt_thread.jsonl";
  const auto same = test::scratch_dir() / "ckpt_thread_sync.jsonl";
  std::filesystem::remove(file);
  int64_t last_taken = -1;
  {
    node::CheckpointWriter writer(file, key_of(2));
    for (int i = 0; i < 30; ++i) {  // 3 s: the first tick, each second, a2's kill
      sim.tick();
      const int before = writer.writes();
      writer.after_tick(sim.world());
      if (writer.writes() == before) continue;
      last_taken = sim.world().frame;
      writer.flush();
      node::write_checkpoint(same, node::take_checkpoint(sim.world(), key_of(2)));
      EXPECT_EQ(bytes_of(file), bytes_of(same)) << "taken at frame " << last_taken;
    }
    EXPECT_GE(writer.writes(), 3);
    for (int i = 0; i < 15; ++i) {  // one more due; the destructor writes it
      sim.tick();
      const int before = writer.writes();
      writer.after_tick(sim.world());
      if (writer.writes() != before) last_taken = sim.world().frame;
    }
  }
  const auto back = node::read_checkpoint(file);
  ASSERT_TRUE(back);
  EXPECT_GT(last_taken, 30);
  EXPECT_EQ(back->frame, last_taken) << "the last one taken, written by the destructor";
  EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));

  // A folder where the file's folder should be: the thread's write fails; flush says so.
  const auto blocker = test::scratch_dir() / "ckpt_blocker";
  std::filesystem::remove_all(blocker);
  std::ofstream(blocker) << "a file, not a folder\n";
  node::CheckpointWriter bad(blocker / "ck.jsonl", key_of(2));
  sim.tick();
  bad.after_tick(sim.world());  // the first tick is always due
  try {
    bad.flush();
    ADD_FAILURE() << "the write cannot succeed";
  } catch (const node::OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("--checkpoint"), std::string::npos) << e.what();
  }
  bad.flush();  // said once
}
