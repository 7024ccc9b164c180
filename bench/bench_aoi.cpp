// bench_aoi: what one node receives with and without area-of-interest groups, against the size of
// the exercise (issue 14). Real sockets on loopback (127.0.0.1), real group joins, the net/
// library's dead reckoning and AOI code; the vehicles are moved here (no terrain, no collision)
// so that 12 nodes and 20,000 entities fit one 2-core machine.
//
// Scene "regions": 12 nodes (3 sites x 4), N ground vehicles at a fixed density of 2 per km^2
// (the map is a square of N / 2 km^2), cut into 4 x 3 regions, one per node; each node's
// vehicles start uniformly in its region and drive at 5-16.7 m/s (Table 2: 60 km/h), turning by
// a random angle every 8 s on average and bouncing off the map's edge. Entity States follow the
// node's rules: dead reckoning RVW, 1 m / 3 deg thresholds, 5 s heartbeat; with AOI a cell change
// sends at once. AOI: --aoi 2000 with 4096 groups (64 x 64 cells = 128 km, no aliasing on the
// maps here); a vehicle wants 5 km + (16.7 + 16.7) m/s x 5 s, left 1 km farther (hysteresis),
// as node/area_of_interest.hpp does.
// Measured over scenario seconds 5-20 (after the start-up burst), ticks of 0.1 s, run as fast as
// the machine goes (rates are per scenario second):
//   pdus_per_s, bytes_per_s  Entity States (144 octets each) one node receives from the others,
//                            mean over the 12 nodes, and the largest node
//   groups                   groups a node holds at the end, mean
//   entities_in_aoi          other nodes' vehicles in the cells of those groups at the end, mean
//                            (without AOI: all other nodes' vehicles)
//   expected - received      what the senders sent into groups the receiver held (or all, without
//                            AOI) minus what it decoded: the socket losses (should be 0)
//   entry latency            for up to 150 pairs a node (another node's vehicle starting 5.0-5.6 km
//                            from the node's nearest vehicle): from the tick the vehicle comes
//                            within 5 km of one of the node's vehicles to the tick the node has an
//                            Entity State of it no older than the 12 s timeout (0 when it already
//                            had), p50 / p99 in scenario seconds; "never" counts entries not shown
//                            by the end.
// Usage: bench_aoi [--quick] [--csv FILE]   (--quick: 1,000 and 5,000 entities only, no CSV)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "support/dirs.hpp"
#include "bench_args.hpp"
#include "net/net.hpp"

namespace {

constexpr int kNodes = 12, kCols = 4, kRows = 3;
constexpr double kDt = 0.1, kWarmS = 5.0, kEndS = 20.0;
constexpr double kRangeM = 5000.0, kVmax = 60.0 / 3.6, kHeartbeatS = 5.0, kTimeoutS = 12.0;
constexpr double kCellM = 2000.0;
constexpr int kGroups = 4096;
constexpr double kDensityPerKm2 = 2.0;
constexpr std::size_t kEsOctets = 144;

struct Vehicle {
  double x, y, speed, heading;  // m, m, m/s, rad (math angle)
  int node;
  std::uint16_t number;          // DIS entity number within its node
  net::DrPublisher pub{net::DrAlgorithm::RVW};
  std::uint32_t group = 0;       // group of its last Entity State
};

struct Result {
  int entities;
  bool aoi;
  double map_km, pdus_mean, pdus_max, bytes_mean, groups_mean, aoi_entities_mean;
  long long expected_minus_received;
  double lat_p50, lat_p99;
  int lat_samples, never;
  double wall_s;
};

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const double k = p * (v.size() - 1);
  const auto i = static_cast<std::size_t>(k);
  return i + 1 < v.size() ? v[i] + (k - i) * (v[i + 1] - v[i]) : v[i];
}

