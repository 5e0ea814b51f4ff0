// Uncertain inputs, because sources are vague: a value may be a range "2.5t..3.5t" (uniform) or
// a spread "3.5m±0.2m" (normal, mean ± standard deviation), and a Monte Carlo run draws them on
// every core, deterministically under a seed (docs/historians.md).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>


namespace trebuchet {

/// A distribution of one input, in SI units.
struct Spread {
  enum class Kind { uniform, normal } kind;
  double a, b;  ///< uniform: from a to b; normal: mean a, standard deviation b
};

double draw(const Spread& spread, std::mt19937_64& random);

/// What one sample gives: R [m], T [J], eps and the release speed v [m/s], or why it failed.
struct SampleOutcome {
  std::array<double, 4> values{};
  std::string failure;  ///< empty when the sample worked
};

inline constexpr std::array<const char*, 4> sample_names = {"R", "T", "eps", "v"};

struct MonteCarloSummary {
  int samples = 0;
  std::vector<std::array<double, 4>> values;            ///< of the samples that worked, in sample order
  std::array<std::array<double, 3>, 4> percentiles{};   ///< 5, 50 and 95 % of R, T, eps, v
  std::vector<std::pair<std::string, int>> failures;    ///< each reason (its message to the first ';', numbers as #) and its count
};

/// Runs `sample` for samples 0 .. n - 1 on `threads` threads. Sample i draws from its own
/// generator, seeded from (seed, i), so the result is the same on any number of threads.
MonteCarloSummary run_monte_carlo(int samples, std::uint64_t seed, int threads,
                                  const std::function<SampleOutcome(std::mt19937_64& random)>& sample);

}  // namespace trebuchet
