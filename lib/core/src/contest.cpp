#include "trebuchet/contest.hpp"

#include <gsl/gsl_qrng.h>
#include <nlopt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "lowest_clearance.hpp"
#include "trebuchet/angles.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/machine.hpp"

namespace trebuchet {
namespace {

// m/M at the search's bound where the request gives no limit on M: a counterweight of at most
// 1e5 times the ball.
constexpr double unlimited_least_mu = 1e-5;

// m over the largest counterweight allowed (at most 0.5), where the request limits it.
std::optional<double> least_mu(const ContestRequest& r) {
  if (!r.limits[mass_limit]) return std::nullopt;
  return std::min(r.projectile_mass / *r.limits[mass_limit], 0.5);
}

// How many coordinates a candidate's point has: L3/L2 the hinged machine's alone.
std::size_t point_size(const ContestRequest& r) { return r.machine == MachineKind::hinged ? 5 : 4; }

// A candidate's point: the logs of L1/L2, L4/L1, m/M, L2 [m] and, for the hinged machine, L3/L2.
using SearchPoint = std::vector<double>;

Engine engine_at(const ContestRequest& r, const SearchPoint& x) {
  Engine e;
  e.machine = r.machine;
  e.theta_i_deg = r.theta_i_deg;
  e.material = r.material;
  e.L2 = std::exp(x[3]);
  e.L1 = std::exp(x[0]) * e.L2;
  e.L3 = r.machine == MachineKind::hinged ? std::exp(x[4]) * e.L2 : 0;  // the others' counterweight at the short arm's end
  e.L4 = std::exp(x[1]) * e.L1;
  e.m = r.projectile_mass;
  e.M = r.projectile_mass / std::exp(x[2]);
  e.mb = r.beam_mass_per_length * (e.L1 + e.L2);
  if (r.box_width && r.box_height) give_box(e, *r.box_width, *r.box_height);
  e.parts.rope_mass = r.rope_mass, e.parts.pouch_mass = r.pouch_mass, e.parts.pin_friction = r.pin_friction;
  e.projectile_diameter = r.projectile_diameter;
  return e;
}

SearchPoint point_of(const Engine& e) {
  SearchPoint x{std::log(e.L1 / e.L2), std::log(e.L4 / e.L1), std::log(e.m / e.M), std::log(e.L2)};
  if (e.machine == MachineKind::hinged) x.push_back(std::log(e.L3 / e.L2));
  return x;
}

// The bounds of a candidate's point: L1/L2 from 1.05 to 60, L4/L1 from 0.05 to 20, M up to its
// limit (m/M from m over it, or unlimited_least_mu, to 0.999), L2 from 1 mm to 1 km, L3/L2 from
// 0.01 to 20.
std::pair<SearchPoint, SearchPoint> bounds_of(const ContestRequest& r) {
  SearchPoint low{std::log(1.05), std::log(0.05), std::log(least_mu(r).value_or(unlimited_least_mu)), std::log(1e-3), std::log(0.01)};
  SearchPoint high{std::log(60.0), std::log(20.0), std::log(0.999), std::log(1e3), std::log(20.0)};
  low.resize(point_size(r)), high.resize(point_size(r));
  return {low, high};
}

// What one candidate's shot gave: the engine with its measures, or why it could not be shot.
// An engine whose sling goes slack before the release is refused, but kept with how far its pull
// falls below 0: the searches see the edge of the engines that hold as they see a limit's.
struct Outcome {
  std::optional<ContestEngine> engine;
  std::string failure;
  double slack = 0;  // the sling's least pull below 0 before the release, in the projectile's weights (refused)
  bool usable() const { return engine && failure.empty(); }
};

// Every candidate of one contest, shot once: the objective and every limit come from the same
// shot, and the searches at relaxed limits (the gains) share the shots they repeat.
class Shots {
 public:
  explicit Shots(const ContestRequest& r) : request_(r) {}
  const Outcome& at(const SearchPoint& x) {
    auto found = outcomes_.find(x);
    return found != outcomes_.end() ? found->second : outcomes_.emplace(x, shoot(x)).first->second;
  }
  int count() const { return static_cast<int>(outcomes_.size()); }
  const std::map<SearchPoint, Outcome>& outcomes() const { return outcomes_; }

