#include "trebuchet/contest.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "simplex.hpp"
#include "solve_1d.hpp"
#include "trebuchet/angles.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/machine.hpp"

namespace trebuchet {
namespace {

// A candidate: L1/L2, L4/L1, m/M, L2 [m] and, for the hinged machine, L3/L2.
struct Shape {
  double l = 4, l4 = 0.9, mu = 0.02, L2 = 1, L = 0.8;
};

Engine engine_of_shape(const ContestRequest& r, const Shape& s) {
  Engine e;
  e.machine = r.machine;
  e.theta_i_deg = r.theta_i_deg;
  e.material = r.material;
  e.L2 = s.L2;
  e.L1 = s.l * s.L2;
  e.L3 = r.machine == MachineKind::hinged ? s.L * s.L2 : 0;  // the others' counterweight at the short arm's end
  e.L4 = s.l4 * e.L1;
  e.m = r.projectile_mass;
  e.M = r.projectile_mass / s.mu;
  e.mb = r.beam_mass_per_length * (e.L1 + e.L2);
  if (r.box_width && r.box_height) give_box(e, *r.box_width, *r.box_height);
  return e;
}

// The counterweight's clearance above the ground [m]: the smaller of the geometry's and the shot's.
double clearance_of(const Verification& v) { return std::min(v.clearance.geometric, v.clearance.in_shot.value_or(v.clearance.geometric)); }

// How far the measures lie beyond the limits given, each as a fraction of its limit; 0 when they meet them all.
double violation(const std::array<double, contest_limit_count>& measured, const ContestLimits& limits) {
  double sum = 0;
  for (int k = 0; k < contest_limit_count; ++k)
    if (limits[k]) sum += std::max(0.0, measured[k] / *limits[k] - 1 - 1e-12);  // M = m/(m/M) may round a part in 1e16 above its limit
  return sum;
}

struct Search {
  const ContestRequest* request = nullptr;
  double mu_least = 0;  // m over the largest counterweight: M at its limit where the search would pass it
  bool hinged = false;
  int shots = 0;
  std::optional<ContestEngine> best;  // the best that meets the limits
  std::string last_failure;  // why the last candidate that could not be shot failed
  bool until_feasible = false;  // whether any engine meets the limits is all that is asked

  Shape shape_of(const std::vector<double>& x) const {
    Shape s{std::exp(x[0]), std::exp(x[1]), std::max(std::exp(x[2]), mu_least), std::exp(x[3]), 0};
    if (hinged) s.L = std::exp(x[4]);
    return s;
  }
  std::vector<double> point_of(const Shape& s) const {
    std::vector<double> x{std::log(s.l), std::log(s.l4), std::log(s.mu), std::log(s.L2)};
    if (hinged) x.push_back(std::log(s.L));
    return x;
  }

  // Minus the objective of a candidate that meets the limits; how far it misses them otherwise
  // (above every one that meets them); a candidate that cannot be built or shot, more still.
  double cost(const Shape& s) {
    if (until_feasible && best) return -1e300;  // answered: the simplex, all alike, shrinks to its end
    ++shots;
    if (!(s.l > 1.05 && s.l < 60 && s.l4 > 0.05 && s.l4 < 20 && s.mu < 1 && s.L2 > 1e-3 && s.L2 < 1e3 && s.L < 20)) return 1e6;
    try {
      ContestEngine c;
      c.engine = engine_of_shape(*request, s);
      c.measured = contest_measures(c.engine, request->settings, &c.verification);
      c.objective = request->efficiency ? c.verification.eps : c.verification.capacity.R;
      // The model stops holding before the release: no engine. A counterweight that strikes the
      // ground (one warning more) misses the clearance below, by how much.
      if (c.verification.warnings.size() > (c.verification.clearance.buildable() ? 0u : 1u)) {
        last_failure = c.verification.warnings.front();
        return 1e5;
      }
      c.clearance = clearance_of(c.verification);
      // A clearance short of the one asked for misses by its shortfall over the engine's height.
      const double missed = violation(c.measured, request->limits) +
          std::max(0.0, (request->min_clearance - c.clearance) / pivot_height(c.engine) - 1e-12);
      c.feasible = missed == 0;
      if (!c.feasible) return missed;
      if (!best || c.objective > best->objective) best = c;
      return -c.objective;
    } catch (const Error& e) {
      last_failure = e.named_message();
      return 1e6;
    }
  }

