// The paced run's summary (node/pace_stats.hpp): late ticks, the worst, the longest and the median
// tick, from a histogram that allocates nothing per tick.
#include <gtest/gtest.h>

#include "node/pace_stats.hpp"

using npsnet::node::PaceStats;

TEST(PaceStats, MedianWithinItsBinLateTicksAndTheWorstNamed) {
  PaceStats p;
  EXPECT_EQ(p.median_tick_s(), 0.0);
  // 101 ticks: 50 of 0.2 ms, 51 of 1.5 ms (the median), two of them late, the worst tick 70.
  for (long i = 0; i < 101; ++i) {
    const double took = i % 2 ? 0.2e-3 : 1.5e-3;
    const double late = i == 30 ? 0.004 : i == 70 ? 0.012 : -0.01;
    p.add(i, took, late);
  }
  EXPECT_NEAR(p.median_tick_s(), 1.5e-3, 1.5e-3 * 0.026);
  const std::string s = p.summary();
  EXPECT_EQ(s.rfind("2 of 101 ticks ended past their deadline, the worst by 12.0 ms (tick 70); longest tick 1.5 ms; "
                    "median tick ", 0), 0u) << s;
}

TEST(PaceStats, OnTimeRunsSayNoTickAndExtremesStayInTheEndBins) {
  PaceStats p;
  p.add(0, 0.0, 0.0);    // below the first bin
  p.add(1, 1e4, 0.0);    // past the last (a frozen exercise counted whole)
  p.add(2, 2e-6, -1.0);
  EXPECT_EQ(p.summary().rfind("0 of 3 ticks ended past their deadline, the worst by 0.0 ms; longest tick 10000000.0 ms", 0), 0u)
      << p.summary();
  EXPECT_NEAR(p.median_tick_s(), 2e-6, 2e-6 * 0.026);
}
