// The own vehicles' checkpoint (checkpoint.hpp).
#include "node/checkpoint.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string_view>
#include <type_traits>
#include <unordered_map>

#include "node/event_log.hpp"
#include "node/simulation.hpp"
#include "world/error.hpp"
#include "world/limits.hpp"

namespace npsnet::node {

namespace {

using nlohmann::json;
constexpr int kFormat = 1;
constexpr double kMaxMps = world::kMaxSpeedKmh / 3.6;

bool own(const world::World& w, size_t e, int node) {
  return w.ents.local[e] && w.ents.node[e] == node && !w.is_munition(e);
}
bool own_round(const world::World& w, size_t e, int node) {
  return w.ents.local[e] && w.ents.active[e] && w.ents.node[e] == node && w.is_munition(e);
}

// Appends key and the number (integers as integers, doubles as the shortest text that reads back
// as the same double; JSON has no inf or nan, and nothing written here is either).
template <class T>
void put(std::string& out, const char* key, T x) {
  out += key;
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  out.append(buf, r.ptr);
  // A double always reads back as one ("-0" would read as the integer 0 and lose its sign).
  if constexpr (std::is_floating_point_v<T>)
    if (std::find_if(buf, r.ptr, [](char ch) { return ch == '.' || ch == 'e'; }) == r.ptr) out += ".0";
}
// Appends key and s as a JSON string (ids and kinds come from the scenario, UTF-8 checked there;
// replace keeps a bad byte from throwing).
void put_text(std::string& out, const char* key, const std::string& s) {
  out += key;
  out += json(s).dump(-1, ' ', false, json::error_handler_t::replace);
}
void put3(std::string& out, const char* key, double a, double b, double c) {
  put(out, key, a), put(out, ",", b), put(out, ",", c);
  out += ']';
}

// Fields of one line, each checked: a wrong one is FILE:LINE: field: message.
struct Line {
  const json& j;
  const std::string& file;
  int ln;
  [[noreturn]] void fail(const std::string& field, const std::string& msg) const {
    throw world::InputError(file, ln, field, msg);
  }
  const json& at(const char* f) const {
    const auto it = j.find(f);
    if (it == j.end()) fail(f, "missing");
    return *it;
  }
  double number(const char* f) const {
    const json& v = at(f);
    if (!v.is_number()) fail(f, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(f, "must be finite");
    return d;
  }
  float within(const char* f, double lo, double hi) const {
    const double d = number(f);
    if (d < lo || d > hi) fail(f, "must be " + std::to_string(lo) + " to " + std::to_string(hi));
    return static_cast<float>(d);
  }
  long integer(const char* f, long lo, long hi) const {
    const json& v = at(f);
    if (!v.is_number_integer()) fail(f, "must be a whole number");
    const long n = v.get<long>();
    if (n < lo || n > hi) fail(f, "must be " + std::to_string(lo) + " to " + std::to_string(hi));
    return n;
  }
  std::string text(const char* f) const {
    const json& v = at(f);
    if (!v.is_string()) fail(f, "must be a string");
    return v.get<std::string>();
  }
  bool flag(const char* f) const {
    const json& v = at(f);
    if (!v.is_boolean()) fail(f, "must be true or false");
    return v.get<bool>();
  }
  // A place (|height| within world/limits.hpp) and a velocity (no faster than any kind may go).
  Vec3 place(const char* f) const {
    const auto p = triple(f);
    if (std::fabs(p[2]) > world::kMaxHeightM) fail(f, "height beyond +-" + std::to_string(world::kMaxHeightM) + " m");
    return Vec3(p[0], p[1], p[2]);
  }
  Vec3 velocity(const char* f) const {
    const auto u = triple(f);
    const Vec3 v(u[0], u[1], u[2]);
    if (v.norm() > kMaxMps) fail(f, "faster than " + std::to_string(world::kMaxSpeedKmh) + " km/h");
    return v;
  }
  std::array<double, 3> triple(const char* f) const {
    const json& v = at(f);
    if (!v.is_array() || v.size() != 3) fail(f, "must be [a, b, c]");
    std::array<double, 3> out{};
    for (size_t i = 0; i < 3; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>())) fail(f, "must hold three finite numbers");
      out[i] = v[i].get<double>();
    }
    return out;
  }
};

}  // namespace

std::string scenario_digest(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::uint64_t h = 1469598103934665603ull;
  char buf[4096];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) h = (h ^ static_cast<unsigned char>(buf[i])) * 1099511628211ull;
    if (!in) break;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