  // The size scales the range and the box, not the shape's accelerations: the best shape is
  // grown (or shrunk) to the largest size that meets the limits, by bisection in log L2.
  void push_size() {
    if (!best) return;
    Shape s;
    s.l = best->engine.L1 / best->engine.L2, s.l4 = best->engine.L4 / best->engine.L1, s.mu = best->engine.m / best->engine.M;
    s.L2 = best->engine.L2, s.L = best->engine.L3 / best->engine.L2;
    const double start = s.L2;
    double low = 0, high = 0;  // log of the factor: feasible at low, not at high
    bool bracketed = false;
    for (int k = 1; k <= 40 && !bracketed; ++k) {
      Shape grown = s;
      grown.L2 = start * std::exp(0.05 * k);
      const double before = best->objective;
      if (cost(grown) > 0)
        bracketed = true, high = 0.05 * k;
      else if (!(best->objective > before))
        return;  // a larger engine does no better: the size does not bind
      else
        low = 0.05 * k;
    }
    if (!bracketed) return;
    for (int k = 0; k < 40 && high - low > 1e-10; ++k) {
      const double middle = (low + high) / 2;
      Shape trial = s;
      trial.L2 = start * std::exp(middle);
      (cost(trial) > 0 ? high : low) = middle;
    }
  }
};

Shape shape_of_engine(const Engine& e) {
  Shape s;
  s.l = e.L1 / e.L2, s.l4 = e.L4 / e.L1, s.mu = e.m / e.M, s.L2 = e.L2, s.L = e.L3 > 0 ? e.L3 / e.L2 : 0.8;
  return s;
}

Search search_from(const ContestRequest& r, const Shape& start, bool until_feasible = false) {
  Search search;
  search.request = &r;
  search.until_feasible = until_feasible;
  search.hinged = r.machine == MachineKind::hinged;
  if (r.limits[mass_limit]) search.mu_least = r.projectile_mass / *r.limits[mass_limit];
  Shape first = start;
  first.mu = std::max(first.mu, search.mu_least);
  const auto cost = [&](const std::vector<double>& x) { return search.cost(search.shape_of(x)); };
  minimize_simplex(cost, search.point_of(first), 0.25, 1e-5, 500);
  if (until_feasible) return search;
  search.push_size();
  // The simplex, shrunk against a limit it presses on, stops a few parts in 1e4 short of it. A
  // second, small simplex from the best, then the size pushed again, meets an active limit to
  // 1e-4 (contest_binds).
  if (search.best) {
    minimize_simplex(cost, search.point_of(shape_of_engine(search.best->engine)), 0.02, 1e-8, 300);
    search.push_size();
  }
  return search;
}

// The starting shapes: the paper's proportions, and a shorter beam with a longer sling, each at
// a size within the box when one is given.
std::vector<Shape> starts_of(const ContestRequest& r) {
  std::vector<Shape> starts{Shape{}, Shape{3, 1.2, 0.02, 1, 1}};
  const double box = std::min(r.limits[width_limit].value_or(1e300), r.limits[height_limit].value_or(1e300));
  for (Shape& s : starts) s.L2 = box < 1e300 ? 0.15 * box / s.l : 1;
  return starts;
}

// The better of two searches: one that meets the limits, then the larger objective.
Search better(Search a, Search b) {
  b.shots += a.shots, a.shots = b.shots;
  if (!a.best) return b;
  if (!b.best) return a;
  return b.best->objective > a.best->objective ? b : a;
}

// The best of the searches from each start, and from `warm` first when given; with
// `until_feasible`, the first engine found that meets the limits.
Search search_all(const ContestRequest& r, const std::optional<Shape>& warm = std::nullopt, bool until_feasible = false) {
  Search found;
  found.request = &r;
  if (warm) found = search_from(r, *warm, until_feasible);
  for (const Shape& start : starts_of(r)) {
    if (until_feasible && found.best) break;
    found = better(found, search_from(r, start, until_feasible));
  }
  return found;
}

// The fewest of the request's limits that no search meets together; the whole set without a
// search when `whole_fails` says it is already known to fail.
std::vector<ContestLimit> fewest_conflicting(const ContestRequest& request, bool whole_fails) {
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
      std::vector<ContestLimit> chosen;
      for (std::size_t i = 0; i < given.size(); ++i)
        if (mask & (1u << i)) some.limits[given[i]] = request.limits[given[i]], chosen.push_back(given[i]);
      if (!search_all(some, std::nullopt, true).best) return chosen;
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
  for (int k = 0; k < contest_limit_count; ++k)
    if (r.limits[k] && !(*r.limits[k] > 0 && std::isfinite(*r.limits[k])))
      throw Error(ErrorKind::bad_number,
                  "{{" + std::string(contest_limit_key(static_cast<ContestLimit>(k))) + "}} = " + format_significant(*r.limits[k], 6) +
                      ": a limit must be positive");
  if (!(r.min_clearance >= 0 && r.min_clearance < 1e6))
    throw Error(ErrorKind::bad_number,
                "{{min_clearance}} = " + format_significant(r.min_clearance, 6) + " m: give a clearance from 0 to 1e6 m (e.g. 10cm)");
  if (r.box_width.has_value() != r.box_height.has_value())
    throw Error(ErrorKind::usage, "a box counterweight needs both {{box_width}} and {{box_height}}");
  for (const auto& side : {r.box_width, r.box_height})
    if (side && !(*side > 0 && *side < 1e6)) throw Error(ErrorKind::bad_number, "a side of the counterweight's box must be positive");
  check_shot_settings(r.settings);
}

// The largest of sign f over samples of a smooth f at increasing times t: the best sample, or
// where it has a neighbour on each side, the vertex of the parabola through the three.
double sampled_extreme(const std::vector<double>& t, const std::vector<double>& f, double sign) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < f.size(); ++i)
    if (sign * f[i] > sign * f[best]) best = i;
  if (best == 0 || best + 1 == f.size()) return sign * f[best];
  return parabola_vertex({t[best - 1], sign * f[best - 1]}, {t[best], sign * f[best]}, {t[best + 1], sign * f[best + 1]}).f;
}

}  // namespace

