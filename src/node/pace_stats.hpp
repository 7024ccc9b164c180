// How a paced run kept time (run.cpp prints it at the end): how many ticks ended past their
// deadline and the worst by how much, the longest tick and the median tick (the tick's own work,
// not the sleep after it). The median comes from a histogram of log-spaced bins (5 % apart,
// 1 us to 100 s): no allocation per tick, however long the run; it is reported as the centre of
// its bin (within 2.5 %).
#pragma once
#include <array>
#include <cstdint>
#include <string>

namespace npsnet::node {

class PaceStats {
 public:
  // Tick `tick` took `took_s` of work and ended `late_s` past its deadline (<= 0: on time).
  void add(long tick, double took_s, double late_s);
  double median_tick_s() const;  // 0 before any tick
  // "L of N ticks ended past their deadline, the worst by X ms (tick T); longest tick Y ms;
  // median tick Z ms"
  std::string summary() const;

 private:
  static constexpr int kBins = 380;  // 1.05^378 = 1e8: 1 us .. 100 s
  std::array<uint32_t, kBins> bins_{};
  long ticks_ = 0, late_ticks_ = 0, worst_late_tick_ = -1;
  double worst_late_s_ = 0, longest_tick_s_ = 0;
};

}  // namespace npsnet::node
