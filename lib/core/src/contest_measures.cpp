// What a contest's limits measure on an engine (contest.hpp): its bounding box, counterweight,
// axle load and peak acceleration from one shot, and the limits an engine breaks. Apart from the
// contest's search, which the page's build leaves out: compare measures a column here too.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "lowest_clearance.hpp"
#include "solve_1d.hpp"
#include "trebuchet/contest.hpp"
#include "trebuchet/machine.hpp"

namespace trebuchet {
namespace {

// The largest of sign f over samples of a smooth f at increasing times t: the best sample, or
// where it has a neighbour on each side, the vertex of the parabola through the three.
double sampled_extreme(const std::vector<double>& t, const std::vector<double>& f, double sign) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < f.size(); ++i)
    if (sign * f[i] > sign * f[best]) best = i;
  if (best == 0 || best + 1 == f.size()) return sign * f[best];
  return parabola_vertex({t[best - 1], sign * f[best - 1]}, {t[best], sign * f[best]}, {t[best + 1], sign * f[best + 1]}).f;
}

// The projectile's peak acceleration up to the release [m/s2]: the samples' (each at most 0.02
// (L2/g)^(1/2) apart), and no less than the sling's refined peak pull allows. A ball (and its
// pouch) pulled by T and its weight alone accelerates by at least T/(m + pouch) - g: in the trough
// too, which holds it level against less than its weight. A sharp peak of the pull between the
// samples, where the sling goes slack at the release, read 5283 m/s2 beside a pull of 9.5e6 m g (a
// fresh builder's test). Not bounded so: a rope of mass, whose tension at the tip is the load, and
// air acting in the sling.
double peak_acceleration(const Engine& engine, const ShotSettings& settings, const Verification& v, const std::vector<double>& times,
                         const std::vector<double>& accelerations) {
  const double g = engine.material.g, sampled = sampled_extreme(times, accelerations, 1) * g;
  if (engine.parts.rope_mass > 0 || settings.drag_in_sling) return sampled;
  return std::max(sampled, v.loads[sling_tension_load].value / (engine.m + engine.parts.pouch_mass) - g);
}

}  // namespace

const char* contest_limit_key(ContestLimit limit) {
  static const char* const keys[contest_limit_count] = {"max_width", "max_height", "max_M", "max_axle_load", "max_acceleration"};
  return keys[limit];
}

std::array<double, contest_limit_count> contest_measures(const Engine& engine, const ShotSettings& given, Verification* verification,
                                                         double* least_sling_pull) {
  check_engine(engine);
  ShotSettings settings = settings_for(engine, given);  // a ball of given size sets its density
  settings.loads = true;
  const ScaledDesign d = shot_design(engine, settings);
  std::vector<TracePoint> trace;
  const ShotResult shot = simulate_shot(d, release_criterion(engine, settings), settings.integrator, &trace, 0.02, nullptr, true, {},
                                        TraceSpan::to_release);
  const Verification v = verification_of(engine, shot, settings.target_level, settings.air, settings.range_from_release);
  // Heights above the base, which the box stands on; x along the ground. Each body's coordinate,
  // and the projectile's acceleration, is sampled every 0.02 (scaled time) and at the release; its
  // extreme lies between the samples beside the best one, where the parabola through the three
  // finds it to O(0.02^3) (the best sample alone fell short by up to 3e-4 of the box, and its
  // acceleration jumped by 1e-3 from one engine to the next, too rough for a search to follow).
  const double base = d.pivot_height();
  std::vector<double> times;
  // x and y of the pivot, the hinge, the counterweight's box (two opposite corners, upright; its
  // centre without a box), the tip and the projectile
  std::array<std::vector<double>, 12> coordinates;
  const Vec2 half_box{engine.parts.box_width.value_or(0) / 2 / engine.L2, engine.parts.box_height.value_or(0) / 2 / engine.L2};  // scaled
  std::vector<double> accelerations;  // scaled, in g
  std::vector<double> pulls;  // the sling's on the projectile, in its weights
  for (const TracePoint& p : trace) {
    if (!times.empty() && !(p.t > times.back())) continue;  // a phase's end, sampled twice
    const Snapshot& s = p.snapshot;
    times.push_back(p.t);
    int k = 0;
    const Vec2 low_corner{s.counterweight.x - half_box.x, s.counterweight.y - half_box.y},
        high_corner{s.counterweight.x + half_box.x, s.counterweight.y + half_box.y};
    for (const Vec2& at : {s.pivot, s.hinge, low_corner, high_corner, s.tip, s.projectile})
      coordinates[k++].push_back(at.x), coordinates[k++].push_back(at.y + base);
    // The sling's pull (the tip feels its opposite), the trough's push and the weight, over the projectile's mass.
    accelerations.push_back(std::hypot(-s.sling_on_tip.x, -s.sling_on_tip.y + s.normal_force - d.mu) / d.mu);
    pulls.push_back(s.sling_tension / d.mu);
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
  if (least_sling_pull) *least_sling_pull = -sampled_extreme(times, pulls, -1);
  return {(x_high - x_low) * engine.L2, (y_high - y_low) * engine.L2, engine.M, v.loads[pivot_load].value,
          peak_acceleration(engine, settings, v, times, accelerations)};
}

bool LimitsToMeet::any() const {
  return min_clearance > 0 || std::any_of(limits.begin(), limits.end(), [](const auto& limit) { return limit.has_value(); });
}

std::vector<BrokenLimit> broken_limits(const Engine& engine, const ShotSettings& settings, const LimitsToMeet& to_meet) {
  Verification v;
  const std::array<double, contest_limit_count> measured = contest_measures(engine, settings, &v);
  std::vector<BrokenLimit> broken;
  for (int k = 0; k < contest_limit_count; ++k)
    if (to_meet.limits[k] && measured[k] > *to_meet.limits[k] * (1 + 1e-12))  // a part in 1e16 of rounding, as the contest allows
      broken.push_back({contest_limit_key(static_cast<ContestLimit>(k)), measured[k], *to_meet.limits[k]});
  const double clearance = lowest_clearance(v);
  if (clearance < to_meet.min_clearance) broken.push_back({"min_clearance", clearance, to_meet.min_clearance});
  return broken;
}

}  // namespace trebuchet
