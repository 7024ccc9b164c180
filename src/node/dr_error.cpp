#include "node/dr_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>

#include "node/cli.hpp"
#include "world/error.hpp"

namespace npsnet::node {

namespace {

using world::Problem;
constexpr size_t kMaxProblems = 20;

struct Sample {
  int log = 0;
  int line = 0;
  double x = 0, y = 0, z = 0;
};
using Key = std::pair<std::string, long long>;  // (id, frame)

struct Samples {
  std::map<Key, Sample> local;
  std::vector<std::pair<Key, Sample>> remote;
};

double number(const nlohmann::json& v, bool& ok) {
  ok = v.is_number() && std::isfinite(v.get<double>());
  return ok ? v.get<double>() : 0.0;
}

// One track event of `file` at `line` into `s`; a problem when a field is wrong.
std::optional<Problem> take(const nlohmann::json& ev, const std::string& file, int line, int log,
                            const std::vector<std::filesystem::path>& logs, std::optional<double> from_s,
                            std::optional<double> to_s, Samples& s) {
  auto bad = [&](const char* field, std::string msg) { return Problem{file, line, field, std::move(msg)}; };
  bool ok = false;
  if (!ev.contains("t")) return bad("t", "missing");
  const double t = number(ev["t"], ok);
  if (!ok) return bad("t", "not a finite number: " + ev["t"].dump());
  if (!ev.contains("frame") || !ev["frame"].is_number_integer() || ev["frame"].get<long long>() < 0)
    return bad("frame", "missing or not a whole number >= 0");
  if (!ev.contains("id") || !ev["id"].is_string()) return bad("id", "missing or not a string");
  const std::string source = ev.contains("source") && ev["source"].is_string() ? ev["source"].get<std::string>() : "";
  if (source != "local" && source != "remote") return bad("source", "must be \"local\" or \"remote\"");
  if (!ev.contains("pos") || !ev["pos"].is_array() || ev["pos"].size() != 3) return bad("pos", "must be [x, y, z]");
  Sample smp{log, line, 0, 0, 0};
  double* xyz[3] = {&smp.x, &smp.y, &smp.z};
  for (int i = 0; i < 3; ++i) {
    *xyz[i] = number(ev["pos"][i], ok);
    if (!ok) return bad("pos", "not a finite number: " + ev["pos"][i].dump());
  }
  if ((from_s && t < *from_s - 1e-9) || (to_s && t > *to_s + 1e-9)) return std::nullopt;
  Key key{ev["id"].get<std::string>(), ev["frame"].get<long long>()};
  if (source == "remote") {
    s.remote.emplace_back(std::move(key), smp);
    return std::nullopt;
  }
  const auto [it, fresh] = s.local.emplace(key, smp);
  if (!fresh)
    return bad("id", "'" + key.first + "' is local (an owner's true position) at frame " + std::to_string(key.second) +
                         " in " + logs[it->second.log].string() + ":" + std::to_string(it->second.line) +
                         " too: give each node's log once");
  return std::nullopt;
}

void read_log(const std::vector<std::filesystem::path>& logs, int log, std::optional<double> from_s,
              std::optional<double> to_s, Samples& s, std::vector<Problem>& problems) {
  const std::string file = logs[log].string();
  std::ifstream in(logs[log]);
  if (!in) {
    problems.push_back({file, 0, "file", std::string("cannot read: ") + std::strerror(errno)});
    return;
  }
  std::string text;
  int line = 0;
  long tracks = 0;
  while (std::getline(in, text) && problems.size() < kMaxProblems) {
    ++line;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto ev = nlohmann::json::parse(text, nullptr, false);
    if (ev.is_discarded() || !ev.is_object()) {
      problems.push_back({file, line, "json", "not a JSON object (an event log line)"});
      continue;
    }
    if (!ev.contains("event") || ev["event"] != "track") continue;
    ++tracks;
    if (auto p = take(ev, file, line, log, logs, from_s, to_s, s)) {
      problems.push_back(*p);
      break;  // the first bad track event of a file: the rest would repeat it
    }
  }
  if (tracks == 0 && problems.empty())
    problems.push_back({file, 0, "track", "no track events: run the node with --track-every S"});
}

void fill(DrErrorRow& row, std::vector<double>& h, std::vector<double>& f) {
  row.horizontal = error_stats(h);
  row.full = error_stats(f);
}

}  // namespace

ErrorStats error_stats(std::vector<double>& e) {
  ErrorStats s;
  s.count = static_cast<long>(e.size());
  if (e.empty()) return s;
  std::sort(e.begin(), e.end());
  const auto rank = [&](long p) { return e[static_cast<size_t>(std::max(1L, (p * s.count + 99) / 100) - 1)]; };
  s.p50 = rank(50), s.p90 = rank(90), s.p99 = rank(99), s.max = e.back();
  return s;
}

DrErrorReport dr_error(const std::vector<std::filesystem::path>& logs, std::optional<double> from_s,
                       std::optional<double> to_s) {
  Samples s;
  std::vector<Problem> problems;
  for (int i = 0; i < static_cast<int>(logs.size()) && problems.size() < kMaxProblems; ++i)
    read_log(logs, i, from_s, to_s, s, problems);
  if (!problems.empty()) throw world::InputError(problems);
  struct Errors {
    std::vector<double> h, f;
    long unmatched = 0;
  };
  std::vector<Errors> by_log(logs.size());
  std::map<std::string, Errors> by_entity;
  Errors all;
  for (const auto& [key, r] : s.remote) {
    const auto it = s.local.find(key);
    Errors* sinks[3] = {&by_log[r.log], &by_entity[key.first], &all};
    if (it == s.local.end()) {
      for (Errors* e : sinks) ++e->unmatched;
      continue;
    }
    const Sample& o = it->second;
    const double h = std::hypot(r.x - o.x, r.y - o.y), f = std::hypot(h, r.z - o.z);
    for (Errors* e : sinks) e->h.push_back(h), e->f.push_back(f);
  }
  DrErrorReport rep;
  auto row = [](std::string name, Errors& e) {
    DrErrorRow r;
    r.name = std::move(name);
    r.unmatched = e.unmatched;
    fill(r, e.h, e.f);
    return r;
  };
  for (size_t i = 0; i < logs.size(); ++i) rep.per_log.push_back(row(logs[i].filename().string(), by_log[i]));
  for (auto& [id, e] : by_entity) rep.per_entity.push_back(row(id, e));
  rep.all = row("all", all);
  return rep;
}

std::string format_report(const DrErrorReport& r) {
  std::string out =
      "dead-reckoning error of remote entities: each node's copy against its owner's true position at the same frame\n"
      "                                  matched unmatched  horizontal (m): p50      p90      p99      max"
      "  3-D (m): p50      p90      p99      max\n";
  char b[512];
  auto line = [&](const char* what, const DrErrorRow& row) {
    if (row.horizontal.count == 0) {  // nothing matched: no figures
      std::snprintf(b, sizeof b, "%-8s %-24s %8ld %9ld %24s %8s %8s %8s %17s %8s %8s %8s\n", what, row.name.c_str(), 0L,
                    row.unmatched, "-", "-", "-", "-", "-", "-", "-", "-");
      out += b;
      return;
    }
    std::snprintf(b, sizeof b, "%-8s %-24s %8ld %9ld %24.3f %8.3f %8.3f %8.3f %17.3f %8.3f %8.3f %8.3f\n", what,
                  row.name.c_str(), row.horizontal.count, row.unmatched, row.horizontal.p50, row.horizontal.p90,
                  row.horizontal.p99, row.horizontal.max, row.full.p50, row.full.p90, row.full.p99, row.full.max);
    out += b;
  };
  for (const auto& row : r.per_log) line("observer", row);
  for (const auto& row : r.per_entity) line("entity", row);
  line("", r.all);
  return out;
}

void add_dr_error_command(CLI::App& app, DrErrorOptions& o) {
  auto* c = app.add_subcommand("dr-error", "dead-reckoning error of remote entities from two or more nodes' event logs");
  c->add_option("LOG", o.logs, "event logs of the nodes of one exercise, each run with --track-every S")->required();
  c->add_option("--from", o.from_s, "only samples at scenario time >= S")->check(finite_in(0, 1e7, "s"));
  c->add_option("--to", o.to_s, "only samples at scenario time <= S")->check(finite_in(0, 1e7, "s"));
  c->footer("Each remote sample (a node's dead-reckoned copy of another node's vehicle) is compared with the\n"
            "owner's true position at the same frame: count, p50, p90, p99, max of the horizontal and 3-D error.\n"
            "Example: npsnet dr-error out/events_n1.jsonl out/events_n2.jsonl --from 0 --to 8");
  o.command = c;
}

std::optional<int> run_dr_error_command(const DrErrorOptions& o) {
  if (!o.command || !*o.command) return std::nullopt;
  if (o.logs.size() < 2) {
    std::fprintf(stderr, "npsnet dr-error: give two or more event logs (one per node of the exercise)\n");
    return 2;
  }
  DrErrorReport r;
  try {
    r = dr_error(o.logs, o.from_s, o.to_s);
  } catch (const world::InputError& e) {
    for (const auto& p : e.problems()) std::fprintf(stderr, "%s\n", p.str().c_str());
    return 2;
  }
  if (r.all.horizontal.count == 0) {
    std::fprintf(stderr, "npsnet dr-error: no remote sample matched its owner's sample at the same frame (%ld unmatched): "
                 "are these the logs of one exercise, with the same --dt and --start-at?\n", r.all.unmatched);
    return 2;
  }
  std::printf("%s", format_report(r).c_str());
  return 0;
}

}  // namespace npsnet::node