Checkpoint take_checkpoint(const world::World& w, const CheckpointKey& key, const RoundIdentity& identity) {
  Checkpoint c;
  c.key = key;
  c.frame = w.frame;
  c.t = w.t;
  const auto& ents = w.ents;
  c.vehicles.reserve(ents.size());  // (grown one by one, the copies cost more than the taking)
  for (size_t e = 0; e < ents.size(); ++e) {
    if (!own(w, e, key.node)) continue;
    CheckpointVehicle v;
    v.id = ents.id[e], v.kind = w.kind_of_entity(e).name;
    v.state = ents.state[e], v.active = ents.active[e] != 0;
    v.pos = ents.pos[e], v.vel = ents.vel[e];
    v.heading = ents.heading_deg[e], v.pitch = ents.pitch_deg[e], v.roll = ents.roll_deg[e];
    v.cruise_mps = ents.cruise_mps[e], v.max_mps = ents.max_mps[e], v.fuel_l = ents.fuel_l[e];
    v.rounds = ents.rounds[e], v.leg = ents.leg[e];
    v.flee_until = ents.flee_until[e], v.calm_until = ents.calm_until[e];
    c.vehicles.push_back(std::move(v));
  }
  if (identity)
    for (size_t m = 0; m < ents.size(); ++m) {
      CheckpointRound r;
      if (!own_round(w, m, key.node) || !identity(static_cast<int>(m), r)) continue;
      r.id = ents.id[m], r.kind = w.kind_of_entity(m).name;
      r.shooter = ents.owner[m] >= 0 ? ents.id[ents.owner[m]] : "";
      r.target = ents.target[m] >= 0 ? ents.id[ents.target[m]] : "";
      r.pos = ents.pos[m], r.vel = ents.vel[m], r.aim = ents.aim[m];
      c.rounds.push_back(std::move(r));
    }
  return c;
}

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& c) {
  const std::string what = "--checkpoint " + file.string();
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  const auto tmp = file.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw OutputError(what + ": cannot write " + tmp);
    const json head = {{"checkpoint", kFormat},
                       {"exercise", c.key.exercise},
                       {"node", c.key.node},
                       {"start_at", c.key.start_at ? json(*c.key.start_at) : json(nullptr)},
                       {"dt", c.key.dt},
                       {"scenario", c.key.scenario},
                       {"frame", c.frame},
                       {"t", c.t},
                       {"vehicles", c.vehicles.size()},
                       {"rounds", c.rounds.size()}};
    f << head.dump() << '\n';
    // The vehicle lines by hand (nlohmann's objects cost ~10 us a vehicle): numbers by
    // std::to_chars, the shortest text that reads back as the same double (floats written as
    // the double they are, so that double -> float on reading gives their bits back).
    std::string line;
    for (const auto& v : c.vehicles) {
      line.clear();
      put_text(line, "{\"id\":", v.id);
      put_text(line, ",\"kind\":", v.kind);
      put(line, ",\"state\":", v.state);
      line += v.active ? ",\"active\":true" : ",\"active\":false";
      put3(line, ",\"pos\":[", v.pos.x(), v.pos.y(), v.pos.z());
      put3(line, ",\"vel\":[", v.vel.x(), v.vel.y(), v.vel.z());
      put3(line, ",\"hpr\":[", v.heading, v.pitch, v.roll);
      put(line, ",\"cruise_mps\":", double{v.cruise_mps});
      put(line, ",\"max_mps\":", double{v.max_mps});
      put(line, ",\"fuel_l\":", double{v.fuel_l});
      put(line, ",\"rounds\":", v.rounds);
      put(line, ",\"leg\":", v.leg);
      put(line, ",\"flee_until\":", double{v.flee_until});
      put(line, ",\"calm_until\":", double{v.calm_until});
      line += "}\n";
      f << line;
    }
    for (const auto& r : c.rounds) {
      line.clear();
      put_text(line, "{\"round\":", r.id);
      put_text(line, ",\"kind\":", r.kind);
      put_text(line, ",\"shooter\":", r.shooter);
      put_text(line, ",\"target\":", r.target);
      put3(line, ",\"pos\":[", r.pos.x(), r.pos.y(), r.pos.z());
      put3(line, ",\"vel\":[", r.vel.x(), r.vel.y(), r.vel.z());
      put3(line, ",\"aim\":[", r.aim.x(), r.aim.y(), r.aim.z());
      put(line, ",\"event\":", r.event);
      put(line, ",\"site\":", r.site);
      put(line, ",\"application\":", r.application);
      put(line, ",\"entity\":", r.entity);
      line += "}\n";
      f << line;
    }
    f.flush();
    if (!f) throw OutputError(what + ": cannot write " + tmp + " (disk full?)");
  }
  std::filesystem::rename(tmp, file, ec);  // whole or not at all
  if (ec) throw OutputError(what + ": " + ec.message());
}