 private:
  Outcome shoot(const SearchPoint& x) const {
    Outcome out;
    try {
      ContestEngine c;
      c.engine = engine_at(request_, x);
      double least_pull = 0;
      c.measured = contest_measures(c.engine, request_.settings, &c.verification, &least_pull);
      c.objective = request_.efficiency ? c.verification.eps : c.verification.capacity.R;
      c.clearance = lowest_clearance(c.verification);
      // The model stops holding before the release: no engine. A counterweight that strikes the
      // ground (a clearance below 0, and where it does so before the release, a warning more) is
      // an engine that misses the clearance, which the search then sees shrink continuously.
      const Verification& v = c.verification;
      const std::size_t ground_warnings = v.clearance.buildable() ? 0u : 1u + v.counterweight_below_base;
      if (v.warnings.size() > ground_warnings) out.failure = v.warnings.front();
      if (v.sling_slack && v.warnings.size() == ground_warnings + 1)  // the slack sling alone
        out.slack = std::max(-least_pull, 1e-6);  // a dip between the samples: just past the edge
      if (out.failure.empty() || out.slack > 0) out.engine = c;
    } catch (const Error& e) {
      out.failure = e.named_message();
    }
    return out;
  }
  const ContestRequest& request_;  // its engine and settings (the limits differ between searches)
  std::map<SearchPoint, Outcome> outcomes_;
};

// By how much an engine misses each limit, scaled to it (positive: missed): the limits given but
// the counterweight's mass (a bound of the search), then the clearance over the engine's height.
std::vector<double> misses(const ContestEngine& c, const ContestRequest& r) {
  std::vector<double> out;
  for (int k = 0; k < contest_limit_count; ++k)
    if (r.limits[k] && k != mass_limit) out.push_back(c.measured[k] / *r.limits[k] - 1);
  out.push_back((r.min_clearance - c.clearance) / pivot_height(c.engine));
  return out;
}

std::size_t miss_count(const ContestRequest& r) {
  std::size_t count = 1;
  for (int k = 0; k < contest_limit_count; ++k) count += r.limits[k] && k != mass_limit;
  return count;
}

bool meets_limits(const ContestEngine& c, const ContestRequest& r) {
  // M = m/(m/M) may round a part in 1e16 above its limit.
  if (r.limits[mass_limit] && c.measured[mass_limit] > *r.limits[mass_limit] * (1 + 1e-12)) return false;
  for (double miss : misses(c, r))
    if (miss > 0) return false;
  return true;
}

// The searches of one request: local searches by COBYLA (NLopt's constrained simplex of linear
// approximations) in the candidate's point, each limit a constraint, the counterweight's mass a
// bound; the best engine that meets the limits over all of them.
struct Search {
  Search(const ContestRequest& r, Shots& s) : request(r), shots(s) {}
  const ContestRequest& request;
  Shots& shots;
  bool until_feasible = false;  // whether any engine that meets the limits is all that is asked
  std::optional<ContestEngine> best;  // the best that meets the limits
  std::optional<ContestEngine> best_of_start;  // the same, of the local search under way
  std::string last_failure;  // why the last candidate that could not be shot failed
  bool any_engine = false;  // whether any candidate was shot, within the limits or not
  bool see_slack = true;  // whether COBYLA sees how far a slack engine goes slack, or none there
  nlopt_opt optimizer = nullptr;

  const Outcome& shoot(const SearchPoint& x) {
    const Outcome& out = shots.at(x);
    any_engine = any_engine || out.usable();
    if (!out.usable()) {
      last_failure = out.failure;
    } else if (meets_limits(*out.engine, request)) {
      if (!best_of_start || out.engine->objective > best_of_start->objective) best_of_start = out.engine;
      if (!best || out.engine->objective > best->objective) best = out.engine;
      if (until_feasible) nlopt_force_stop(optimizer);
    }
    return out;
  }

  // Whether COBYLA sees the outcome's engine: a usable one, or a slack one where see_slack.
  bool sees(const Outcome& out) const { return out.usable() || (see_slack && out.engine); }

  static double minus_log_objective(unsigned n, const double* x, double*, void* data) {
    Search& s = *static_cast<Search*>(data);
    const Outcome& out = s.shoot(SearchPoint(x, x + n));
    return s.sees(out) && out.engine->objective > 0 ? -std::log(out.engine->objective) : 50;  // none: worse than any engine
  }
  static void limits_missed(unsigned m, double* result, unsigned n, const double* x, double*, void* data) {
    Search& s = *static_cast<Search*>(data);
    const Outcome& out = s.shoot(SearchPoint(x, x + n));
    const bool seen = s.sees(out);
    std::vector<double> missed = seen ? misses(*out.engine, s.request) : std::vector<double>(m - 1, 1.0);
    missed.push_back(seen ? out.slack : 1.0);
    std::copy(missed.begin(), missed.end(), result);
  }

