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

#include "trebuchet/error.hpp"
#include "trebuchet/parallel.hpp"

namespace trebuchet {

/// A distribution of one input, in SI units.
struct Spread {
  enum class Kind { uniform, normal } kind;
  double a, b;  ///< uniform: from a to b; normal: mean a, standard deviation b
};

double draw(const Spread& spread, std::mt19937_64& random);

/// A fraction count/of of samples, with its 95 % Wilson score interval (binomial; sound for
/// fractions near 0 or 1 and few samples). All 0 for no samples.
struct Share {
  double fraction = 0, low = 0, high = 0;
};
Share binomial_share(int count, int of);

/// What one sample gives: R [m], T [J], eps and the release speed v [m/s], or why it failed.
struct SampleOutcome {
  std::array<double, 4> values{};
  std::vector<double> drawn;  ///< the run's uncertain inputs as this sample drew them, in their order (SI; angles in degrees)
  std::string failure;  ///< empty when the sample worked
  ErrorKind failure_kind = ErrorKind::numerical;  ///< what kind of failure (error.hpp): bad input or numerical
};

/// The samples that failed for one reason.
struct SampleFailures {
  std::string reason;  ///< the message to its first ';', its numbers written # so that alike failures count together
  int count = 0;
  std::string first;  ///< the whole message of the first sample that failed so, numbers and all
  ErrorKind kind = ErrorKind::numerical;  ///< that sample's
};

inline constexpr std::array<const char*, 4> sample_names = {"R", "T", "eps", "v"};

struct MonteCarloSummary {
  int samples = 0;
  std::vector<std::array<double, 4>> values;  ///< of the samples that worked, in sample order
  std::vector<std::vector<double>> drawn;  ///< their drawn inputs, beside `values`
  std::vector<SampleOutcome> outcomes;  ///< every sample's, worked or not, in sample order
  std::array<std::array<double, 3>, 4> percentiles{};  ///< 5, 50 and 95 % of R, T, eps, v
  std::vector<SampleFailures> failures;  ///< by reason, the most frequent first
};

/// Runs `sample` for samples 0 .. n - 1 on `threads` threads. Sample i draws from its own
/// generator, seeded from (seed, i), so the result is the same on any number of threads.
/// `progress` hears of every sample done.
MonteCarloSummary run_monte_carlo(int samples, std::uint64_t seed, int threads, const std::function<SampleOutcome(std::mt19937_64& random)>& sample,
                                  const Progress& progress = {});

/// Sample i of a run under `seed` alone, as run_monte_carlo runs it: a run split into parts (the
/// browser page's Web Workers) gives the same samples as the whole.
SampleOutcome run_sample(std::uint64_t seed, std::size_t i, const std::function<SampleOutcome(std::mt19937_64& random)>& sample);

/// The summary of a run's outcomes, given in sample order.
MonteCarloSummary summarize_samples(const std::vector<SampleOutcome>& outcomes);

/// How often the samples that worked reach a claimed range: the fraction whose R is at least
/// the claim, with its 95 % Wilson score interval (binomial; sound for fractions near 0 or 1
/// and few samples), and the median of each drawn input over the samples that reach it.
struct ClaimAssessment {
  double claim = 0;  ///< R [m]
  int reached = 0, worked = 0;
  double probability = 0, low = 0, high = 0;
  std::vector<double> median_reaching;  ///< by input; empty when none reaches the claim
};
ClaimAssessment assess_claim(const MonteCarloSummary& summary, double claim);

/// How much a drawn input moves the first of the sample values, with the 95 % interval of that
/// correlation over runs of as many samples: Fisher's z, atanh rho, is near normal with the
/// variance 1.06/(n - 3) for Spearman's rho (Fieller, Hartley and Pearson 1957). Resolved where
/// the interval leaves 0 out: the run's samples tell its sign; otherwise another seed may rank
/// it elsewhere.
struct RankCorrelation {
  double rho = 0, low = -1, high = 1;
  bool resolved() const { return low > 0 || high < 0; }
};

/// How much each drawn input moves the first of the sample values (R in a shot's run, the fitted
/// friction in a calibration's): Spearman's rank correlation of the input with it over the
/// samples that worked (GSL's gsl_stats_spearman), which a monotone effect of any shape shows
/// and the other inputs' independent draws do not bias, with its interval. By input, in the
/// run's order; 0 for an input or an R that does not vary. Empty with fewer than 3 samples that
/// worked.
std::vector<RankCorrelation> rank_correlations(const MonteCarloSummary& summary);

}  // namespace trebuchet
