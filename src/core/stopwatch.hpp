// Milliseconds of the steady clock since t0: the timings benchmarks and reports print (never an
// input to a decision that must be the same from run to run).
#pragma once
#include <chrono>

namespace npsnet::core {

inline double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace npsnet::core