  // One run of COBYLA from `x`, its first steps `step` in the logs, stopped where a step of
  // `resolution` changes nothing (the limits then met to about that of them), or after 1500 shots.
  void cobyla(SearchPoint x, double step, double resolution) {
    auto [low, high] = bounds_of(request);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], low[i], high[i]);
    optimizer = nlopt_create(NLOPT_LN_COBYLA, static_cast<unsigned>(x.size()));
    nlopt_set_lower_bounds(optimizer, low.data());
    nlopt_set_upper_bounds(optimizer, high.data());
    nlopt_set_min_objective(optimizer, minus_log_objective, this);
    const std::vector<double> tolerances(miss_count(request) + 1, 0.0);  // the limits, then the sling's slack
    nlopt_add_inequality_mconstraint(optimizer, static_cast<unsigned>(tolerances.size()), limits_missed, this, tolerances.data());
    nlopt_set_initial_step1(optimizer, step);
    nlopt_set_xtol_abs1(optimizer, resolution);
    nlopt_set_maxeval(optimizer, 1500);
    double value = 0;
    nlopt_optimize(optimizer, x.data(), &value);
    nlopt_destroy(optimizer);
    optimizer = nullptr;
  }

  // A coarse local search from `start`: steps of `step` in the logs (a quarter from a start far
  // from any optimum) down to 1e-3. Its end: the best engine it found that meets the limits.
  std::optional<ContestEngine> coarse(const SearchPoint& start, double step) {
    best_of_start.reset();
    cobyla(start, step, 1e-3);
    return best_of_start;
  }

  // A coarse search's end refined: steps of 0.05 down to 1e-6, and again from the end while that
  // gains (at most 3 times): COBYLA, its steps shrunk against several limits at once, can stop
  // short of their corner. The objective it reached.
  double refine(const ContestEngine& end) {
    best_of_start = end;
    for (int run = 0; run < 4; ++run) {
      const double before = best_of_start->objective;
      cobyla(point_of(best_of_start->engine), 0.05, 1e-6);
      if (run > 0 && !(best_of_start->objective > before * (1 + 1e-9))) break;
    }
    return best_of_start->objective;
  }
};

// The first point of every search: the paper's proportions (L1/L2 = 4, L4/L1 = 0.9, M = 50 m or
// its limit, L3/L2 = 0.8) at a size within the box when one is given.
SearchPoint paper_start(const ContestRequest& r, double box) {
  const double mu = std::max(0.02, least_mu(r).value_or(0));
  SearchPoint x{std::log(4.0), std::log(0.9), std::log(mu), std::log(box < 1e300 ? 0.15 * box / 4 : 1)};
  if (r.machine == MachineKind::hinged) x.push_back(std::log(0.8));
  return x;
}

// A Sobol sequence of `dimension` coordinates (GSL's gsl_qrng): the same points every run.
using Sobol = std::unique_ptr<gsl_qrng, decltype(&gsl_qrng_free)>;
Sobol sobol_sequence(std::size_t dimension) { return Sobol(gsl_qrng_alloc(gsl_qrng_sobol, static_cast<unsigned>(dimension)), gsl_qrng_free); }

// The points of a Sobol sequence (GSL's gsl_qrng) over the shapes a contest's engine takes,
// log-uniform: L1/L2 from 1.5 to 8, L4/L1 from 0.4 to 1.6, M from its limit to a twentieth of it
// (or 10 to 200 m), L2 about 0.3 of the box over L1/L2 + 1 (within a factor 3), or 0.2 to 5 m
// without a box, L3/L2 from 0.3 to 1.5. With `shrink`, L2 is then shortened where the beam would
// outweigh half the counterweight, which could hardly turn it: a small counterweight or a heavy
// beam, where no engine of the sample as drawn meets the limits, starts small engines too.
std::vector<SearchPoint> sobol_sample(const ContestRequest& r, double box, int count, bool shrink) {
  const std::size_t n = point_size(r);
  const Sobol sequence = sobol_sequence(n);
  const auto between = [](double low, double high, double u) { return std::log(low) + u * (std::log(high) - std::log(low)); };
  const double mu_least = least_mu(r).value_or(0.005), least_L2 = bounds_of(r).first[3];
  std::vector<SearchPoint> sample;
  for (int k = 0; k < count; ++k) {
    double u[5] = {};
    gsl_qrng_get(sequence.get(), u);
    SearchPoint x{between(1.5, 8, u[0]), between(0.4, 1.6, u[1]), between(mu_least, std::min(20 * mu_least, 0.999), u[2])};
    const double l = std::exp(x[0]);
    x.push_back(box < 1e300 ? between(0.3 * box / (l + 1) / std::sqrt(3.0), 0.3 * box / (l + 1) * std::sqrt(3.0), u[3]) : between(0.2, 5, u[3]));
    if (shrink && r.beam_mass_per_length > 0)  // the beam's mass (l + 1) L2 per metre at most half the counterweight's, m/(m/M)
      x[3] = std::max(std::min(x[3], std::log(r.projectile_mass / std::exp(x[2]) / (2 * r.beam_mass_per_length * (l + 1)))), least_L2);
    if (n == 5) x.push_back(between(0.3, 1.5, u[4]));
    sample.push_back(x);
  }
  return sample;
}

