// Two or more nodes in one process, wired by a test (issue 11): each node's bridge has an offline
// session whose sent datagrams (net::Session::set_offline_sink) go to the other nodes' inboxes
// through the test's `deliver` policy (how many copies of a datagram reach a node: 0 = lost,
// 2 = duplicated); each node drains its inbox at the start of its next tick (the bridge's source:
// the bridge clock is then the scenario clock). Nodes tick in turn, node 1 first: deterministic,
// no socket, no sleeping. A node can be killed and restarted (a new process with the same numbers
// that joins the running exercise: its scenario caught up headless, as run.cpp does).
#pragma once
#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "node/bridge_options.hpp"
#include "node/checkpoint.hpp"
#include "node/event_log.hpp"
#include "node/net_bridge.hpp"
#include "node/simulation.hpp"
#include "support/scratch.hpp"
#include "world/scenario.hpp"

namespace npsnet::test {

struct WiredNode {
  int id = 0;
  std::filesystem::path events;
  std::unique_ptr<node::EventLog> log;
  std::unique_ptr<node::Simulation> sim;
  std::unique_ptr<node::NetBridge> bridge;
  std::deque<std::vector<std::uint8_t>> inbox;
  std::filesystem::path checkpoint_file;               // keep_checkpoint: node/checkpoint.hpp
  std::unique_ptr<node::CheckpointWriter> checkpoint;  // written after each of its live ticks
  const world::World& world() const { return sim->world(); }
  int index(const std::string& id_) const { return sim->find_entity(id_); }
};

// A datagram from node `from` to node `to`: how many copies arrive. The bytes are the datagram's.
using Deliver = std::function<int(int from, int to, const std::vector<std::uint8_t>& bytes)>;

class Wire {
 public:
  // Nodes 1..n of `scenario_file` (its vehicles' `node`), application = node, site 1; remote
  // entity timeout `timeout_s` (a short one shortens the heartbeat, bridge_options.hpp).
  Wire(const std::string& scenario_file, int n, const std::string& tag, double timeout_s, Deliver deliver)
      : deliver_(std::move(deliver)),
        tag_(tag),
        timeout_s_(timeout_s),
        scenario_file_(scenario_file),
        scenario_(world::load_scenario(scenario_file)),
        world_(world::build_world(scenario_)) {
    for (int k = 1; k <= n; ++k) nodes_.push_back(make_node(k, tag + "_n" + std::to_string(k)));
  }
  // Every live node ticks once, in order, `ticks` times.
  void run(int ticks) {
    for (int i = 0; i < ticks; ++i)
      for (auto& nd : nodes_)
        if (nd->sim) {
          nd->sim->tick();
          if (nd->checkpoint) nd->checkpoint->after_tick(nd->world());
        }
  }
  // Node k keeps its own vehicles in a checkpoint file (run.cpp's --checkpoint), which its
  // restarts read and keep writing.
  void keep_checkpoint(int k) {
    WiredNode& nd = node(k);
    nd.checkpoint_file = scratch_dir() / (tag_ + "_n" + std::to_string(k) + ".checkpoint.jsonl");
    std::filesystem::remove(nd.checkpoint_file);
    nd.checkpoint = std::make_unique<node::CheckpointWriter>(nd.checkpoint_file, checkpoint_key(k),
                                                             node::round_identities(nd.bridge.get()));
  }
  node::CheckpointKey checkpoint_key(int k) const { return {1, k, std::nullopt, 0.1, node::scenario_digest(scenario_file_)}; }
  // Node k dies (SIGKILL): it ticks no more, sends nothing, and what is sent to it is lost.
  void kill(int k) {
    WiredNode& nd = node(k);
    nd.bridge.reset();
    nd.sim.reset();
    nd.checkpoint.reset();  // what it wrote stays on disk
    nd.inbox.clear();
  }
  // Node k starts again (a new process with the same numbers, run.cpp's join): it catches its
  // own scenario up headless (no network, no event log, no fire) for the `ticks` the exercise has
  // run, then goes live. Its new events go to a new log (events of node k: this one's).
  // With keep_checkpoint(k), as run.cpp's --checkpoint: the catch-up puts the checkpoint's
  // vehicles back at its frame (when it is this exercise's and not after the join).
  void restart(int k, int ticks) {
    auto nd = make_node(k, tag_ + "_n" + std::to_string(k) + "_restart");
    std::optional<node::Checkpoint> restore;
    if (!node(k).checkpoint_file.empty()) {
      nd->checkpoint_file = node(k).checkpoint_file;
      restore = node::read_checkpoint(nd->checkpoint_file);
      if (restore && !node::checkpoint_unusable(*restore, checkpoint_key(k), ticks).empty()) restore.reset();
      nd->checkpoint = std::make_unique<node::CheckpointWriter>(nd->checkpoint_file, checkpoint_key(k),
                                                                node::round_identities(nd->bridge.get()));
    }
    nd->log->mute(true);
    nd->sim->hold_fire(true);
    nd->bridge->catch_up(true);
    for (int i = 0; i < ticks; ++i) {
      nd->sim->tick();
      if (restore && nd->world().frame == restore->frame)
        node::adopt_rounds(nd->bridge.get(), *restore, node::restore_checkpoint(*nd->sim, *restore, nd->checkpoint_file));
    }
    nd->bridge->catch_up(false);
    nd->sim->hold_fire(false);
    nd->log->mute(false);
    nodes_.at(static_cast<size_t>(k - 1)) = std::move(nd);
  }
  WiredNode& node(int k) { return *nodes_.at(static_cast<size_t>(k - 1)); }
  // The events node k has written so far (the log is flushed every tick).
  std::vector<nlohmann::json> events(int k) {
    std::vector<nlohmann::json> out;
    std::ifstream in(node(k).events);
    for (std::string line; std::getline(in, line);)
      if (!line.empty()) out.push_back(nlohmann::json::parse(line));
    return out;
  }