std::optional<Checkpoint> read_checkpoint(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file, ec)) throw world::InputError(file.string(), 0, "file", "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return read_checkpoint_text(text.str(), file.string());
}

Checkpoint read_checkpoint_text(std::string_view bytes, const std::string& name) {
  std::istringstream in{std::string(bytes)};
  Checkpoint c;
  size_t want = 0, want_rounds = 0;
  int ln = 0;
  for (std::string text; std::getline(in, text);) {
    ++ln;
    json j;
    try {
      j = json::parse(text);
    } catch (const json::exception&) {
      throw world::InputError(name, ln, "line", "not a JSON object (a checkpoint is JSON Lines)");
    }
    if (!j.is_object()) throw world::InputError(name, ln, "line", "not a JSON object (a checkpoint is JSON Lines)");
    const Line l{j, name, ln};
    if (ln == 1) {
      if (l.integer("checkpoint", 0, 1 << 30) != kFormat) l.fail("checkpoint", "format " + l.at("checkpoint").dump() + " is not 1");
      c.key.exercise = static_cast<int>(l.integer("exercise", 1, 255));
      c.key.node = static_cast<int>(l.integer("node", 1, 65535));
      if (!l.at("start_at").is_null()) c.key.start_at = l.number("start_at");
      c.key.dt = l.number("dt");
      c.key.scenario = l.text("scenario");
      c.frame = l.integer("frame", 0, 1L << 50);
      c.t = l.number("t");
      want = static_cast<size_t>(l.integer("vehicles", 0, 1L << 30));
      want_rounds = j.contains("rounds") ? static_cast<size_t>(l.integer("rounds", 0, 1L << 30)) : 0;
      continue;
    }
    if (c.vehicles.size() == want) {  // the rounds follow the vehicles
      if (c.rounds.size() == want_rounds) l.fail("line", "more lines than the header's vehicles and rounds");
      CheckpointRound r;
      r.id = l.text("round"), r.kind = l.text("kind"), r.shooter = l.text("shooter"), r.target = l.text("target");
      r.pos = l.place("pos"), r.vel = l.velocity("vel"), r.aim = l.place("aim");
      r.event = static_cast<int>(l.integer("event", 0, 65535));
      r.site = static_cast<int>(l.integer("site", 0, 65535));
      r.application = static_cast<int>(l.integer("application", 0, 65535));
      r.entity = static_cast<int>(l.integer("entity", 0, 65535));
      c.rounds.push_back(std::move(r));
      continue;
    }
    CheckpointVehicle v;
    v.id = l.text("id");
    v.kind = l.text("kind");
    v.state = static_cast<int>(l.integer("state", 0, 255));
    v.active = l.flag("active");
    // The bounds a scenario's own numbers keep (world/limits.hpp): a run never meets a value it cannot use.
    v.pos = l.place("pos"), v.vel = l.velocity("vel");
    const auto a = l.triple("hpr");
    for (double x : a)
      if (std::fabs(x) > 720) l.fail("hpr", "angles must be within +-720 deg");
    v.heading = static_cast<float>(a[0]), v.pitch = static_cast<float>(a[1]), v.roll = static_cast<float>(a[2]);
    v.cruise_mps = l.within("cruise_mps", 0, kMaxMps), v.max_mps = l.within("max_mps", 0, kMaxMps);
    v.fuel_l = l.within("fuel_l", 0, world::kMaxCount);
    v.rounds = static_cast<int>(l.integer("rounds", -1, static_cast<long>(world::kMaxCount)));
    v.leg = static_cast<int>(l.integer("leg", 0, static_cast<long>(world::kMaxCount)));
    v.flee_until = l.within("flee_until", -world::kMaxDurationS, world::kMaxDurationS);
    v.calm_until = l.within("calm_until", -world::kMaxDurationS, world::kMaxDurationS);
    c.vehicles.push_back(std::move(v));
  }
  if (ln == 0) throw world::InputError(name, 0, "file", "empty: not a checkpoint");
  if (c.vehicles.size() != want)
    throw world::InputError(name, 1, "vehicles", "says " + std::to_string(want) + ", the file has " +
                                                     std::to_string(c.vehicles.size()));
  if (c.rounds.size() != want_rounds)
    throw world::InputError(name, 1, "rounds", "says " + std::to_string(want_rounds) + ", the file has " +
                                                   std::to_string(c.rounds.size()));
  return c;
}