// The starts of a search: `warm` first, the paper's proportions, then the best of a Sobol sample
// (those that meet the limits by their objective, then the others by how little they miss).
std::vector<SearchPoint> starts_of(Search& search, const std::vector<SearchPoint>& warm, int sample_starts) {
  const ContestRequest& r = search.request;
  const double box = std::min(r.limits[width_limit].value_or(1e300), r.limits[height_limit].value_or(1e300));
  std::vector<SearchPoint> starts = warm;
  starts.push_back(paper_start(r, box));
  std::vector<std::pair<double, SearchPoint>> ranked;
  for (const bool shrink : {false, true}) {  // shrunk only where the sample as drawn met the limits nowhere
    if (std::any_of(ranked.begin(), ranked.end(), [](const auto& one) { return one.first <= 0; })) break;
    for (const SearchPoint& x : sobol_sample(r, box, contest_sample_size, shrink)) {
      const Outcome& out = search.shoot(x);
      if (search.until_feasible && search.best) return {};
      if (!out.usable()) continue;
      double missed = 0;
      for (double miss : misses(*out.engine, r)) missed += std::max(0.0, miss);
      ranked.emplace_back(missed > 0 ? missed : -out.engine->objective, x);
    }
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  // The best first, each at least 0.3 from every start before it in some log: starts in distinct
  // places, not five in one basin.
  const auto apart = [&](const SearchPoint& x) {
    for (const SearchPoint& start : starts) {
      double distance = 0;
      for (std::size_t i = 0; i < x.size(); ++i) distance = std::max(distance, std::abs(x[i] - start[i]));
      if (distance < 0.3) return false;
    }
    return true;
  };
  for (std::size_t k = 0; k < ranked.size() && starts.size() < warm.size() + 1 + sample_starts; ++k)
    if (apart(ranked[k].second)) starts.push_back(ranked[k].second);
  return starts;
}

// What a search found: the best engine that meets the limits, what each local search reached
// (none where it found no such engine), and why the last candidate that failed, failed.
struct Found {
  std::optional<ContestEngine> best;
  std::vector<std::optional<double>> start_objectives;
  std::vector<SearchPoint> ends;  // where the local searches that found such an engine ended, the best first
  std::string last_failure;
  bool any_engine = false;  // whether any candidate could be shot
  int local_searches = 0;  // from the starts
  int hops = 0, hops_gained = 0;  // from the best (hop_from_best)
};

// How far a search reaches beyond its warm starts: not at all (the Pareto front's next point);
// near (the gains: the paper's proportions and the sample's best two, the two best ends
// refined); or wholly (the contest: the paper's proportions and the sample's best five, every end
// within 1 % of the best refined).
enum class Reach { warm_only, near, whole };

// Hops from the best (monotone basin hopping): a coarse search from a point up to `contest_hop`
// from it in each log, a Sobol set's (the same every run); an end that throws farther is refined
// and hopped from in turn. It ends after `contest_fruitless_hops` hops in a row that gain nothing,
// or `contest_most_hops` in all. Through air the local searches end on many optima of their own
// (from 910 to 970 m for issue 63's contest), each a little below the next: the hops climb them.
void hop_from_best(Search& s, Found& found) {
  const std::size_t n = point_size(s.request);
  const Sobol sequence = sobol_sequence(n);
  double u[5] = {};
  gsl_qrng_get(sequence.get(), u);  // the first point, a corner of the cube
  SearchPoint centre = point_of(s.best->engine);
  for (int hop = 0, fruitless = 0; hop < contest_most_hops && fruitless < contest_fruitless_hops; ++hop) {
    gsl_qrng_get(sequence.get(), u);
    SearchPoint x = centre;
    for (std::size_t i = 0; i < n; ++i) x[i] += contest_hop * (2 * u[i] - 1);
    const double before = s.best->objective;
    const std::optional<ContestEngine> end = s.coarse(x, 0.05);
    ++found.hops;
    if (!end || !(end->objective > before)) {
      ++fruitless;
      continue;
    }
    fruitless = end->objective > before * (1 + binding_gain) ? 0 : fruitless + 1;  // a gain within the search's resolution bears no fruit
    ++found.hops_gained;
    found.start_objectives.push_back(s.refine(*end));
    centre = point_of(s.best_of_start->engine);
    found.ends.insert(found.ends.begin(), centre);
  }
}

// The best engine of a request: coarse local searches from `warm` and the starts `reach` adds,
// then the best of their ends refined; with `until_feasible`, the first engine found that meets
// the limits.
Found search_once(const ContestRequest& r, Shots& shots, const std::vector<SearchPoint>& warm, Reach reach, bool until_feasible, bool see_slack) {
  Search s{r, shots};
  s.until_feasible = until_feasible;
  s.see_slack = see_slack;
  const std::vector<SearchPoint> starts = reach == Reach::warm_only ? warm
                                                                    : starts_of(s, warm, reach == Reach::whole ? contest_local_searches - 1 : 2);
  Found found;
  std::vector<std::optional<ContestEngine>> ends;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    if (until_feasible && s.best) break;
    ends.push_back(s.coarse(starts[k], k < warm.size() ? 0.05 : 0.25));  // a warm start: an optimum of nearby limits
    found.start_objectives.push_back(ends.back() ? std::optional<double>(ends.back()->objective) : std::nullopt);
  }
  found.local_searches = static_cast<int>(ends.size());
  if (!until_feasible && s.best) {
    std::vector<std::size_t> order(ends.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    const auto objective = [&](std::size_t k) { return ends[k] ? ends[k]->objective : -1e300; };
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return objective(a) > objective(b); });
    const double best_end = s.best->objective;
    std::size_t refined = 0;
    for (std::size_t k : order)
      if (ends[k]) {
        if (ends[k]->objective >= 0.99 * best_end && (reach == Reach::whole || refined < 2))
          found.start_objectives[k] = s.refine(*ends[k]), ends[k] = s.best_of_start, ++refined;
        found.ends.push_back(point_of(ends[k]->engine));
      }
    if (reach != Reach::warm_only && searches_at_best(found.start_objectives, s.best->objective, found.start_objectives.size()) < 2)
      hop_from_best(s, found);
  }
  found.best = s.best;
  found.last_failure = s.last_failure;
  found.any_engine = s.any_engine;
  return found;
}

