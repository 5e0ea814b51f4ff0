#include "trebuchet/uncertainty.hpp"

#include <gsl/gsl_statistics_double.h>

#include <cmath>
#include <algorithm>
#include <map>
#include <regex>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/parallel.hpp"

namespace trebuchet {

namespace {

// A failure's reason without its numbers, so that samples failing alike count together:
// "L4 = -4.5: the sling length must be positive" is "L4 = #: the sling length must be positive".
std::string failure_reason(const std::string& message) {
  // A number is not part of a name: L4 keeps its 4.
  static const std::regex number("(^|[^A-Za-z0-9_.])[-+]?[0-9]+(\\.[0-9]*)?([eE][-+]?[0-9]+)?");
  return std::regex_replace(message.substr(0, message.find(';')), number, "$1#");
}

}  // namespace

double draw(const Spread& spread, std::mt19937_64& random) {
  if (spread.kind == Spread::Kind::uniform) return std::uniform_real_distribution<double>(spread.a, spread.b)(random);
  return std::normal_distribution<double>(spread.a, spread.b)(random);
}

Share binomial_share(int count, int of) {
  Share out;
  if (of <= 0) return out;
  // Wilson's score interval at 95 % (z = 1.96).
  const double n = of, p = count / n, z = 1.959963984540054;
  const double centre = (p + z * z / (2 * n)) / (1 + z * z / n), half = z / (1 + z * z / n) * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n));
  out.fraction = p;
  // At none or all, an end is 0 or 1 exactly (the formula's round-off would leave 1e-17).
  out.low = count == 0 ? 0 : std::max(0.0, centre - half);
  out.high = count == of ? 1 : std::min(1.0, centre + half);
  return out;
}

SampleOutcome run_sample(std::uint64_t seed, std::size_t i, const std::function<SampleOutcome(std::mt19937_64& random)>& sample) {
  // Each sample's own generator: its draws do not depend on which thread runs it, or when.
  std::seed_seq sequence{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32), static_cast<std::uint32_t>(i),
                         static_cast<std::uint32_t>(static_cast<std::uint64_t>(i) >> 32)};
  std::mt19937_64 random(sequence);
  return sample(random);
}

MonteCarloSummary run_monte_carlo(int samples, std::uint64_t seed, int threads, const std::function<SampleOutcome(std::mt19937_64& random)>& sample,
                                  const Progress& progress) {
  std::vector<SampleOutcome> outcomes(static_cast<std::size_t>(samples));
  for_each_index(
      outcomes.size(), threads, [&](std::size_t i) { outcomes[i] = run_sample(seed, i, sample); }, progress);
  return summarize_samples(outcomes);
}

MonteCarloSummary summarize_samples(const std::vector<SampleOutcome>& outcomes) {
  MonteCarloSummary summary;
  summary.samples = static_cast<int>(outcomes.size());
  std::map<std::string, std::size_t> reasons;  // each reason's place in summary.failures
  summary.outcomes = outcomes;
  for (const SampleOutcome& o : outcomes) {
    if (o.failure.empty()) {
      summary.values.push_back(o.values);
      summary.drawn.push_back(o.drawn);
      continue;
    }
    const std::string reason = failure_reason(o.failure);
    const auto [at, first] = reasons.emplace(reason, summary.failures.size());
    if (first) summary.failures.push_back({reason, 0, o.failure, o.failure_kind});
    ++summary.failures[at->second].count;
  }
  // The most frequent first; alike counts in the order they first failed.
  std::stable_sort(summary.failures.begin(), summary.failures.end(), [](const auto& a, const auto& b) { return a.count > b.count; });
  if (!summary.values.empty())
    for (std::size_t k = 0; k < sample_names.size(); ++k) {
      std::vector<double> column;
      for (const auto& v : summary.values) column.push_back(v[k]);
      std::sort(column.begin(), column.end());
      for (int p = 0; p < 3; ++p)
        summary.percentiles[k][static_cast<std::size_t>(p)] = gsl_stats_quantile_from_sorted_data(
            column.data(), 1, column.size(), std::array{0.05, 0.5, 0.95}[static_cast<std::size_t>(p)]);
    }
  return summary;
}

ClaimAssessment assess_claim(const MonteCarloSummary& summary, double claim) {
  ClaimAssessment out;
  out.claim = claim;
  out.worked = static_cast<int>(summary.values.size());
  std::vector<std::vector<double>> reaching(summary.drawn.empty() ? 0 : summary.drawn.front().size());
  for (std::size_t i = 0; i < summary.values.size(); ++i) {
    if (!(summary.values[i][0] >= claim)) continue;
    ++out.reached;
    for (std::size_t k = 0; k < reaching.size() && k < summary.drawn[i].size(); ++k) reaching[k].push_back(summary.drawn[i][k]);
  }
  if (out.worked == 0) return out;
  const Share share = binomial_share(out.reached, out.worked);
  out.probability = share.fraction, out.low = share.low, out.high = share.high;
  if (out.reached > 0)
    for (std::vector<double>& column : reaching) {
      std::sort(column.begin(), column.end());
      out.median_reaching.push_back(gsl_stats_median_from_sorted_data(column.data(), 1, column.size()));
    }
  return out;
}

std::vector<RankCorrelation> rank_correlations(const MonteCarloSummary& summary) {
  const std::size_t n = summary.values.size();
  if (n < 3 || summary.drawn.front().empty()) return {};
  std::vector<double> R(n), work(2 * n);
  std::vector<RankCorrelation> out;
  for (std::size_t i = 0; i < n; ++i) R[i] = summary.values[i][0];
  // 1.96 standard deviations of z either side: 95 %. With 3 samples the interval is all of -1..1.
  const double half_width = n > 3 ? 1.96 * std::sqrt(1.06 / static_cast<double>(n - 3)) : 1e300;
  for (std::size_t k = 0; k < summary.drawn.front().size(); ++k) {
    std::vector<double> input(n);
    for (std::size_t i = 0; i < n; ++i) input[i] = summary.drawn[i][k];
    const double value = gsl_stats_spearman(input.data(), 1, R.data(), 1, n, work.data());
    RankCorrelation c;
    c.rho = std::isfinite(value) ? std::clamp(value, -1.0, 1.0) : 0;  // a constant column has none; round-off can pass +-1
    const double z = std::atanh(std::clamp(c.rho, -1 + 1e-12, 1 - 1e-12));  // finite at +-1 (14.2), where a few samples still leave doubt
    c.low = std::tanh(z - half_width), c.high = std::tanh(z + half_width);
    out.push_back(c);
  }
  return out;
}

}  // namespace trebuchet