std::string checkpoint_mismatch(const Checkpoint& c, const CheckpointKey& key) {
  auto fmt = [](const std::optional<double>& s) { return s ? std::to_string(*s) : std::string("none"); };
  if (c.key.exercise != key.exercise) return "exercise " + std::to_string(c.key.exercise) + ", not " + std::to_string(key.exercise);
  if (c.key.node != key.node) return "node " + std::to_string(c.key.node) + ", not " + std::to_string(key.node);
  if (c.key.start_at != key.start_at) return "--start-at " + fmt(c.key.start_at) + ", not " + fmt(key.start_at);
  if (c.key.dt != key.dt) return "--dt " + std::to_string(c.key.dt) + ", not " + std::to_string(key.dt);
  if (c.key.scenario != key.scenario) return "another scenario file (digest " + c.key.scenario + ", not " + key.scenario + ")";
  return "";
}

std::string checkpoint_unusable(const Checkpoint& c, const CheckpointKey& key, int64_t join_frame) {
  if (std::string other = checkpoint_mismatch(c, key); !other.empty()) return other;
  return c.frame > join_frame ? "taken after the exercise's current time" : "";
}

std::vector<int> checkpoint_slots(const world::World& w, const Checkpoint& c, const std::filesystem::path& file) {
  std::vector<world::Problem> problems;
  std::vector<int> where(c.vehicles.size(), -1);
  std::unordered_map<std::string_view, int> slot;
  for (size_t k = 0; k < w.ents.size(); ++k) slot.emplace(w.ents.id[k], static_cast<int>(k));
  for (size_t i = 0; i < c.vehicles.size(); ++i) {
    const auto& v = c.vehicles[i];
    const int ln = static_cast<int>(i) + 2;
    const auto it = slot.find(v.id);
    const int e = it == slot.end() ? -1 : it->second;
    if (e < 0 || !own(w, static_cast<size_t>(e), c.key.node)) {
      problems.push_back({file.string(), ln, "id", "'" + v.id + "' is no vehicle of node " + std::to_string(c.key.node) + " here"});
      continue;
    }
    const world::Kind& k = w.kind_of_entity(e);
    if (!w.terrain.contains(v.pos.x(), v.pos.y()))
      problems.push_back({file.string(), ln, "pos", "(" + std::to_string(v.pos.x()) + ", " + std::to_string(v.pos.y()) + ") is off the map"});
    else if (k.name != v.kind) problems.push_back({file.string(), ln, "kind", "'" + v.kind + "', but '" + v.id + "' is a " + k.name});
    else if (v.state >= static_cast<int>(k.states.size()))
      problems.push_back({file.string(), ln, "state", std::to_string(v.state) + ": " + k.name + " has " +
                                                          std::to_string(k.states.size()) + " states"});
    else where[i] = e;
  }
  for (size_t i = 0; i < c.rounds.size(); ++i) {
    const auto& r = c.rounds[i];
    const int ln = static_cast<int>(c.vehicles.size() + i) + 2;
    const auto it = slot.find(r.shooter);
    const int k = w.kinds.find(r.kind);
    if (it == slot.end() || !own(w, static_cast<size_t>(it->second), c.key.node))
      problems.push_back({file.string(), ln, "shooter", "'" + r.shooter + "' is no vehicle of node " + std::to_string(c.key.node) + " here"});
    else if (k < 0 || w.kinds[k].mobility != world::Mobility::Munition)
      problems.push_back({file.string(), ln, "kind", "'" + r.kind + "' is not a munition kind"});
    else if (!w.terrain.contains(r.pos.x(), r.pos.y()))
      problems.push_back({file.string(), ln, "pos", "(" + std::to_string(r.pos.x()) + ", " + std::to_string(r.pos.y()) + ") is off the map"});
  }
  if (!problems.empty()) throw world::InputError(std::move(problems));
  return where;
}