// The searches of `search_once`, COBYLA seeing how far a slack engine goes slack; where they find
// no engine within the limits, again with a slack engine none (a cliff). Seen as a limit, the
// sling's slack, which can jump where a sharp dip of its pull falls between the samples, can hold
// COBYLA short of the limits: the efficiency's contest of the floating arm under 10 m/s² found
// no engine so, and eps 0.688 again.
Found search(const ContestRequest& r, Shots& shots, const std::vector<SearchPoint>& warm, Reach reach = Reach::whole, bool until_feasible = false) {
  Found found = search_once(r, shots, warm, reach, until_feasible, true);
  if (found.best || reach == Reach::warm_only) return found;
  Found again = search_once(r, shots, warm, reach, until_feasible, false);
  again.any_engine = again.any_engine || found.any_engine;
  return again;
}

// The fewest of the request's limits that no search meets together; the whole set without a
// search when `whole_fails` says it is already known to fail.
std::vector<ContestLimit> fewest_conflicting(const ContestRequest& request, Shots& shots, bool whole_fails) {
  std::vector<ContestLimit> given;
  for (int k = 0; k < contest_limit_count; ++k)
    if (request.limits[k]) given.push_back(static_cast<ContestLimit>(k));
  // The subsets by size, the smallest first: the first that no search meets.
  for (std::size_t size = 1; size <= given.size(); ++size) {
    if (size == given.size() && whole_fails) return given;
    for (unsigned mask = 0; mask < (1u << given.size()); ++mask) {
      if (static_cast<std::size_t>(__builtin_popcount(mask)) != size) continue;
      ContestRequest some = request;
      some.limits = {};
      some.min_clearance = 0;  // a clearance no engine meets within the limits is named by best_engine
      std::vector<ContestLimit> chosen;
      for (std::size_t i = 0; i < given.size(); ++i)
        if (mask & (1u << i)) some.limits[given[i]] = request.limits[given[i]], chosen.push_back(given[i]);
      if (!search(some, shots, {}, Reach::whole, true).best) return chosen;
    }
  }
  return {};
}

void check_request(const ContestRequest& r) {
  if (r.machine == MachineKind::whipper) throw Error(ErrorKind::usage, whipper_not_designed);
  if (!(r.projectile_mass > 0 && r.projectile_mass < 1e12))
    throw Error(ErrorKind::bad_number, "{{m}} = " + format_significant(r.projectile_mass, 6) + ": the contest's projectile mass must be positive");
  if (!(r.beam_mass_per_length >= 0 && r.beam_mass_per_length < 1e9))
    throw Error(
        ErrorKind::bad_number,
        "the beam's mass per metre, " + format_significant(r.beam_mass_per_length, 6) + " kg/m, must be 0 or more; give {{mb_per_m}} or {{D}}");
  check_limits_to_meet({r.limits, r.min_clearance});
  if (r.box_width.has_value() != r.box_height.has_value())
    throw Error(ErrorKind::usage, "a box counterweight needs both {{box_width}} and {{box_height}}");
  for (const auto& side : {r.box_width, r.box_height})
    if (side && !(*side > 0 && *side < 1e6)) throw Error(ErrorKind::bad_number, "a side of the counterweight's box must be positive");
  check_shot_settings(r.settings);
  // The sling's parts and the ball's size, where given, as the shot checks them: on the paper's
  // proportions with the heaviest counterweight the search may choose, its limit or its bound
  // (a pouch may not outweigh it).
  if (r.rope_mass != 0 || r.pouch_mass != 0 || r.pin_friction != 0 || r.projectile_diameter) {
    Engine probe = engine_at(r, paper_start(r, 1e300));
    probe.M = r.limits[mass_limit] ? *r.limits[mass_limit] : r.projectile_mass / unlimited_least_mu;  // the search's bound
    check_engine(probe);
    settings_for(probe, r.settings);  // a size beside a density, or with no air to act in
  }
}

}  // namespace

