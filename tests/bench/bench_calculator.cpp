// Calculator throughput in the library, one core: designs per second, median of repeated runs.
// Usage: bench-calculator [designs_per_run] [runs]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "timing.hpp"

using namespace trebuchet;
using trebuchet::bench::median;

namespace {

// Capacities spread over the covered X interval and a decade of sizes (Y), fixed seed.
std::vector<DesignRequest> requests(std::size_t count, Quantity second) {
  std::mt19937_64 random(20261121);
  std::uniform_real_distribution<double> X(-0.5, 0.5), Y(-1.0, 2.0);
  std::vector<DesignRequest> list;
  for (std::size_t k = 0; k < count; ++k) {
    const double x = X(random), y = Y(random);
    const Capacity capacity = capacity_at({x, y}, 240, 26000);
    DesignRequest r;
    r.first = {Quantity::R, capacity.R};
    r.second = {Quantity::T, capacity.T};
    if (second != Quantity::T)  // the same engines, asked for through another given
      r.second = {second, design_optimal_engine(builtin_scaling_table(), r).engine.m};
    list.push_back(r);
  }
  return list;
}

void measure(const char* label, const std::vector<DesignRequest>& list, int runs) {
  const ScalingTable& table = builtin_scaling_table();
  std::vector<double> rates;
  double checksum = 0;
  for (int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    for (const DesignRequest& r : list) checksum += design_optimal_engine(table, r).engine.M;
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    rates.push_back(static_cast<double>(list.size()) / elapsed.count());
  }
  std::printf("%-24s median %.3g designs/s (%d runs of %zu; min %.3g, max %.3g)  [checksum %.6g]\n", label, median(rates), runs, list.size(),
              *std::min_element(rates.begin(), rates.end()), *std::max_element(rates.begin(), rates.end()), checksum);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t designs = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 100000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 15;
  measure("R, T given", requests(designs, Quantity::T), runs);
  measure("R, m given (2x2 solve)", requests(designs, Quantity::m), runs);
  return 0;
}