const char* contest_limit_key(ContestLimit limit) {
  static const char* const keys[contest_limit_count] = {"max_width", "max_height", "max_M", "max_axle_load", "max_acceleration"};
  return keys[limit];
}

std::array<double, contest_limit_count> contest_measures(const Engine& engine, const ShotSettings& given, Verification* verification) {
  check_engine(engine);
  ShotSettings settings = given;
  settings.loads = true;
  const ScaledDesign d = shot_design(engine, settings);
  std::vector<TracePoint> trace;
  const ShotResult shot = simulate_shot(d, release_criterion(engine, settings), settings.integrator, &trace, 0.02, nullptr, true);
  const Verification v = verification_of(engine, shot, settings.target_level, settings.air, settings.range_from_release);
  // Heights above the base, which the box stands on; x along the ground. Each body's coordinate
  // is sampled every 0.02 (scaled time) up to the release; its extreme lies between the samples
  // beside the best one, where the parabola through the three finds it to O(0.02^3) (the best
  // sample alone fell short by up to 3e-4 of the box).
  const double base = d.pivot_height();
  std::vector<double> times;
  // x and y of the pivot, the hinge, the counterweight's box (two opposite corners, upright; its
  // centre without a box), the tip and the projectile
  std::array<std::vector<double>, 12> coordinates;
  const Vec2 half_box{engine.parts.box_width.value_or(0) / 2 / engine.L2, engine.parts.box_height.value_or(0) / 2 / engine.L2};  // scaled
  double acceleration = 0;
  for (const TracePoint& p : trace) {
    if (p.phase == Phase::released) continue;
    if (!times.empty() && !(p.t > times.back())) continue;  // a phase's end, sampled twice
    const Snapshot& s = p.snapshot;
    times.push_back(p.t);
    int k = 0;
    const Vec2 low_corner{s.counterweight.x - half_box.x, s.counterweight.y - half_box.y},
        high_corner{s.counterweight.x + half_box.x, s.counterweight.y + half_box.y};
    for (const Vec2& at : {s.pivot, s.hinge, low_corner, high_corner, s.tip, s.projectile})
      coordinates[k++].push_back(at.x), coordinates[k++].push_back(at.y + base);
    // The sling's pull (the tip feels its opposite), the trough's push and the weight, over the projectile's mass.
    acceleration = std::max(acceleration, std::hypot(-s.sling_on_tip.x, -s.sling_on_tip.y + s.normal_force - d.mu) / d.mu);
  }
  double x_low = 1e300, x_high = -1e300, y_low = 0, y_high = base;
  for (int k = 0; k < 12; ++k) {
    const double high = sampled_extreme(times, coordinates[k], 1), low = -sampled_extreme(times, coordinates[k], -1);
    if (k % 2 == 0)
      x_low = std::min(x_low, low), x_high = std::max(x_high, high);
    else
      y_low = std::min(y_low, low), y_high = std::max(y_high, high);
  }
  if (verification) *verification = v;
  return {(x_high - x_low) * engine.L2, (y_high - y_low) * engine.L2, engine.M, v.loads[pivot_load].value, acceleration * engine.material.g};
}