namespace {

// The best engine of a checked request, without what relaxing its limits would gain.
ContestEngine best_engine(const ContestRequest& request, Shots& shots, std::vector<SearchPoint>* ends = nullptr) {
  const Found found = search(request, shots, {});
  if (ends) *ends = found.ends;
  if (!found.best) {
    // A clearance asked for that no engine meets, where the limits alone can be met, is named itself.
    if (request.min_clearance > 0) {
      ContestRequest without = request;
      without.min_clearance = 0;
      if (search(without, shots, {}, Reach::whole, true).best)
        throw Error(ErrorKind::out_of_range,
                    "no engine found keeps its counterweight {{min_clearance}} = " + format_significant(request.min_clearance, 4) +
                        " m above the ground within the other limits; ask for less clearance, or loosen the box's height");
    }
    // No engine shot at all is no conflict of limits: the engines themselves fail.
    const std::vector<ContestLimit> conflict = found.any_engine ? fewest_conflicting(request, shots, true) : std::vector<ContestLimit>{};
    if (conflict.empty())
      throw Error(ErrorKind::out_of_range,
                  "no engine the search tried could be built and shot" +
                      (found.last_failure.empty() ? std::string() : " (the last: " + found.last_failure + ")") +
                      "; give a projectile, beam and angle of ordinary size, or limits that allow one");
    std::string names;
    for (ContestLimit k : conflict) names += (names.empty() ? "" : " and ") + std::string("{{") + contest_limit_key(k) + "}}";
    throw Error(ErrorKind::out_of_range,
                "no engine found meets " + names +
                    (conflict.size() > 1 ? " together, though it meets any fewer of them; loosen one of them" : "; loosen it"));
  }
  ContestEngine best = *found.best;
  best.start_objectives = found.start_objectives;
  best.local_searches = found.local_searches, best.hops = found.hops, best.hops_gained = found.hops_gained;
  best.shots = shots.count();
  return best;
}

// What relaxing one limit (or the clearance) of `relaxed` gains over `best`: a search under the
// looser limits from where the contest's own local searches ended, `best` first (it meets them
// too, so the gain is never negative), and from the starts of its own that reach near.
double gain_over(const ContestEngine& best, const ContestRequest& relaxed, Shots& shots, const std::vector<SearchPoint>& ends) {
  const Found more = search(relaxed, shots, ends, Reach::near);
  return more.best ? std::max(0.0, more.best->objective - best.objective) : 0;
}

// Each limit given: what it costs, found by searching again with it 10 % looser. It binds where
// that gains (more than 1e-5 of the objective, above the search's resolution): a limit the
// engine only touches gains nothing, and one it stands short of may still gain, where the looser
// limit lets another engine past this one.
void add_gains(ContestEngine& best, const ContestRequest& request, Shots& shots, const std::vector<SearchPoint>& ends) {
  const auto binds = [&](double gain) { return gain > binding_gain * best.objective; };
  for (int k = 0; k < contest_limit_count; ++k) {
    if (!request.limits[k]) continue;
    ContestRequest relaxed = request;
    relaxed.limits[k] = *request.limits[k] * 1.1;
    best.at_limit[k] = std::abs(best.measured[k] / *request.limits[k] - 1) <= at_limit_tolerance;
    best.gain_if_relaxed[k] = gain_over(best, relaxed, shots, ends);
    best.binds[k] = binds(*best.gain_if_relaxed[k]);
  }
  const double height = pivot_height(best.engine);
  best.clearance_at_limit = best.clearance - request.min_clearance <= at_limit_tolerance * height;
  if (request.min_clearance > 0) {  // the ground itself is no limit to relax
    ContestRequest relaxed = request;
    relaxed.min_clearance = request.min_clearance * 0.9;
    best.gain_if_clearance_relaxed = gain_over(best, relaxed, shots, ends);
  }
}

// The best engine shot so far, by any search, that meets the request's limits.
std::optional<ContestEngine> best_shot(const Shots& shots, const ContestRequest& request) {
  std::optional<ContestEngine> best;
  for (const auto& [point, outcome] : shots.outcomes())
    if (outcome.usable() && meets_limits(*outcome.engine, request) && (!best || outcome.engine->objective > best->objective)) best = outcome.engine;
  return best;
}

// A pin bent to the best engine's pin to bend lets go where the pin angle first reaches it, a shot
// given that pin: where that is not the engine's release, a note says no pin makes it.
void note_pin(ContestEngine& best, const ContestRequest& request) {
  ShotSettings at = request.settings;
  at.loads = false;
  at.release_at = SetRelease{ReleaseBy::pin_angle, best.verification.pin_to_bend_deg};
  PinShot pin{best.verification.pin_to_bend_deg, std::nullopt, std::nullopt, ""};
  try {
    pin.R = verify_engine(best.engine, at).capacity.R;
  } catch (const Error& e) {
    pin.refused = e.what();
  }
  if (const std::optional<std::string> note = pin_release_note(best.verification, pin)) {
    best.verification.notes.push_back(*note);
    best.pin_releases = false;
  }
}

// Where the best stands at a bound of the search rather than at a limit (the counterweight at 1e5
// times the ball without a --max-M, the arms' ratios, L2's 1 mm to 1 km), a note says so: a
// heavier or longer engine beyond it may throw farther, and only a limit given bounds it.
void note_bounds(ContestEngine& best, const ContestRequest& request) {
  const auto [low, high] = bounds_of(request);
  const SearchPoint x = point_of(best.engine);
  const char* names[] = {"L1/L2", "L4/L1", "m/M", "L2", "L3/L2"};
  std::vector<std::string> at;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (i == 2 && x[i] <= low[i] + 1e-6 && !request.limits[mass_limit])  // M at its limit is the limit's, not the search's
      at.push_back(
          "M = " + (best.engine.M >= 1000 ? format_significant(best.engine.M / 1000, 3) + " t" : format_significant(best.engine.M, 3) + " kg") +
          ", 1e5 times the ball's mass, with no limit on the counterweight given");
    else if (i != 2 && x[i] <= low[i] + 1e-6)
      at.push_back(std::string(names[i]) + " = " + format_significant(std::exp(low[i]), 3) + (i == 3 ? " m" : ""));
    if (x[i] >= high[i] - 1e-6) at.push_back(std::string(names[i]) + " = " + format_significant(std::exp(high[i]), 3) + (i == 3 ? " m" : ""));
  }
  if (!at.empty())
    best.verification.notes.push_back("the search stopped at its own bound (" + join(at, "; ") + "): an engine beyond it may throw farther");
}

