// Timing helpers of the benchmarks: medians of repeated runs (never used by the tests).
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace trebuchet::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

/// Repeats `work` until `budget` seconds have passed (at least 3, at most 41 times); median [s].
template <class Work>
double median_seconds(Work work, double budget) {
  std::vector<double> times;
  const auto start = Clock::now();
  while (times.size() < 3 || (times.size() < 41 && seconds_since(start) < budget)) {
    const auto t0 = Clock::now();
    work();
    times.push_back(seconds_since(t0));
  }
  return median(times);
}

}  // namespace trebuchet::bench