Result run(int n_entities, bool aoi, std::uint16_t port, unsigned seed) {
  const auto wall0 = std::chrono::steady_clock::now();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0, 1);
  const double side = std::sqrt(n_entities / kDensityPerKm2) * 1000.0;
  const double rw = side / kCols, rh = side / kRows;
  const net::AoiGrid grid = net::AoiGrid::make("239.1.2.3", kCellM, kGroups).value();
  const double want_r = kRangeM + 2 * kVmax * kHeartbeatS;

  std::vector<std::unique_ptr<net::Session>> sessions;
  std::vector<net::AoiMembership> members;
  for (int n = 0; n < kNodes; ++n) {
    net::SessionConfig c;
    c.transport.url = "udp://239.1.2.3:" + std::to_string(port);
    c.transport.iface = "127.0.0.1";
    c.transport.join_destination = !aoi;
    c.site = static_cast<std::uint16_t>(1 + n / 4);
    c.application = static_cast<std::uint16_t>(1 + n);
    sessions.push_back(std::make_unique<net::Session>(c));
    members.emplace_back(grid, kCellM / 2);
  }
  std::vector<Vehicle> veh;
  std::vector<std::vector<int>> of_node(kNodes);
  for (int i = 0; i < n_entities; ++i) {
    const int n = i % kNodes;
    Vehicle v;
    v.node = n;
    v.x = (n % kCols + u01(rng)) * rw;
    v.y = (n / kCols + u01(rng)) * rh;
    v.speed = 5.0 + u01(rng) * (kVmax - 5.0);
    v.heading = u01(rng) * 2 * M_PI;
    v.number = static_cast<std::uint16_t>(of_node[n].size() + 1);
    of_node[n].push_back(i);
    veh.push_back(v);
  }
  // Global index of (node, number), and the receivers' last reception of each vehicle.
  auto global = [&](int node, std::uint16_t number) { return of_node[node][number - 1]; };
  std::vector<std::vector<double>> last_rx(kNodes, std::vector<double>(veh.size(), -1e9));
  auto nearest_own = [&](int node, const Vehicle& e) {
    double best = 1e18;
    for (int j : of_node[node]) best = std::min(best, std::hypot(veh[j].x - e.x, veh[j].y - e.y));
    return best;
  };
  // Tracked pairs for the entry latency.
  struct Pair {
    int node, e;
    bool in_range = false, pending = false;
    double entered = 0;
  };
  std::vector<Pair> pairs;
  for (int n = 0; n < kNodes; ++n) {
    int taken = 0;
    for (std::size_t i = 0; i < veh.size() && taken < 150; ++i) {
      if (veh[i].node == n) continue;
      const double d = nearest_own(n, veh[i]);
      if (d > 5000.0 && d < 5600.0) pairs.push_back({n, static_cast<int>(i)}), ++taken;
    }
  }
  std::vector<double> latency;
  int never = 0;
  std::vector<long long> received(kNodes, 0), expected(kNodes, 0);
  std::vector<long long> rx_window(kNodes, 0);
  net::EntityStatePdu es;
  es.entity_type = {1, 1, 225, 1, 1, 3, 0};
  es.alternative_entity_type = es.entity_type;

  auto drain = [&](double t, bool measuring) {
    for (int r = 0; r < kNodes; ++r)
      sessions[r]->poll(net::Overloaded{[&](const net::EntityStatePdu& p) {
        ++received[r];
        if (measuring) ++rx_window[r];
        const int node = p.entity_id.application - 1;
        if (node >= 0 && node < kNodes && p.entity_id.entity >= 1 && p.entity_id.entity <= of_node[node].size())
          last_rx[r][global(node, p.entity_id.entity)] = t;
      }, [](const auto&) {}});
  };

  const long ticks = std::lround(kEndS / kDt);
  for (long k = 0; k < ticks; ++k) {
    const double t = k * kDt;
    const bool measuring = t >= kWarmS;
    for (auto& v : veh) {  // move: random turns, bounce off the map's edge
      if (u01(rng) < kDt / 8.0) v.heading += (u01(rng) - 0.5) * M_PI;
      v.x += std::cos(v.heading) * v.speed * kDt;
      v.y += std::sin(v.heading) * v.speed * kDt;
      if (v.x < 0 || v.x > side) v.heading = M_PI - v.heading, v.x = std::clamp(v.x, 0.0, side);
      if (v.y < 0 || v.y > side) v.heading = -v.heading, v.y = std::clamp(v.y, 0.0, side);
    }
    if (aoi)
      for (int n = 0; n < kNodes; ++n) {
        members[n].begin();
        for (int i : of_node[n]) members[n].want(veh[i].x, veh[i].y, want_r);
        members[n].end([&](std::uint32_t g) { return sessions[n]->join_group(grid.address(g)); },
                        [&](std::uint32_t g) { sessions[n]->leave_group(grid.address(g)); });
      }
    for (int n = 0; n < kNodes; ++n) {
      int since_drain = 0;
      for (int i : of_node[n]) {
        Vehicle& v = veh[i];
        net::KinematicState s;
        s.position = {v.x, v.y, 0};
        s.velocity = {std::cos(v.heading) * v.speed, std::sin(v.heading) * v.speed, 0};
        s.orientation.psi = v.heading;
        const std::uint32_t g = aoi ? grid.address(grid.group_of(v.x, v.y)) : net::Session::kDestination;
        const bool moved_cell = aoi && v.pub.has_sent() && g != v.group;
        if (!moved_cell && v.pub.needs_update(s, t) == net::DrPublisher::Reason::None) continue;
        es.entity_id = sessions[n]->entity_id(v.number);
        net::write_kinematics(s, v.pub.algorithm(), es);
        if (!sessions[n]->send_to(g, es)) continue;
        v.pub.mark_sent(s, t);
        v.group = g;
        for (int r = 0; r < kNodes; ++r)
          if (r != n && (!aoi || members[r].held(grid.group_of(v.x, v.y)))) ++expected[r];
        if (++since_drain == 64) drain(t, measuring), since_drain = 0;  // within a socket buffer
      }
      drain(t, measuring);
    }
    for (auto& p : pairs) {  // entry latency
      const bool in = nearest_own(p.node, veh[p.e]) <= kRangeM;
      const bool shown = t - last_rx[p.node][p.e] <= kTimeoutS;
      if (in && !p.in_range && measuring) {
        if (shown) latency.push_back(0.0);
        else p.pending = true, p.entered = t;
      } else if (p.pending && shown) {
        latency.push_back(t - p.entered);
        p.pending = false;
      }
      p.in_range = in;
    }
  }
  for (const auto& p : pairs) never += p.pending;
  Result res{};
  res.entities = n_entities;
  res.aoi = aoi;
  res.map_km = side / 1000.0;
  const double window = kEndS - kWarmS;
  for (int r = 0; r < kNodes; ++r) {
    res.pdus_mean += rx_window[r] / window / kNodes;
    res.pdus_max = std::max(res.pdus_max, rx_window[r] / window);
    res.groups_mean += (aoi ? members[r].held_count() : 1.0) / kNodes;
    long in_aoi = 0;  // other nodes' vehicles in the groups this node holds (all of them without AOI)
    for (const auto& v : veh) in_aoi += v.node != r && (!aoi || members[r].held(grid.group_of(v.x, v.y)));
    res.aoi_entities_mean += static_cast<double>(in_aoi) / kNodes;
    res.expected_minus_received += expected[r] - received[r];
  }
  res.bytes_mean = res.pdus_mean * kEsOctets;
  res.lat_p50 = percentile(latency, 0.5);
  res.lat_p99 = percentile(latency, 0.99);
  res.lat_samples = static_cast<int>(latency.size());
  res.never = never;
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