// The beam's strength is no limit of the contest: where the best engine's beam breaks in its shot,
// a note says so (the report's beam line alone did: a fresh builder's test).
void note_beam(ContestEngine& best) {
  const std::optional<BeamStrength>& beam = best.verification.beam;
  if (beam && beam->margin < 1)
    best.verification.notes.push_back("this engine's beam breaks in the shot (margin " + format_significant(beam->margin, 3) +
                                      " < 1): the contest limits no beam's stress; give a thicker beam (a larger mass per metre, or D)");
}

// The contest's best over `shots`, which may hold other searches' (the Pareto front's): a shot
// among them that meets every limit and throws farther is adopted as a gain's is.
ContestEngine optimum_from(const ContestRequest& request, Shots& shots) {
  std::vector<SearchPoint> ends;
  ContestEngine best = best_engine(request, shots, &ends);
  // A gain's search may shoot an engine that meets every limit as given and throws farther than
  // the best (the contest's own searches missed it; its limit then only seemed to bind): that
  // engine, refined under the limits as given, is the best, a local search of its own, and the
  // gains are searched again from it; at most twice.
  for (int round = 0; request.gains; ++round) {
    add_gains(best, request, shots, ends);
    if (round == 2) break;
    const std::optional<ContestEngine> missed = best_shot(shots, request);
    if (!missed || !(missed->objective > best.objective * (1 + binding_gain))) break;
    Search s{request, shots};
    s.best = missed;
    s.refine(*missed);
    const ContestEngine before = best;  // how the search went, which the adopted engine's shot does not carry
    best = *s.best;
    best.start_objectives = before.start_objectives;
    best.start_objectives.push_back(best.objective);
    best.local_searches = before.local_searches, best.hops = before.hops, best.hops_gained = before.hops_gained;
    ends.insert(ends.begin(), point_of(best.engine));
  }
  best.shots = shots.count();
  note_pin(best, request);
  note_bounds(best, request);
  note_beam(best);
  return best;
}

