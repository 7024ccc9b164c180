// Paced-run timekeeping (pace_stats.hpp).
#include "node/pace_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace npsnet::node {

namespace {
constexpr double kBinRatio = 1.05, kFirstBinS = 1e-6;
}  // namespace

void PaceStats::add(long tick, double took_s, double late_s) {
  ++ticks_;
  longest_tick_s_ = std::max(longest_tick_s_, took_s);
  if (late_s > 0) ++late_ticks_;
  if (late_s > worst_late_s_) worst_late_s_ = late_s, worst_late_tick_ = tick;
  const double b = took_s > kFirstBinS ? std::log(took_s / kFirstBinS) / std::log(kBinRatio) : 0;
  ++bins_[static_cast<size_t>(std::clamp(b, 0.0, double(kBins - 1)))];
}

double PaceStats::median_tick_s() const {
  if (ticks_ == 0) return 0;
  long seen = 0;
  for (int b = 0; b < kBins; ++b)
    if ((seen += bins_[b]) * 2 >= ticks_) return kFirstBinS * std::pow(kBinRatio, b + 0.5);
  return longest_tick_s_;
}

std::string PaceStats::summary() const {
  char s[256];
  std::snprintf(s, sizeof s, "%ld of %ld ticks ended past their deadline, the worst by %.1f ms%s; longest tick %.1f ms; "
                "median tick %.3f ms", late_ticks_, ticks_, 1000 * worst_late_s_,
                late_ticks_ ? (" (tick " + std::to_string(worst_late_tick_) + ")").c_str() : "", 1000 * longest_tick_s_,
                1000 * median_tick_s());
  return s;
}

}  // namespace npsnet::node