bool contest_binds(const ContestEngine& engine, const ContestRequest& request, ContestLimit limit) {
  const auto& given = request.limits[limit];
  return given && std::abs(engine.measured[limit] / *given - 1) <= 1e-4;
}

namespace {

// The best engine of a checked request, without what relaxing its limits would gain.
ContestEngine best_engine(const ContestRequest& request) {
  const Search search = search_all(request);
  if (!search.best) {
    // A clearance asked for that no engine meets, where the limits alone can be met, is named itself.
    if (request.min_clearance > 0) {
      ContestRequest without = request;
      without.min_clearance = 0;
      if (search_all(without, std::nullopt, true).best)
        throw Error(ErrorKind::out_of_range,
                    "no engine found keeps its counterweight {{min_clearance}} = " + format_significant(request.min_clearance, 4) +
                        " m above the ground within the other limits; ask for less clearance, or loosen the box's height");
    }
    const std::vector<ContestLimit> conflict = fewest_conflicting(request, true);
    if (conflict.empty())
      throw Error(ErrorKind::out_of_range,
                  "no engine the search tried could be built and shot" +
                      (search.last_failure.empty() ? std::string() : " (the last: " + search.last_failure + ")") +
                      "; give a projectile, beam and angle of ordinary size, or limits that allow one");
    std::string names;
    for (ContestLimit k : conflict) names += (names.empty() ? "" : " and ") + std::string("{{") + contest_limit_key(k) + "}}";
    throw Error(ErrorKind::out_of_range,
                "no engine found meets " + names +
                    (conflict.size() > 1 ? " together, though it meets any fewer of them; loosen one of them" : "; loosen it"));
  }
  ContestEngine best = *search.best;
  best.shots = search.shots;
  return best;
}

}  // namespace

ContestEngine contest_optimum(const ContestRequest& request) {
  check_request(request);
  ContestEngine best = best_engine(request);
  // What each binding limit costs: the search again, from the best engine, with it 10 % looser.
  for (int k = 0; k < contest_limit_count; ++k) {
    const auto limit = static_cast<ContestLimit>(k);
    if (!contest_binds(best, request, limit)) continue;
    ContestRequest relaxed = request;
    relaxed.limits[k] = *request.limits[k] * 1.1;
    const Search more = search_from(relaxed, shape_of_engine(best.engine));
    best.shots += more.shots;
    if (more.best) best.gain_if_relaxed[k] = std::max(0.0, more.best->objective - best.objective);
  }
  return best;
}

std::vector<ContestLimit> conflicting_limits(const ContestRequest& request) { return fewest_conflicting(request, false); }

std::vector<ContestEngine> pareto_front(const ContestRequest& request, int points) {
  check_request(request);
  if (!(points >= 2 && points <= 200)) throw Error(ErrorKind::bad_number, "{{points}} = " + std::to_string(points) + ": give 2 to 200 points");
  ContestRequest free = request;
  free.limits[axle_limit].reset();
  const ContestEngine top = best_engine(free);
  const double most = request.limits[axle_limit] ? std::min(*request.limits[axle_limit], top.measured[axle_limit]) : top.measured[axle_limit];
  // Every engine found, from the largest load down, each search warm from the last optimum: the
  // front's point at a load is the best of them all within it (a search that stopped short is
  // bettered by one that went farther at a smaller load).
  std::vector<ContestEngine> found{top};
  std::optional<Shape> warm = shape_of_engine(top.engine);
  std::vector<double> loads;
  for (int k = points - 1; k >= 0; --k) {
    ContestRequest limited = request;
    limited.limits[axle_limit] = most * (0.2 + 0.8 * k / (points - 1));
    loads.push_back(*limited.limits[axle_limit]);
    Search search = search_from(limited, *warm);
    if (!search.best) search = search_all(limited);  // the warm start could not reach this load
    if (!search.best) continue;
    search.best->shots = search.shots;
    found.push_back(*search.best);
    warm = shape_of_engine(search.best->engine);
  }
  std::vector<ContestEngine> front;
  for (auto load = loads.rbegin(); load != loads.rend(); ++load) {
    const ContestEngine* best = nullptr;
    for (const ContestEngine& c : found)
      if (c.measured[axle_limit] <= *load && (!best || c.objective > best->objective)) best = &c;
    if (best && (front.empty() || best->objective > front.back().objective)) front.push_back(*best);
  }
  return front;
}

}  // namespace trebuchet