// The Pareto front's searches over `shots`: every engine found, from the largest load down, each
// search warm from the last optimum; `loads` the axle's limits searched, from the largest down.
// The front starts from `given` where there is one, else from the best without the axle's limit.
std::vector<ContestEngine> front_searches(const ContestRequest& request, int points, Shots& shots, std::vector<double>& loads,
                                          const ContestEngine* given = nullptr) {
  ContestRequest free = request;
  free.limits[axle_limit].reset();
  const ContestEngine top = given ? *given : best_engine(free, shots);
  const double most = request.limits[axle_limit] ? std::min(*request.limits[axle_limit], top.measured[axle_limit]) : top.measured[axle_limit];
  std::vector<ContestEngine> found{top};
  SearchPoint warm = point_of(top.engine);
  for (int k = points - 1; k >= 0; --k) {
    ContestRequest limited = request;
    limited.limits[axle_limit] = most * (0.2 + 0.8 * k / (points - 1));
    loads.push_back(*limited.limits[axle_limit]);
    Found search_found = search(limited, shots, {warm}, Reach::warm_only);
    if (!search_found.best) search_found = search(limited, shots, {});  // the warm start could not reach this load
    if (!search_found.best) continue;
    search_found.best->shots = shots.count();
    found.push_back(*search_found.best);
    warm = point_of(search_found.best->engine);
  }
  return found;
}

// The front's point at each load: the best of every engine found within it (a search that
// stopped short is bettered by one that went farther at a smaller load), by rising load.
std::vector<ContestEngine> front_of(const std::vector<ContestEngine>& found, const std::vector<double>& loads) {
  std::vector<ContestEngine> front;
  for (auto load = loads.rbegin(); load != loads.rend(); ++load) {
    const ContestEngine* best = nullptr;
    for (const ContestEngine& c : found)
      if (c.measured[axle_limit] <= *load && (!best || c.objective > best->objective)) best = &c;
    if (best && (front.empty() || best->objective > front.back().objective)) front.push_back(*best);
  }
  return front;
}

void check_points(int points) {
  if (!(points >= 2 && points <= 200)) throw Error(ErrorKind::bad_number, "{{points}} = " + std::to_string(points) + ": give 2 to 200 points");
}

}  // namespace

ContestEngine contest_optimum(const ContestRequest& request) {
  check_request(request);
  Shots shots(request);
  return optimum_from(request, shots);
}

ContestResult contest_with_front(const ContestRequest& request, int points) {
  check_request(request);
  if (points == 0) return {contest_optimum(request), {}};
  check_points(points);
  Shots shots(request);
  std::vector<double> loads;
  std::vector<ContestEngine> found = front_searches(request, points, shots, loads);
  ContestResult out{optimum_from(request, shots), {}};
  if (out.best.objective > found.front().objective) {  // the front began below the best: again, from it
    loads.clear();
    const std::vector<ContestEngine> again = front_searches(request, points, shots, loads, &out.best);
    found.insert(found.end(), again.begin(), again.end());
    out.best = optimum_from(request, shots);  // which adopts what those searches shot, the shots shared
  }
  out.best.shots = shots.count();  // the front's searches' too
  found.push_back(out.best);
  out.front = front_of(found, loads);
  return out;
}

std::vector<MachineBest> contest_each_machine(ContestRequest request) {
  std::vector<MachineBest> each;
  for (const MachineKind machine : searched_machines) {
    request.machine = machine;
    try {
      each.push_back({machine, contest_optimum(request), std::nullopt});
    } catch (const Error& e) {
      each.push_back({machine, std::nullopt, e});
    }
  }
  return each;
}

void check_limits_to_meet(const LimitsToMeet& to_meet) {
  for (int k = 0; k < contest_limit_count; ++k)
    if (const auto& limit = to_meet.limits[k]; limit && !(*limit > 0 && std::isfinite(*limit)))
      throw Error(ErrorKind::bad_number,
                  "{{" + std::string(contest_limit_key(static_cast<ContestLimit>(k))) + "}} = " + format_significant(*limit, 6) +
                      ": a limit must be positive");
  if (!(to_meet.min_clearance >= 0 && to_meet.min_clearance < 1e6))
    throw Error(ErrorKind::bad_number,
                "{{min_clearance}} = " + format_significant(to_meet.min_clearance, 6) + " m: give a clearance from 0 to 1e6 m (e.g. 10cm)");
}

std::vector<ContestLimit> conflicting_limits(const ContestRequest& request) {
  Shots shots(request);
  return fewest_conflicting(request, shots, false);
}

std::vector<ContestEngine> pareto_front(const ContestRequest& request, int points) {
  check_request(request);
  check_points(points);
  Shots shots(request);
  std::vector<double> loads;
  return front_of(front_searches(request, points, shots, loads), loads);
}

}  // namespace trebuchet