std::vector<int> restore_checkpoint(Simulation& sim, const Checkpoint& c, const std::filesystem::path& file) {
  world::World& w = sim.world();
  auto& ents = w.ents;
  const std::vector<int> where = checkpoint_slots(w, c, file);
  // The rounds first (a launch takes a round from its shooter; the vehicles' counts come after).
  std::vector<int> rounds;
  for (const auto& r : c.rounds) {
    world::Launch l;
    l.shooter = sim.find_entity(r.shooter);
    l.kind = w.kinds.find(r.kind);
    l.target = r.target.empty() ? -1 : sim.find_entity(r.target);  // absent (remote): flies on unguided
    l.muzzle = r.pos, l.vel = r.vel, l.aim = r.aim;
    const int m = sim.relaunch(l);
    ents.id[m] = r.id;
    rounds.push_back(m);
  }
  for (size_t i = 0; i < c.vehicles.size(); ++i) {
    const auto& v = c.vehicles[i];
    const int e = where[i];
    ents.state[e] = static_cast<uint8_t>(v.state), ents.active[e] = v.active ? 1 : 0;
    ents.pos[e] = v.pos, ents.vel[e] = v.vel;
    ents.heading_deg[e] = v.heading, ents.pitch_deg[e] = v.pitch, ents.roll_deg[e] = v.roll;
    ents.cruise_mps[e] = v.cruise_mps, ents.max_mps[e] = v.max_mps, ents.fuel_l[e] = v.fuel_l;
    ents.rounds[e] = v.rounds, ents.leg[e] = v.leg;
    ents.flee_until[e] = v.flee_until, ents.calm_until[e] = v.calm_until;
    sim.placed(e);
  }
  return rounds;
}

struct CheckpointWriter::Shared {
  std::mutex mu;
  std::condition_variable cv;
  std::optional<Checkpoint> pending;  // taken, not yet picked up by the thread
  bool writing = false, stop = false;
  std::exception_ptr error;           // the first failed write, for the tick's thread
  std::thread thread;
};

CheckpointWriter::CheckpointWriter(std::filesystem::path file, CheckpointKey key, RoundIdentity identity)
    : file_(std::move(file)), key_(std::move(key)), identity_(std::move(identity)), shared_(std::make_unique<Shared>()) {
  Shared& s = *shared_;
  s.thread = std::thread([&s, file = file_] {
    std::unique_lock lock(s.mu);
    for (;;) {
      s.cv.wait(lock, [&] { return s.pending || s.stop; });
      if (!s.pending) return;  // stopped with nothing left to write
      Checkpoint c = std::move(*s.pending);
      s.pending.reset();
      s.writing = true;
      lock.unlock();
      std::exception_ptr failed;
      try {
        write_checkpoint(file, c);
      } catch (...) {
        failed = std::current_exception();
      }
      lock.lock();
      s.writing = false;
      if (failed && !s.error) s.error = failed;
      s.cv.notify_all();
    }
  });
}

CheckpointWriter::~CheckpointWriter() {
  {
    std::lock_guard lock(shared_->mu);
    shared_->stop = true;
  }
  shared_->cv.notify_all();
  shared_->thread.join();  // writes what is pending first
}

void CheckpointWriter::flush() {
  std::unique_lock lock(shared_->mu);
  shared_->cv.wait(lock, [&] { return !shared_->pending && !shared_->writing; });
  if (shared_->error) std::rethrow_exception(std::exchange(shared_->error, nullptr));
}

void CheckpointWriter::after_tick(const world::World& w) {
  {
    std::lock_guard lock(shared_->mu);
    if (shared_->error) std::rethrow_exception(std::exchange(shared_->error, nullptr));
  }
  const auto& ents = w.ents;
  if (sig_.size() < ents.size()) sig_.resize(ents.size(), ~uint64_t{0});
  bool changed = false;
  for (size_t e = 0; e < ents.size(); ++e) {
    uint64_t s = 0;  // not ours: 0
    if (own(w, e, key_.node))
      s = uint64_t{ents.state[e]} | uint64_t{ents.active[e]} << 8 | uint64_t{std::bit_cast<uint32_t>(ents.cruise_mps[e])} << 32;
    else if (identity_ && own_round(w, e, key_.node))  // a round in flight (fired, or its slot reused)
      s = uint64_t{1} << 16;  // spent: 0 again, so a slot fired again is a change too
    if (s != sig_[e]) changed = true, sig_[e] = s;
  }
  if (!changed && w.t < last_t_ + kCheckpointEveryS - 1e-9) return;
  Checkpoint c = take_checkpoint(w, key_, identity_);
  {
    std::lock_guard lock(shared_->mu);
    shared_->pending = std::move(c);  // replaces one the thread has not picked up yet
  }
  shared_->cv.notify_all();
  last_t_ = w.t;
  ++writes_;
}

}  // namespace npsnet::node