std::string row(const Result& r) {
  char line[256];
  std::snprintf(line, sizeof line, "%d,%d,%.1f,%.1f,%.1f,%.0f,%.1f,%.0f,%lld,%.2f,%.2f,%d,%d,%.1f", r.entities, r.aoi ? 1 : 0,
                r.map_km, r.pdus_mean, r.pdus_max, r.bytes_mean, r.groups_mean, r.aoi_entities_mean,
                r.expected_minus_received, r.lat_p50,
                r.lat_p99, r.lat_samples, r.never, r.wall_s);
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  const auto [quick, csv] = npsnet::bench::bench_args(argc, argv, "bench_aoi: the area of interest's traffic and entry latency",
                                                      "1,000 and 5,000 entities only, no CSV",
                                                      std::string(npsnet::dirs::source()) + "/bench/results/aoi.csv");
  const std::vector<int> sizes = quick ? std::vector<int>{1000, 5000} : std::vector<int>{1000, 2000, 5000, 10000, 20000};
  const std::uint16_t port = static_cast<std::uint16_t>(20000 + ::getpid() % 40000);
  std::vector<Result> out;
  const char* head =
      "entities,aoi,map_km,pdus_per_s_node,pdus_per_s_max_node,bytes_per_s_node,groups_node,entities_in_aoi_node,expected_minus_received,"
      "entry_latency_p50_s,entry_latency_p99_s,entry_samples,never_shown,wall_s";
  std::printf("%s\n", head);
  for (int n : sizes)
    for (bool aoi : {false, true}) {
      const Result r = run(n, aoi, port, 1234u + static_cast<unsigned>(n));
      std::printf("%s\n", row(r).c_str());
      std::fflush(stdout);
      out.push_back(r);
    }
  if (quick) return 0;
  std::ofstream f(csv);
  f << head << "\n";
  for (const auto& r : out) f << row(r) << "\n";
  std::fprintf(stderr, "bench_aoi: wrote %s\n", csv.c_str());
  return 0;
}