 private:
  std::unique_ptr<WiredNode> make_node(int k, const std::string& name) {
    auto nd = std::make_unique<WiredNode>();
    nd->id = k;
    nd->events = scratch_dir() / (name + ".jsonl");
    nd->log = std::make_unique<node::EventLog>(nd->events);
    nd->sim = std::make_unique<node::Simulation>(world_, scenario_, *nd->log, 0.1);
    node::BridgeOptions bo;
    bo.offline = true;
    bo.node = k;
    bo.app = k;
    bo.timeout_s = timeout_s_;
    auto session = node::open_session(bo);
    session->set_offline_sink([this, k](std::uint32_t, std::span<const std::uint8_t> b) {
      const std::vector<std::uint8_t> bytes(b.begin(), b.end());
      for (auto& other : nodes_)
        if (other->id != k && other->bridge)
          for (int c = deliver_(k, other->id, bytes); c > 0; --c) other->inbox.push_back(bytes);
    });
    nd->bridge = std::make_unique<node::NetBridge>(bo, std::move(session), *nd->sim, *nd->log);
    nd->bridge->attach();
    WiredNode* self = nd.get();
    nd->bridge->set_source([self](double now_s, node::NetBridge& b) {
      while (!self->inbox.empty()) {
        const auto d = std::move(self->inbox.front());
        self->inbox.pop_front();
        b.receive(d, now_s);
      }
    });
    return nd;
  }

  Deliver deliver_;
  std::string tag_;
  double timeout_s_;
  std::string scenario_file_;
  world::Scenario scenario_;
  world::World world_;
  std::vector<std::unique_ptr<WiredNode>> nodes_;
};

// The PDU type of a datagram of one PDU (header octet 2), and an Entity State's damage bits.
inline int pdu_type(const std::vector<std::uint8_t>& d) { return d.size() > 2 ? d[2] : -1; }
// The application of an Entity State's entity id (octets 14-15).
inline int es_application(const std::vector<std::uint8_t>& d) { return d.size() > 15 ? (d[14] << 8) | d[15] : -1; }
// The damage state of vehicle `id` when destroyed (its kind's last state) on node n.
inline int destroyed(const WiredNode& n, const std::string& id) {
  return static_cast<int>(n.world().kinds[n.world().ents.kind[n.index(id)]].states.size()) - 1;
}
inline unsigned es_damage(const std::vector<std::uint8_t>& d) {
  if (d.size() < 88) return 0;
  const std::uint32_t app = (std::uint32_t(d[84]) << 24) | (std::uint32_t(d[85]) << 16) | (std::uint32_t(d[86]) << 8) | d[87];
  return (app >> 3) & 3u;
}

}  // namespace npsnet::test
