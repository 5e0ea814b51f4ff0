#include "trebuchet/shot.hpp"

#include <algorithm>
#include <limits>
#include <cmath>
#include <memory>
#include <iterator>
#include <optional>
#include <utility>
#include <vector>

#include "given_release.hpp"
#include "gsl_errors.hpp"
#include "ode.hpp"
#include "solve_1d.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/angles.hpp"

namespace trebuchet {
namespace {

// A shot whose accepted state passes cos phi = 0.02 (phi > 88.9 deg) in the trough is
// abandoned, before the step control loses accuracy at the singularity of eq:EOM_I_1.
constexpr double abandon_trough_cos_phi = 2 * refuse_trough_cos_phi;

// Where the model stops holding (issue 12): the sling pushes instead of pulling, or the
// counterweight or the beam's tip passes below the engine's base, or the whipper's arm would pull
// the counterweight it holds, or a rope of mass stops being a straight rope (rope_holds). Each is
// a continuous function of time, negative when the condition fails; the first time each turns
// negative is kept.
constexpr int condition_count = 5;
using Conditions = std::array<double, condition_count>;
// A condition fails below -1e-9 (scaled: M g for the tension, L2 for heights), so that round-off
// cannot raise it where it holds with equality: an F = 1 counterweight hanging straight down
// touches the base's level.
constexpr double condition_slack = 1e-9;
// Two instants found as roots, within this of each other, are one (scaled time): the slack's
// onset is found to 1e-12 and the range's peak to 1e-11, but the four-point slope's round-off
// moves that root by up to 1e-8 (measured: 8e-9 on random engines). Over 1e-7 the model's push
// moves the ball by about |T'| 1e-14 L2 / (2 mu): nothing a figure shows.
constexpr double same_time = 1e-7;
// A rope of mass modelled as a straight rod (sling.hpp) holds while it pulls at both ends and
// the shear the rod carries there, which a rope cannot, stays below tan 10 deg of its tension:
// a rope would bend by that angle at its end to carry it, and its ends' angles, the sling's
// length and phi along it would be off by as much. > 0 where it holds, and for a rope of no mass;
// not asked in the trough, where the model takes every sling straight from the start
// (docs/machines.md, "The sling's mass").
double rope_holds(Phase phase, const Snapshot& s) {
  if (phase != Phase::lifted || (s.rope_shear_at_tip == 0 && s.rope_shear_at_end == 0)) return 1;
  const double bend = std::tan(10 * M_PI / 180);
  return std::min(bend * s.rope_tension_at_tip - std::abs(s.rope_shear_at_tip), bend * s.sling_tension - std::abs(s.rope_shear_at_end));
}

Conditions conditions_of(Phase phase, const Snapshot& s) {
  return {s.sling_tension + condition_slack, s.counterweight_height + condition_slack, s.tip_height + condition_slack,
          s.counterweight_push + condition_slack, rope_holds(phase, s) + condition_slack};
}
using Onsets = std::array<std::optional<double>, condition_count>;

// The samples of one phase at the integrator's step ends, with the running force extremes
// refined on the continuous solution: where a force has a local maximum at a step end, the
// true peak lies within the two neighbouring steps and is found there by Brent's method.
class PhaseRecord {
 public:
  struct Sample : StepEnd {
    ForceValues forces;
    ForceExtremes extremes;  // over [0, t], refined peaks included
    std::array<double, load_count> loads;
    double counterweight_height;  // of its centre above the base, scaled
    Conditions conditions;  // where the model holds (conditions_of)
  };
  struct Peak {
    double t;
    ForceValues forces;
  };

  PhaseRecord(PhaseIntegrator& integrator, ForceExtremes before, Onsets& onsets) : integrator_(integrator), before_(before), onsets_(onsets) {
    samples_.reserve(128);  // a phase takes 20 to 70 steps at the defaults
  }

  void add(const StepEnd& end, const Snapshot& snap) {
    const ForceValues forces = force_values(snap);
    ForceExtremes extremes = samples_.empty() ? before_ : samples_.back().extremes;
    extremes.add(forces);
    const Conditions now = conditions_of(integrator_.phase(), snap);
    samples_.push_back({end, forces, extremes, load_values(snap), snap.counterweight_height, now});
    if (samples_.size() >= 3) refine_peaks(), record_dips();
    record_onsets(now);
  }

  const std::vector<Sample>& samples() const { return samples_; }

  // The state at `time` from the interpolant between the samples around it.
  OdeVector y_at(double time) const {
    const std::size_t base = base_of(time);
    if (time <= samples_[base].t || base + 1 == samples_.size()) return y_exact_at(time);
    return hermite(samples_[base], samples_[base + 1], time, integrator_.angles(), integrator_.dimension());
  }

  // The state at `time`, integrated anew from the last sample at or before it.
  OdeVector y_exact_at(double time) const {
    const Sample& base = samples_[base_of(time)];
    return integrator_.at(base.t, base.y, time);
  }

  // The snapshot at `time`, of the state integrated anew (y_exact_at) or on the interpolant (y_at).
  Snapshot snapshot_exact_at(double time) const { return integrator_.machine().snapshot(integrator_.phase(), integrator_.state(y_exact_at(time))); }
  Snapshot snapshot_at(double time) const { return integrator_.machine().snapshot(integrator_.phase(), integrator_.state(y_at(time))); }

  // Where a running extreme of eq:F starts to grow inside [lo, hi]: the instant when its force,
  // below the extreme at the sample before, crosses it (the root of force - extreme on the
  // continuous solution). The slope of Q jumps there; between such onsets Q is smooth.
  struct Onset {
    double t;
    ForceIndex force;
  };
  std::vector<Onset> growth_onsets(double lo, double hi) const {
    std::vector<Onset> out;
    for (std::size_t i = base_of(lo); i + 1 < samples_.size() && samples_[i].t < hi; ++i) {
      const Sample &a = samples_[i], &b = samples_[i + 1];
      for (int k = 0; k < force_count; ++k) {
        const double extreme = a.extremes.max[k];
        if (!(a.forces[k] < extreme && b.extremes.max[k] > extreme)) continue;
        // The force passes the extreme by the next sample, or at a refined peak before it.
        double t_above = b.t;
        if (!(b.forces[k] > extreme))
          for (const Peak& p : peaks_)
            if (p.t > a.t && p.t < b.t && p.forces[k] > extreme) t_above = std::min(t_above, p.t);
        const double t = find_root([&](double time) { return forces_at(time)[k] - extreme; }, a.t, t_above, 1e-14, 0);
        if (t > lo && t < hi) out.push_back({t, static_cast<ForceIndex>(k)});
      }
    }
    std::sort(out.begin(), out.end(), [](const Onset& x, const Onset& y) { return x.t < y.t; });
    return out;
  }

  // The values of load k at the samples before t_end, then `at_end` at t_end: where its largest
  // value is sought (simulate_shot, the builder's loads).
  std::vector<Point> load_points(int k, double t_end, double at_end) const {
    std::vector<Point> points;
    for (const Sample& sample : samples_)
      if (sample.t < t_end) points.push_back({sample.t, sample.loads[k]});
    points.push_back({t_end, at_end});
    return points;
  }

  // The largest value of load k near points[top] of load_points: between its neighbours, as a
  // peak of force is refined (refine_peaks), when it has two.
  LoadPeak refined_load_peak(int k, const std::vector<Point>& points, std::size_t top) const {
    LoadPeak peak{points[top].f, points[top].x};
    if (top == 0 || top + 1 == points.size()) return peak;
    const Point estimate = parabola_vertex(points[top - 1], points[top], points[top + 1]);
    const double t = peak_between([&](double time) { return loads_at(time)[k]; }, points[top - 1].x, estimate.x, points[top + 1].x, 1e-6, 1e-8);
    const double value = loads_at(t)[k];
    return value > peak.value ? LoadPeak{value, t} : peak;
  }

  // The last sample at or before `time` (the first one for earlier times); samples are in time order.
  std::size_t base_of(double time) const {
    const auto after = std::upper_bound(samples_.begin() + 1, samples_.end(), time,
                                        [](double value, const Sample& sample) { return value < sample.t; });
    return static_cast<std::size_t>(after - samples_.begin()) - 1;
  }

  // The running extremes over [0, time], without the value at `time` itself.
  ForceExtremes extremes_before(double time) const {
    const std::size_t base = base_of(time);
    ForceExtremes out = samples_[base].extremes;
    for (const Peak& p : peaks_)
      if (p.t > samples_[base].t && p.t <= time) out.add(p.forces);
    return out;
  }

 private:
  ForceValues forces_at(double time) const { return force_values(snapshot_at(time)); }

  std::array<double, load_count> loads_at(double time) const { return load_values(snapshot_at(time)); }

  // A condition that turns negative between the last two samples fails at the root of its
  // value on the interpolant between them; one negative at the first sample fails there.
  void record_onsets(const Conditions& now) {
    for (int k = 0; k < condition_count; ++k) {
      if (onsets_[k] || !(now[k] < 0)) continue;
      const double t = samples_.back().t;
      if (samples_.size() == 1 || !(previous_[k] >= 0)) {
        onsets_[k] = t;
      } else {
        const double t0 = samples_[samples_.size() - 2].t;
        onsets_[k] = find_root([&](double time) { return conditions_of(integrator_.phase(), snapshot_at(time))[k]; }, t0, t, 1e-12, 0);
      }
    }
    previous_ = now;
  }

  // A condition that holds at the last three samples, lowest at the middle one, may fail between
  // them: its minimum there, found on the interpolant as a force's peak is (refine_peaks), below 0
  // is an onset, at the root before it. Without it a slack that sets in and ends within two steps
  // would pass unwarned, and the warning would flicker with the step ends around it.
  void record_dips() {
    const std::size_t mid = samples_.size() - 2;
    const Sample &a = samples_[mid - 1], &b = samples_[mid], &c = samples_[mid + 1];
    for (int k = 0; k < condition_count; ++k) {
      const double fa = a.conditions[k], fb = b.conditions[k], fc = c.conditions[k];
      if (onsets_[k] || !(fa >= 0 && fb >= 0 && fc >= 0) || !(fb <= fa && fb < fc)) continue;
      // The parabola through the three estimates the minimum; one above 0 by more than the dip's
      // whole depth in the samples would need the parabola to err by more than that depth, which
      // the steps of an integration to its tolerance do not leave room for: not sought.
      const Point estimate = parabola_vertex({a.t, -fa}, {b.t, -fb}, {c.t, -fc});
      if (-estimate.f > std::max(fa, fc) - fb) continue;
      const auto condition_at = [&](double time) { return conditions_of(integrator_.phase(), snapshot_at(time))[k]; };
      const double t_low = peak_between([&](double time) { return -condition_at(time); }, a.t, estimate.x, c.t, 1e-6, 1e-8);
      if (condition_at(t_low) < 0) onsets_[k] = find_root(condition_at, t_low < b.t ? a.t : b.t, t_low, 1e-12, 0);
    }
  }

  // A force peaking at the middle one of the last three samples peaks between the outer two.
  // A peak that stays well below the running maximum before it cannot change any later
  // maximum and is skipped: the parabola through the three samples estimates it, and 1 %
  // covers that estimate's error (1e-3 at worst on the random designs of tests/test_reference).
  // The peak is the root of the force's slope, central difference with step 1e-6 (scaled time),
  // found to 1e-8: its value is then exact to f'' 1e-16 / 2.
  void refine_peaks() {
    const std::size_t mid = samples_.size() - 2;
    const Sample &a = samples_[mid - 1], &b = samples_[mid], &c = samples_[mid + 1];
    for (int k = 0; k < force_count; ++k) {
      const double fa = a.forces[k], fb = b.forces[k], fc = c.forces[k];
      if (!(fb > fa && fb >= fc)) continue;
      const Point estimate = parabola_vertex({a.t, fa}, {b.t, fb}, {c.t, fc});
      if (estimate.f < 0.99 * a.extremes.max[k]) continue;
      const double t_peak = peak_between([&](double time) { return forces_at(time)[k]; }, a.t, estimate.x, c.t, 1e-6, 1e-8);
      Peak peak{t_peak, forces_at(t_peak)};
      if (!(peak.forces[k] >= fb)) peak = {b.t, b.forces};  // the slope's root was no peak
      peaks_.push_back(peak);
      for (std::size_t s = mid - 1; s < samples_.size(); ++s)
        if (samples_[s].t >= t_peak) samples_[s].extremes.add(peak.forces);
    }
  }

  PhaseIntegrator& integrator_;
  ForceExtremes before_;
  Onsets& onsets_;
  Conditions previous_{};
  std::vector<Sample> samples_;
  std::vector<Peak> peaks_;
};

// The objective is smooth between the onsets of growth of the running extremes, where its slope
// jumps. On each smooth piece of [lo, hi] the slope is scanned at `scan` (sorted times) and the
// piece's ends; wherever it falls through zero between two scan points, a maximum lies between
// them, at the root. The best of these and of the ends (onsets included) is the release. The
// slope is `rate` where it gives one (the range through air: its flight's sensitivities,
// ShotRun::range_rate), else the four-point central difference with step 1e-5 (scaled time):
// truncation O(step^4) moves the root by ~1e-20, round-off by ~1e-11, relative; a maximum within
// two steps of an onset is taken at the onset, at most Q'' (2e-5)^2/2 below it. Checked against
// the independent reference (tests/test_reference.cpp).
struct Candidate {
  double t;
  double value;
  std::optional<ForceIndex> at_onset;
  std::optional<double> before_slack;  // the onset of a slack up to the peak it was sought before (optimal_release)
};
template <class Objective, class Rate>
Candidate release_time(const Objective& objective, const Rate& rate, double lo, double hi, const std::vector<double>& scan,
                       const std::vector<PhaseRecord::Onset>& onsets) {
  constexpr double slope_step = 1e-5;
  std::vector<double> ends{lo};
  for (const auto& onset : onsets)
    if (onset.t > lo && onset.t < hi) ends.push_back(onset.t);
  ends.push_back(hi);
  Candidate best{lo, objective(lo), std::nullopt, std::nullopt};
  auto consider = [&](double t) {
    const double value = objective(t);
    if (value > best.value) best = {t, value, std::nullopt, std::nullopt};
  };
  // The slope, remembered at the scan points, where the root search evaluates it again.
  std::vector<Point> slopes;
  const auto slope = [&](double t) {
    for (const Point& known : slopes)
      if (known.x == t) return known.f;
    const std::optional<double> exact = rate(t);
    const double value = exact
        ? 12 * slope_step * *exact  // in the four-point difference's scale
        : 8 * (objective(t + slope_step) - objective(t - slope_step)) - (objective(t + 2 * slope_step) - objective(t - 2 * slope_step));
    slopes.push_back({t, value});
    return value;
  };
  // The edge of the throws: between `off`, on the flat where no release throws forward (the
  // objective 0), and `on`, past which the objective falls, it jumps above 0. Its maximum there
  // lies at the edge (found by bisection to 1e-12 of the time) or at the slope's root after it.
  const auto after_edge = [&](double off, double on) {
    const double fallen = on;
    for (int k = 0; k < 80 && on - off > 1e-12 * on; ++k) {
      const double middle = (off + on) / 2;
      (objective(middle) > 0 ? on : off) = middle;
    }
    consider(on);
    const double start = on + 2 * slope_step;
    if (start < fallen && slope(start) > 0)
      if (const auto root = root_between(slope, start, fallen, 1e-11, 0)) consider(*root);
  };
  for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
    const double a = ends[i] + 2 * slope_step, b = ends[i + 1] - 2 * slope_step;
    consider(ends[i + 1]);
    if (!(a < b)) continue;
    std::vector<double> points{a};
    for (double t : scan)
      if (t > a && t < b) points.push_back(t);
    points.push_back(b);
    double previous = slope(a);
    for (std::size_t j = 1; j < points.size(); ++j) {
      const double here = slope(points[j]);
      if (previous > 0 && !(here > 0)) {
        if (const auto root = root_between(slope, points[j - 1], points[j], 1e-11, 0)) consider(*root);
      } else if (previous == 0 && here < 0 && objective(points[j]) > 0) {
        after_edge(points[j - 1], points[j]);  // the throws begin between them, past their best
      }
      previous = here;
    }
  }
  for (const auto& onset : onsets)
    if (onset.t == best.t) best.at_onset = onset.force;
  return best;
}

[[noreturn]] void fail(const std::string& reason) { throw Error(ErrorKind::numerical, reason); }

// Whether a release throws: forward from above the base; the whipper's, forward and up. Its ball
// first drops off the arm forward and down, a throw of a metre or less (and of a force factor
// near 0, the sling lying along the arm, which would inflate Q); the whip throws it forward and
// up, as pytrebuchet releases it (docs/machines.md, "The whipper").
bool throws(const ScaledDesign& e, const ReleasePoint& r) {
  return r.range > 0 && (e.machine != MachineKind::whipper || (r.velocity_angle > 0 && r.velocity_angle < M_PI / 2));
}

// The event that closes the release window (docs/verifier.md, "Window"): after a release in the
// window has thrown the projectile forward, its velocity turns backward (its x component, toward
// the target at -x, scaled, falls through zero). Every later release throws backward until a
// later swing of the sling, which would be another throw. The sling going slack and the sling
// passing the arm's line are reported (ShotResult, the pin angle), not ends of the window: the
// paper's release (section 5) is an ideal one, whose optimum may lie past either.
class BackwardWatch {
 public:
  static double forward_speed(const Snapshot& s) { return -s.projectile_velocity.x; }
  explicit BackwardWatch(bool thrown) : thrown_(thrown) {}
  // Whether the velocity turns backward between the last sample and `s`, after a forward throw.
  bool turns_backward(const Snapshot& s) const { return thrown_ && !(forward_speed(s) > 0); }
  void add(bool throws_here) { thrown_ = thrown_ || throws_here; }

 private:
  bool thrown_;
};

// Coulomb friction as modelled acts only while a pin turns (sliding, no sticking). Where its
// friction can hold the pin, the pin's turn reaches zero and then reverses at nearly every
// accepted step, or creeps on at round-off while the rejected steps chatter about zero: the pin
// sticks. Either shows within a few dozen accepted steps, where ordinary motion reverses a few
// times in a shot and never dwells at round-off.
class StickWatch {
 public:
  // `turn` and `scale` (the speed that round-off is relative to) are scaled angular speeds.
  bool sticks(double turn, double scale) {
    held_ = std::abs(turn) < 1e-9 * (1 + std::abs(scale)) ? held_ + 1 : 0;
    const bool reversed = turn * last_ < 0;
    last_ = turn;
    return (reversed && ++reversals_ > 30) || held_ > 50;
  }

 private:
  int reversals_ = 0, held_ = 0;
  double last_ = 0;
};

// Whether friction holds a pin of `dynamics`, watched at each accepted state: the axle (the
// beam's turn) and the hinge pin (the counterweight's turn relative to the beam).
struct PinWatch {
  StickWatch axle, hinge;
  bool axle_holds(const ScaledDesign& e, const State& s) { return e.parts.axle_friction > 0 && axle.sticks(s.theta_dot, s.psi_dot); }
  bool hinge_holds(const ScaledDesign& e, const State& s) { return e.parts.hinge_friction > 0 && hinge.sticks(s.psi_dot - s.theta_dot, s.theta_dot); }
};

// The motion of one phase over [t_begin, t_end] for the series: the step ends in it, or with
// dt > 0 the continuous solution at every multiple of dt after t_begin (at 0 too) and t_end.
void record_trace(std::vector<TracePoint>* trace, PhaseIntegrator& integrator, const PhaseRecord& record, double t_begin, double t_end, double dt) {
  if (!trace) return;
  auto add = [&](double t, const OdeVector& y) {
    const State s = integrator.state(y);
    trace->push_back({integrator.phase(), t, s, integrator.machine().snapshot(integrator.phase(), s), integrator.work(y)});
  };
  if (!(dt > 0)) {
    for (const auto& sample : record.samples())
      if (sample.t >= t_begin && sample.t <= t_end) add(sample.t, sample.y);
    return;
  }
  for (double k = std::ceil(t_begin / dt); k * dt < t_end; ++k)
    if (k * dt > t_begin || t_begin == 0) add(k * dt, record.y_at(k * dt));
  add(t_end, record.y_at(t_end));
}

// Phase III: beam and counterweight without the projectile (mu = 0), from the release for as
// long again as the shot took, so that the ringing of appendix B shows and the counterweight
// makes a full swing or more. `each_step` is called with every accepted step's start and end
// state. Where friction holds a pin after the release (StickWatch) the machine comes to rest
// (the model leaves sticking out), and phase III ends there. The shot's figures are known at
// the release: where phase III cannot go on (its step budget spent, a step that fails), it ends
// there, and says where and why.
template <class EachStep>
std::optional<PhaseIiiCut> follow_released(const ScaledDesign& e, const IntegratorSettings& settings, const State& release, const Losses& work,
                                           double t_release, PhaseIntegrator& released, EachStep each_step) {
  OdeVector y = released.vector_of(release, work);
  const double t_end = 2 * t_release;
  double t = t_release, h = 1e-3;
  PinWatch pins;
  for (long steps = 0; t < t_end; ++steps) {
    if (steps >= settings.max_steps) return PhaseIiiCut{t, "its step budget of " + std::to_string(settings.max_steps) + " steps ran out"};
    const double t_start = t;
    const OdeVector y_start = y;
    if (!released.step(t, y.data(), t_end, h))
      return PhaseIiiCut{t, released.friction_unsettled() ? "the friction at the pins left its accelerations unsettled" : "a step failed"};
    each_step(t_start, y_start, t, y);
    const State s = released.state(y);
    if (pins.axle_holds(e, s) || pins.hinge_holds(e, s)) break;
  }
  return std::nullopt;
}

// Phase III for the series: at the step ends, or every dt > 0 (each integrated anew from the step it falls in).
void trace_released(const Machine& dynamics, const ScaledDesign& e, const IntegratorSettings& settings, const State& release, const Losses& work,
                    double t_release, double dt, std::vector<TracePoint>& trace) {
  PhaseIntegrator released(dynamics, Phase::released, settings);
  double k = std::floor(t_release / dt) + 1;  // the next multiple of dt, when dt > 0
  auto add = [&](double time, const OdeVector& at) {
    const State s = released.state(at);
    trace.push_back({Phase::released, time, s, dynamics.snapshot(Phase::released, s), released.work(at)});
  };
  const double t_end = 2 * t_release;
  follow_released(e, settings, release, work, t_release, released, [&](double t_start, const OdeVector& y_start, double t, const OdeVector& y) {
    if (dt > 0) {
      for (; k * dt <= t; ++k) add(k * dt, released.at(t_start, y_start, k * dt));
      if (t >= t_end && trace.back().t < t) add(t, y);
    } else {
      add(t, y);
    }
  });
}

// How far below the release the flight ends (0 for Denny's range, back at the release height),
// and the range measured from where the criterion measures it (the release point for Denny's).
double flight_drop(const ReleasePoint& r, const ReleaseCriterion& criterion) {
  return criterion.range_from_release ? 0 : r.height - criterion.target_level;
}
double measured_range(double flown, const ReleasePoint& r, const ReleaseCriterion& criterion) {
  return criterion.range_from_release ? flown + r.position.x : flown;
}

// The projectile's motion at a release (position, velocity, height, the vacuum range to level 0
// where it flies toward the target from above the base, its velocity angle): what decides
// whether it throws.
void set_motion(ReleasePoint& r, const ScaledDesign& e, const Snapshot& snap) {
  r.position = snap.projectile;
  r.velocity = snap.projectile_velocity;
  r.height = e.pivot_height() + r.position.y;
  if (r.velocity.x < 0 && r.height >= 0) r.range = vacuum_range(r.position, r.velocity, r.height, 1);
  r.velocity_angle = velocity_angle(snap);
}

// The range the release maximises under Release::range: in vacuum from the pivot to the
// criterion's target level (level 0 is the paper's), else through the criterion's drag, or
// Denny's, from the release point to where the flight dips below the release height (section
// 6.3); 0 where the flight never comes down to its end.
double objective_range(const ReleasePoint& r, const ReleaseCriterion& criterion) {
  if (!criterion.drag && !criterion.range_from_release && criterion.target_level == 0) return r.range;
  const double drop = flight_drop(r, criterion);
  double range = 0;
  if (criterion.drag) {
    const auto end = fly(r.position, r.velocity, drop, *criterion.drag, 1);
    if (!end) return 0;
    range = end->range;
  } else {
    if (!(r.velocity.y * r.velocity.y + 2 * drop > 0)) return 0;  // the target level lies above the apex
    range = vacuum_range(r.position, r.velocity, drop, 1);
  }
  return std::max(measured_range(range, r, criterion), 0.0);
}

}  // namespace

// The axle's load is the force the frame carries: at the pivot, and the floating arm's guide's
// push on its counterweight beside its rail's (docs/machines.md; 0 on the other machines).
std::array<double, load_count> load_values(const Snapshot& s) {
  const Vec2 frame{s.pivot_reaction.x + s.guide_force.x, s.pivot_reaction.y + s.guide_force.y};  // of order M g, as |F_R| (force_values)
  return {std::max(s.sling_tension, s.rope_tension_at_tip), std::hypot(s.hinge_force.x, s.hinge_force.y),
          std::sqrt(frame.x * frame.x + frame.y * frame.y), std::abs(s.beam_moment)};
}

ReleasePoint release_point(const ScaledDesign& e, const ReleaseCriterion& criterion, double t, const State& s, const Snapshot& snap,
                           ForceExtremes extremes) {
  extremes.add(force_values(snap));
  ReleasePoint r;
  r.t = t;
  r.state = s;
  set_motion(r, e, snap);
  r.energy_at_target = energy_at_target(e.mu, r.velocity, r.height);
  r.efficiency = efficiency(r.energy_at_target, e.energy_drop());
  r.extremes = extremes;
  r.force_factor = force_factor(extremes, e.mu);
  r.pin_angle = pin_angle(snap);
  if (r.range > 0) {
    r.quality = quality(r.range, e.l, e.mu, r.efficiency, r.force_factor, criterion.n);
    if (!throws(e, r)) return r;
    switch (criterion.release) {
      case Release::quality: r.objective = r.quality; break;
      case Release::efficiency: r.objective = r.efficiency; break;
      case Release::range: r.objective = objective_range(r, criterion); break;  // tab:Denny, "Present" row
    }
  }
  return r;
}

ShotResult simulate_shot(const ScaledDesign& e, const ReleaseCriterion& criterion, const IntegratorSettings& settings, std::vector<TracePoint>* trace,
                         double trace_dt, std::vector<TracePoint>* unreleased, bool find_loads, const OtherReleases& others, TraceSpan span) {
  return simulate_shot(*machine_of(e), criterion, settings, trace, trace_dt, unreleased, find_loads, others, span);
}

namespace {

// One shot of appendix A, in the order a reader follows it: phase I from rest (with the
// whipper's phase held before it), phase II to the end of the release window, the release
// search, and from the release the loads and the counterweight's lowest point through phase
// III. Its members are what one phase hands on to the next. Phase II is one trajectory for every
// release: a shot given a release (begin_given) reads its samples, stepped on as it needs them,
// so that the shots given several releases share the steps (simulate_given_shots).
class ShotRun {
 public:
  ShotRun(const Machine& dynamics, const ReleaseCriterion& criterion, const IntegratorSettings& settings, bool replays)
      : dynamics_(dynamics),
        e_(dynamics.design()),
        criterion_(criterion),
        settings_(settings),
        whips_(dynamics.first_phase() == Phase::held),
        replays_(replays),
        energy_scale_(e_.energy_drop()) {}

  void phase_one(std::vector<TracePoint>* trace, double trace_dt);
  void phase_two();
  void begin_given(const GivenRelease& asked);
  void search_window(bool unreleased);
  void find_release();
  void follow_others(const OtherReleases& others);
  void mark_onsets();
  void find_loads();
  void find_lowest_counterweight();
  void write_trace(std::vector<TracePoint>* trace, double trace_dt, TraceSpan span, std::vector<TracePoint>* unreleased);
  const ShotResult& result() const { return result_; }

 private:
  void track_energy(const Snapshot& s, const Losses& work);
  bool count_step(const char* phase, const State& s, bool hinge_turns = true);
  void start();
  [[noreturn]] void refuse_backward_start() const;
  double carry(PhaseIntegrator& integrator, PhaseRecord& record);
  void check_carried_step(bool axle_holds) const;
  void check_held_step() const;
  ReleasePoint point_from(double time, const OdeVector& state) const;
  ReleasePoint point_at(double time) const { return point_from(time, phase2_->y_at(time)); }
  std::optional<double> range_rate_at(double time) const;
  void keep_sample(const Snapshot& at, bool thrown);
  void step_phase_two();
  void take_step();
  bool step_ends_shot();
  std::string window_end_seen() const;
  bool objective_fallen() const;
  [[noreturn]] void refuse_given(const std::string& what);
  [[noreturn]] void fail_no_forward_release() const;
  Candidate optimal_release() const;
  Candidate best_release_before(double latest) const;
  std::optional<double> slack_up_to_peak(double t) const;
  double given_release(const GivenWatch& g) const;

  const Machine& dynamics_;
  const ScaledDesign& e_;
  const ReleaseCriterion& criterion_;
  const IntegratorSettings& settings_;
  const bool whips_;  // the whipper, whose counterweight rests on the arm in a phase held first
  const bool replays_;  // whether releases replay the samples (a given release, OtherReleases)
  const double energy_scale_;
  ShotResult result_;
  double energy0_ = 0;
  // The steps taken and the energy's drift so far (track_energy), over every phase stepped.
  long steps_ = 0;
  double drift_ = 0;
  // The hinge pin's friction turns with the counterweight's swing relative to the beam, which
  // reverses a few times in a shot. A pin whose friction can hold that swing makes it stick and
  // slip, which Coulomb's law as modelled here (sliding only) leaves out: the turn then reverses
  // at nearly every step, and the shot says so rather than spend its step budget.
  PinWatch pins_;
  OdeVector y_{};
  double t_ = 0, h_ = 1e-3;
  Onsets onsets_;
  Snapshot snap_;
  std::unique_ptr<PhaseIntegrator> held_;
  std::unique_ptr<PhaseRecord> held_record_;
  std::optional<PhaseIntegrator> trough_, lifted_;
  std::optional<PhaseRecord> phase1_, phase2_;
  // Phase II: the objective at every step end, in the order of the samples, and its best.
  std::vector<double> sampled_;
  double best_quality_ = 0;
  // The highest apex, in vacuum, of the flights that a release at a step end sends forward
  // (scaled, above the base): what a target level above every flight is told.
  double highest_apex_ = 0;
  // What a given release watches at each sample of phase II (the snapshot, whether a release
  // there throws), kept only where releases replay them; the steps and the energy drift up to it.
  std::vector<Snapshot> snapshots_;
  std::vector<char> throwing_;
  std::vector<double> drift_up_to_;
  std::vector<long> steps_up_to_;
  std::optional<GivenRelease> asked_;  // the release given, as given
  std::optional<GivenWatch> given_;
  std::optional<BackwardWatch> backward_;
  std::string window_end_;  // why the window ended, for a given release that never comes
  std::optional<std::size_t> window_end_at_;  // the sample it ended on
  std::optional<Error> failure_;  // a step of phase II that failed: every release past it fails so
  std::size_t seen_ = 0;  // the samples of phase II the release sought has read
  bool ended_ = false;  // the shot ended (not merely past the release)
  double search_end_ = 0;  // the last sample's time when the release was sought
  double t_release_ = 0;
};

// The bodies' energy and the work of the losses balance (with none, the energy is conserved).
void ShotRun::track_energy(const Snapshot& s, const Losses& work) {
  double lost = 0;
  for (double w : work) lost += w;
  drift_ = std::max(drift_, std::abs(s.energy + lost - energy0_) / energy_scale_);
}

// Counts an accepted step against the budget; whether the axle's friction now holds the beam.
// In the whipper's phase held the counterweight does not turn on its pin: nothing to watch.
bool ShotRun::count_step(const char* phase, const State& s, bool hinge_turns) {
  if (++steps_ > settings_.max_steps)
    fail("step budget of " + std::to_string(settings_.max_steps) + " steps exceeded in " + phase +
         "; loosen {{rtol}} or choose a higher-order {{stepper}}");
  if (hinge_turns && pins_.hinge_holds(e_, s))
    fail(
        "the hinge pin's friction makes the counterweight stick to the beam and slip, which the model leaves out "
        "(docs/verifier.md, \"Real engines\"); give a smaller {{hinge_friction}} or {{hinge_radius}}");
  return pins_.axle_holds(e_, s);
}

// The start of phase I: at rest (eq:InitialConditions: phi_i = 0, and psi_i = 0 unless propped).
void ShotRun::start() {
  y_ = {dynamics_.theta_i(), radians(e_.psi_i_deg), 0, 0, 0, 0};
  snap_ = dynamics_.snapshot(dynamics_.first_phase(), State{y_[0], y_[1], 0, 0, 0, 0});
  // A counterweight propped forward can pull the short arm the wrong way: the shot never starts.
  if (!(snap_.theta_ddot > 0)) refuse_backward_start();
  energy0_ = snap_.energy;
}

void ShotRun::refuse_backward_start() const {
  if (whips_)
    fail(
        "the whipper's beam starts to turn backwards, away from the throw: what rests on its arm, the counterweight (or a heavy ball on a "
        "sling longer than the long arm), lies too far behind the pivot; lengthen the counterweight's rope {{L3}}, turn it less off the arm "
        "(a smaller {{rope_angle_deg}}), or lighten the projectile {{m}}");
  if (e_.psi_i_deg != 0)
    fail("the beam starts to turn away from the throw (the counterweight, propped at psi_i = " + format_significant(e_.psi_i_deg, 4) +
         " deg, pulls the short arm backwards); " +
         (e_.psi_i_deg > 0 ? std::string("prop it less, or back ({{psi_i_deg}} < 0)") : std::string("hold it back less ({{psi_i_deg}} nearer 0)")));
  // Hanging, the counterweight is outweighed at rest by what the long arm holds: name what the engine gives of it.
  std::string held = "the projectile {{m}}, the beam {{mb}}";
  if (e_.parts.sling.rope > 0) held += ", the sling's rope {{rope_mass}}";
  if (e_.parts.sling.pouch > 0) held += ", the pouch {{pouch_mass}}";
  fail("the beam starts to turn away from the throw: at rest, what the long arm holds (" + held +
       ") outweighs the counterweight {{M}} about the pivot; lighten it, or give a heavier {{M}}");
}

// What ends a carrying phase's step in failure, before its snapshot is taken (whose friction is
// unsettled near a sling upright in the trough): friction that stops the beam holds it
// (Coulomb's law at rest: the engine jams), or the sling stands vertical in the trough.
void ShotRun::check_carried_step(bool axle_holds) const {
  if (axle_holds || (dynamics_.dissipates() && !(y_[2] > 0)))
    fail(std::string("friction stops the beam before the projectile ") + (whips_ ? "leaves the arm" : "lifts off") +
         ": the engine jams; give smaller friction coefficients or pin radii ({{axle_friction}}, {{hinge_friction}}, {{trough_friction}})");
  if (dynamics_.trough_cos_phi(y_[0]) < abandon_trough_cos_phi)
    fail(
        "the sling stands vertical in the trough (phi -> 90 deg) before lift-off; lengthen the sling {{L4}} or lighten what it carries, the "
        "projectile {{m}}" +
        std::string(e_.parts.sling.pouch > 0 ? " and the pouch {{pouch_mass}}" : ""));
}

// The whipper's projectile leaving the arm before its counterweight, in its phase held.
void ShotRun::check_held_step() const {
  if (!(snap_.normal_force > 0))
    fail(
        "the whipper's projectile would leave the arm before its counterweight, which the model (pytrebuchet's order) leaves out; "
        "lengthen the sling {{L4}} or the counterweight's rope {{L3}}, or turn the rope further off the arm (a larger {{rope_angle_deg}})");
}

// Runs a phase that carries the projectile (and, held, the counterweight) from (t, y) to where
// its contact lets go: the root of the contact's value on the interpolant, the state there
// integrated anew from the step start. Returns the time.
double ShotRun::carry(PhaseIntegrator& integrator, PhaseRecord& record) {
  const Phase phase = integrator.phase();
  const auto contact = [&](const Snapshot& at) { return phase == Phase::held ? at.counterweight_on_arm : at.normal_force; };
  if (phase != dynamics_.first_phase()) snap_ = dynamics_.snapshot(phase, integrator.state(y_));  // the first's is the start's
  record.add(integrator.step_end(t_, y_, snap_), snap_);
  if (!(contact(snap_) > 0)) return t_;  // it lets go at once
  while (true) {
    if (!integrator.step(t_, y_.data(), settings_.max_time, h_))
      fail(integrator.friction_unsettled() ? unsettled_friction : "integrator failure in phase I; tighten {{rtol}} or choose another {{stepper}}");
    const bool axle_holds = count_step("phase I", integrator.state(y_), phase != Phase::held);
    check_carried_step(axle_holds);
    snap_ = dynamics_.snapshot(phase, integrator.state(y_));
    if (phase == Phase::held) check_held_step();
    if (!(contact(snap_) > 0)) {
      const StepEnd& before = record.samples().back();
      const StepEnd after = integrator.step_end(t_, y_, snap_);
      auto contact_at = [&](double time) {
        return contact(dynamics_.snapshot(phase, integrator.state(hermite(before, after, time, integrator.angles(), integrator.dimension()))));
      };
      t_ = find_root(contact_at, before.t, t_, 1e-13, 0);
      y_ = integrator.at(before.t, before.y, t_);
      snap_ = dynamics_.snapshot(phase, integrator.state(y_));
      record.add(integrator.step_end(t_, y_, snap_), snap_);
      track_energy(snap_, integrator.work(y_));
      return t_;
    }
    record.add(integrator.step_end(t_, y_, snap_), snap_);
    track_energy(snap_, integrator.work(y_));
    if (y_[0] >= dynamics_.turn_limit(phase) || t_ >= settings_.max_time)
      fail(phase == Phase::held ? "the whipper's counterweight never leaves the arm; lengthen its rope {{L3}} or change the masses"
               : whips_         ? "the whipper's projectile never leaves the arm; change the sling length {{L4}} or the masses"
                                : "the projectile never lifts off: the trough still carries it when the beam is upright; "
                                  "change the sling length L4 or the masses");
  }
}

// Phase I: from rest until the trough's normal force vanishes. The whipper starts with a phase
// `held`, until its counterweight leaves the arm, and its phase I ends where the projectile leaves it.
void ShotRun::phase_one(std::vector<TracePoint>* trace, double trace_dt) {
  start();
  if (whips_) {
    held_ = std::make_unique<PhaseIntegrator>(dynamics_, Phase::held, settings_);
    held_record_ = std::make_unique<PhaseRecord>(*held_, ForceExtremes{}, onsets_);
    result_.t_counterweight_free = carry(*held_, *held_record_);
    record_trace(trace, *held_, *held_record_, 0, t_, trace_dt);
  }
  trough_.emplace(dynamics_, Phase::trough, settings_);
  phase1_.emplace(*trough_, held_record_ ? held_record_->samples().back().extremes : ForceExtremes{}, onsets_);
  result_.t_liftoff = carry(*trough_, *phase1_);
  record_trace(trace, *trough_, *phase1_, result_.t_counterweight_free.value_or(0), t_, trace_dt);
}

ReleasePoint ShotRun::point_from(double time, const OdeVector& state) const {
  const State s = lifted_->state(state);
  return release_point(e_, criterion_, time, s, dynamics_.snapshot(Phase::lifted, s), phase2_->extremes_before(time));
}

void ShotRun::keep_sample(const Snapshot& at, bool thrown) {
  if (replays_) snapshots_.push_back(at), throwing_.push_back(thrown);
  drift_up_to_.push_back(drift_), steps_up_to_.push_back(steps_);
}

// Phase II from the located lift-off state, its first sample taken.
void ShotRun::phase_two() {
  const State lift = trough_->state(y_);
  lifted_.emplace(dynamics_, Phase::lifted, settings_);
  phase2_.emplace(*lifted_, phase1_->samples().back().extremes, onsets_);
  const Losses work_at_liftoff = trough_->work(y_);
  y_ = {lift.theta, lift.psi, lift.phi, lift.theta_dot, lift.psi_dot, lift.phi_dot};
  for (std::size_t k = 0; k + 6 < lifted_->dimension(); ++k) y_[6 + k] = work_at_liftoff[k];
  const Snapshot lift_snapshot = dynamics_.snapshot(Phase::lifted, lift);
  phase2_->add(lifted_->step_end(t_, y_, lift_snapshot), lift_snapshot);
  const ReleasePoint at_liftoff = point_at(t_);
  sampled_ = {at_liftoff.objective};
  best_quality_ = sampled_.front();
  const bool thrown_at_liftoff = throws(e_, at_liftoff);
  keep_sample(lift_snapshot, thrown_at_liftoff);
  seen_ = 1;
  h_ = 1e-3;
  // The release window (docs/verifier.md, "Window"): one for every shot, every form of release
  // and every machine, lossless or not. It ends where the projectile's velocity turns backward
  // after a forward throw (BackwardWatch; located on the continuous solution, where the last
  // sample of phase II is then taken), or where the beam turns over, friction holds it (the
  // machine stops), or the time is out. Where the beam stops turning forward is no end.
  backward_.emplace(thrown_at_liftoff);
}

// A shot given `asked` on this trajectory, from lift-off: a given release watches its value from
// lift-off on; one already past there would release in the trough. The whipper's projectile
// leaves the arm falling forward, and its velocity and pin angles turn through a whole turn
// before the release: a given angle is the first one below their value there, whole turns apart
// (docs/machines.md, "The whipper"). What phases I and II found before it stays.
void ShotRun::begin_given(const GivenRelease& asked) {
  const double t_liftoff = result_.t_liftoff;
  const std::optional<double> t_counterweight_free = result_.t_counterweight_free;
  result_ = ShotResult{};
  result_.t_liftoff = t_liftoff, result_.t_counterweight_free = t_counterweight_free;
  asked_ = asked;
  given_.emplace(asked, phase2_->samples().front().t, snapshots_.front(), throwing_.front(), whips_);
  seen_ = 1, ended_ = false, t_release_ = 0;
}

// A step of phase II that fails fails every release that needs it, with the same error.
void ShotRun::step_phase_two() {
  if (failure_) throw *failure_;
  try {
    take_step();
  } catch (const Error& e) {
    failure_ = e;
    throw;
  }
}

// One step of phase II, its sample kept for every release that reads it.
void ShotRun::take_step() {
  const StepEnd step_start = phase2_->samples().back();
  if (!lifted_->step(t_, y_.data(), settings_.max_time, h_))
    fail(lifted_->friction_unsettled() ? unsettled_friction : "integrator failure in phase II; tighten {{rtol}} or choose another {{stepper}}");
  State s = lifted_->state(y_);
  const bool axle_holds = count_step("phase II", s);
  snap_ = dynamics_.snapshot(Phase::lifted, s);
  track_energy(snap_, lifted_->work(y_));
  if (backward_->turns_backward(snap_)) {
    // The window closes inside this step: the state where the velocity turns, integrated anew from the step's start.
    const StepEnd after = lifted_->step_end(t_, y_, snap_);
    const auto forward_at = [&](double time) {
      return BackwardWatch::forward_speed(
          dynamics_.snapshot(Phase::lifted, lifted_->state(hermite(step_start, after, time, 3, lifted_->dimension()))));
    };
    t_ = find_root(forward_at, step_start.t, t_, 1e-13, 0);
    y_ = lifted_->at(step_start.t, step_start.y, t_);
    s = lifted_->state(y_);
    snap_ = dynamics_.snapshot(Phase::lifted, s);
    window_end_ = "the projectile's velocity turns backward first";
  }
  const ReleasePoint here = release_point(e_, criterion_, t_, s, snap_, phase2_->samples().back().extremes);
  phase2_->add(lifted_->step_end(t_, y_, snap_), snap_);
  sampled_.push_back(here.objective);
  const bool thrown = throws(e_, here);
  keep_sample(snap_, thrown);
  best_quality_ = std::max(best_quality_, here.objective);
  if (here.range > 0) highest_apex_ = std::max(highest_apex_, here.height + std::pow(std::max(here.velocity.y, 0.0), 2) / 2);  // scaled, g = 1
  backward_->add(thrown);
  if (window_end_.empty()) {
    if (s.theta > dynamics_.turn_limit(Phase::lifted))
      window_end_ = "the beam turns over first";
    else if (t_ >= settings_.max_time)
      window_end_ = "the time runs out first";
    else if (axle_holds)
      window_end_ = "the axle's friction stops the beam first";
  }
  if (!window_end_.empty() && !window_end_at_) window_end_at_ = phase2_->samples().size() - 1;
}

// The next sample of phase II for the release sought: stepped, or read where another release's
// shot stepped it already; whether the shot ends there (the window, or a given release spent).
bool ShotRun::step_ends_shot() {
  if (seen_ == phase2_->samples().size()) step_phase_two();
  const std::size_t i = seen_++;
  if (given_) given_->add(i, phase2_->samples()[i].t, snapshots_[i], throwing_[i]);
  return window_end_at_ == i || (given_ && given_->spent());
}

// Why the window ended, where it ended within the samples read; empty where it did not.
std::string ShotRun::window_end_seen() const { return window_end_at_ && *window_end_at_ < seen_ ? window_end_ : std::string(); }

// Whether the objective has fallen to half its maximum, past an optimum's release. The whipper's
// projectile first drops off the arm forward, with an objective that peaks near zero, before the
// beam whips it round: its optimum is sought over the whole forward swing.
bool ShotRun::objective_fallen() const { return !whips_ && best_quality_ > 0 && sampled_.back() < 0.5 * best_quality_; }

// A given release that cannot be made is refused with the values the whole swing runs through:
// where the search stopped past it, the swing is followed on to its end.
void ShotRun::refuse_given(const std::string& what) {
  while (!ended_) ended_ = step_ends_shot();
  refuse_given_release(*asked_, given_->watch, what, whips_);  // the value as given, not moved by whole turns
}

// No release with a positive objective: under Release::range with a target level above the
// base, the flights go forward but none comes down at that level; else none goes forward.
void ShotRun::fail_no_forward_release() const {
  if (criterion_.release == Release::range && !criterion_.range_from_release && criterion_.target_level > 0 && highest_apex_ > 0)
    throw Error(ErrorKind::usage,
                "{{target_level}} = " + format_significant(criterion_.target_level * criterion_.length_unit, 4) +
                    " m lies above the flight of every release: the highest apex, in vacuum, is about " +
                    format_significant(highest_apex_ * criterion_.length_unit, 4) + " m above the engine's base" +
                    (criterion_.drag ? " (the air lowers it)" : "") + "; give a lower target level");
  fail("no release sends the projectile forward: over phase II it never flies toward the target");
}

// Phase II stepped through the release window until past the release, and what cannot be
// released refused: a given release in the trough or never reached, no forward release, or an
// energy drift above the limit.
void ShotRun::search_window(bool unreleased) {
  // Past the release: the objective has fallen to half its maximum, or two steps past a given
  // release, so that the running extremes of eq:F before it are refined as an optimum's are.
  // With `unreleased` asked for, phase II goes on past a given release as an optimum's window
  // would (to half the objective's best), so that the pictures show what it gave up.
  const auto past = [&] {
    if (given_) return given_->done(seen_) && (!unreleased || objective_fallen());
    return objective_fallen();
  };
  while (!(ended_ = step_ends_shot()) && !past()) {
  }
  if (given_ && given_->in_trough)
    refuse_given(whips_ ? "the release would come before the projectile leaves the arm"
                        : "the release would come before lift-off, with the projectile still in the trough");
  if (given_ && !given_->watch.crossed)
    refuse_given("the release never comes: " +
                 (window_end_seen().empty() ? std::string("the watched value never reaches it") : "the release window ends, " + window_end_seen()));
  if (!given_ && !(best_quality_ > 0)) fail_no_forward_release();
  result_.energy_drift = drift_up_to_[seen_ - 1], result_.steps = steps_up_to_[seen_ - 1];
  if (result_.energy_drift > settings_.max_energy_drift)
    fail("energy drift " + format_significant(result_.energy_drift, 3) + " of Delta U exceeds " + format_significant(settings_.max_energy_drift, 3) +
         "; tighten {{rtol}} or choose another {{stepper}}");
}

// Where the sling goes slack before the range's release `t` and stays slack up to it (scaled
// time): its tension below 0 from the onset at every step end of phase II up to `t`, and not
// pulling at `t` itself (below 1e-6 of the ball's weight: in vacuum such a peak lies where the
// model's push falls back to 0, to 1e-7 of it; a sling that pulls again before the peak pulled by
// 1e-3 of it or more on a review's random engines). From the onset the model keeps the ball on
// the sling's circle, pushed, where a free ball would fly off: in vacuum its range may still grow
// if the push turns the ball toward the target, and through air on the flight alone it grows as
// the ball is kept out of the drag. The range's release is then the best before the onset
// (docs/verifier.md, "the sling going slack"). A slack that ends before the peak, one in phase I,
// and the other objectives keep the whole window, and are warned.
std::optional<double> ShotRun::slack_up_to_peak(double t) const {
  const auto& samples = phase2_->samples();
  const std::optional<double>& onset = onsets_[0];
  if (criterion_.release != Release::range || !onset || !(*onset > samples.front().t) || !(*onset < t - same_time)) return std::nullopt;
  const auto snapshot_of = [&](const OdeVector& y) { return dynamics_.snapshot(Phase::lifted, lifted_->state(y)); };
  for (const auto& sample : samples)
    if (sample.t > *onset && sample.t <= t && !(conditions_of(Phase::lifted, snapshot_of(phase2_->y_at(sample.t)))[0] < 0)) return std::nullopt;
  if (!(snapshot_of(phase2_->y_exact_at(t)).sling_tension < 1e-6 * e_.mu)) return std::nullopt;
  return onset;
}

Candidate ShotRun::optimal_release() const {
  Candidate found = best_release_before(std::numeric_limits<double>::infinity());
  // Sampled values within round-off of 0 can leave no candidate with the objective above it.
  if (!(found.value > 0)) fail_no_forward_release();
  if (const auto slack = slack_up_to_peak(found.t)) {
    const Candidate before = best_release_before(*slack);
    if (before.value > 0) found = before, found.before_slack = slack;
  }
  return found;
}

// The release search (docs/verifier.md, "Release"). The objective is smooth between the onsets
// of growth of the running extremes, so its maximum over phase II lies at an onset or at the
// maximum of a smooth piece. Every onset of phase II is located on the continuous solution. A
// smooth maximum lies within a step of a step end that is at least as high as both its
// neighbours, as long as no step holds both a minimum and a maximum of one smooth piece: the two
// steps beside each such step end are searched, each on its own (the slope is scanned at the
// step end between them). An onset higher than every candidate so far is searched too, within
// its step. This is the best release of phase II up to `latest` (scaled time; infinity: the
// whole window).
Candidate ShotRun::best_release_before(double latest) const {
  const auto& samples = phase2_->samples();
  const auto objective = [&](double time) { return point_at(time).objective; };
  const auto rate = [&](double time) { return range_rate_at(time); };
  const std::size_t last = samples.size() - 1;
  // The onsets of phase II; none is sought in a step whose ends both have the objective at 0,
  // where the projectile would not fly forward.
  std::vector<PhaseRecord::Onset> onsets_ii;
  for (std::size_t j = 0; j < last; ++j)
    if (sampled_[j] > 0 || sampled_[j + 1] > 0)
      for (const auto& onset : phase2_->growth_onsets(samples[j].t, samples[j + 1].t)) onsets_ii.push_back(onset);
  Candidate found{samples.front().t, 0, std::nullopt, std::nullopt};
  auto search = [&](std::size_t first, std::size_t end) {
    if (!(samples[first].t < latest)) return;
    std::vector<double> scan;
    for (std::size_t i = first + 1; i < end; ++i) scan.push_back(samples[i].t);
    const Candidate c = release_time(objective, rate, samples[first].t, std::min(samples[end].t, latest), scan, onsets_ii);
    if (c.value > found.value) found = c;
  };
  for (std::size_t i = 0; i <= last; ++i) {
    const bool peak = (i == 0 || sampled_[i] >= sampled_[i - 1]) && (i == last || sampled_[i] >= sampled_[i + 1]);
    if (peak && sampled_[i] > 0) search(i > 0 ? i - 1 : 0, std::min(i + 1, last));
  }
  for (const auto& onset : onsets_ii) {
    if (!(onset.t < latest) || !(objective(onset.t) > found.value)) continue;
    const std::size_t step_start = phase2_->base_of(onset.t);
    search(step_start, std::min(step_start + 1, last));
  }
  if (latest < samples.back().t)
    if (const double at_latest = objective(latest); at_latest > found.value) found = {latest, at_latest, std::nullopt, std::nullopt};
  return found;
}

// The slope of the range through air in the release's time, where the release maximises it and
// throws: the flight's own sensitivities (range_rate) along the release's motion, its position's
// rate the projectile's velocity and its velocity's the four-point central difference of that
// velocity on the continuous solution (step 1e-5, as the objective's slope; no flight). nullopt
// elsewhere, and where the flight does not come down ahead of the release (objective_range's 0).
std::optional<double> ShotRun::range_rate_at(double time) const {
  if (criterion_.release != Release::range || !criterion_.drag) return std::nullopt;
  const auto snapshot_at = [&](double t) { return dynamics_.snapshot(Phase::lifted, lifted_->state(phase2_->y_at(t))); };
  ReleasePoint r;
  set_motion(r, e_, snapshot_at(time));
  if (!throws(e_, r)) return std::nullopt;
  constexpr double h = 1e-5;
  const auto velocity_at = [&](double t) { return snapshot_at(t).projectile_velocity; };
  const Vec2 v1 = velocity_at(time + h), v_1 = velocity_at(time - h), v2 = velocity_at(time + 2 * h), v_2 = velocity_at(time - 2 * h);
  const Vec2 acceleration{(8 * (v1.x - v_1.x) - (v2.x - v_2.x)) / (12 * h), (8 * (v1.y - v_1.y) - (v2.y - v_2.y)) / (12 * h)};
  const bool from_release = criterion_.range_from_release;
  const auto flown = range_rate(r.position, r.velocity, flight_drop(r, criterion_),
                                FlightTangent{r.velocity, acceleration, from_release ? 0 : r.velocity.y}, *criterion_.drag, 1);
  if (!flown || !(measured_range(flown->range, r, criterion_) > 0)) return std::nullopt;
  return flown->rate + (from_release ? r.velocity.x : 0);  // measured_range's rate
}

// A given release is the root of its watched value on the continuous solution, within the step
// it was crossed in, each value integrated anew from the step's start (y_exact_at).
double ShotRun::given_release(const GivenWatch& g) const {
  if (g.given.by == ReleaseBy::time) return g.given.value;
  const auto& samples = phase2_->samples();
  const std::size_t i = *g.watch.crossed;
  const auto ahead = [&](double time) {
    const State s = lifted_->state(phase2_->y_exact_at(time));
    return ahead_of(g.given, watched_value(g.given.by, time, dynamics_.snapshot(Phase::lifted, s), g.watch.near));
  };
  return find_root(ahead, samples[i - 1].t, samples[i].t, 1e-13, 0);
}

// The release, given or the optimum, and the state there integrated anew.
void ShotRun::find_release() {
  if (given_) {
    t_release_ = given_release(*given_);
  } else {
    const Candidate found = optimal_release();
    t_release_ = found.t;
    result_.release_at_growth_of = found.at_onset;
    result_.release_before_slack = found.before_slack;
  }
  const OdeVector y_release = phase2_->y_exact_at(t_release_);
  result_.release = point_from(t_release_, y_release);
  result_.work = lifted_->work(y_release);
  if (given_ && !(result_.release.range > 0))
    refuse_given("released there, the projectile does not fly forward from above the engine's base" +
                 (given_->given.by == ReleaseBy::velocity_angle
                      ? std::string()
                      : " (its velocity angle is " + format_significant(degrees(result_.release.velocity_angle), 4) + " deg)"));
  search_end_ = phase2_->samples()[seen_ - 1].t;
}

// The further releases (OtherReleases), each replayed over the samples as its own shot would
// watch it, phase II stepped on until each is two samples past its release (GivenWatch::done)
// or cannot come. The shot's own figures stay as found: its search's end, its drift and steps.
void ShotRun::follow_others(const OtherReleases& others) {
  const auto& samples = phase2_->samples();
  std::vector<GivenWatch> watches;
  std::vector<std::size_t> seen;  // the samples each watch has replayed
  for (const GivenRelease& asked : others(result_.release))
    watches.emplace_back(asked, samples.front().t, snapshots_.front(), throwing_.front(), whips_), seen.push_back(1);
  const auto catch_up = [&] {
    bool waiting = false;
    for (std::size_t k = 0; k < watches.size(); ++k) {
      for (; seen[k] < samples.size(); ++seen[k]) watches[k].add(seen[k], samples[seen[k]].t, snapshots_[seen[k]], throwing_[seen[k]]);
      waiting = waiting || (!watches[k].in_trough && !watches[k].done(samples.size()) && !watches[k].spent());
    }
    return waiting;
  };
  // A step that fails here fails a further release's own shot as well, if it needed the step.
  try {
    while (catch_up() && window_end_.empty()) step_phase_two();
  } catch (const Error&) {
  }
  catch_up();
  for (const GivenWatch& w : watches) {
    std::optional<OtherRelease> other;
    const auto& crossed = w.watch.crossed;
    // Its own shot ends two samples past the release, or where the window ends or a step failed first.
    const bool stepped = crossed && (w.done(samples.size()) || !window_end_.empty() || w.spent());
    if (!w.in_trough && stepped && !(drift_up_to_[std::min(*crossed + 2, samples.size() - 1)] > settings_.max_energy_drift)) {
      const double time = given_release(w);
      const OdeVector at = phase2_->y_exact_at(time);
      const ReleasePoint point = point_from(time, at);
      if (point.range > 0) other = OtherRelease{point, lifted_->work(at)};
    }
    result_.others.push_back(other);
  }
}

// Only what happens before the release invalidates the shot. A free ball keeps its landing
// point wherever along its flight it is let go, so the range's slope in the release time is the
// sling's pull times the range's gradient in the ball's velocity along the sling: the range
// peaks where the tension falls through 0, and its best release is the sling's going slack: a
// slack onset within same_time of the release is the release itself, not a failure before it.
void ShotRun::mark_onsets() {
  auto before_release = [&](const std::optional<double>& t) { return t && *t <= t_release_ ? t : std::nullopt; };
  result_.slack_sling = onsets_[0] && *onsets_[0] < t_release_ - same_time ? onsets_[0] : std::nullopt;
  result_.counterweight_below_base = before_release(onsets_[1]);
  result_.tip_below_base = before_release(onsets_[2]);
  result_.counterweight_pulled = before_release(onsets_[3]);
  result_.rope_bent = before_release(onsets_[4]);
}

// The builder's loads: the largest sampled value of each over the phases (each before the
// release ends on its last sample, phase II on the release), refined once, in its phase.
void ShotRun::find_loads() {
  const auto at_release = load_values(dynamics_.snapshot(Phase::lifted, result_.release.state));
  for (int k = 0; k < load_count; ++k) {
    struct PhasePoints {
      const PhaseRecord* record;
      std::vector<Point> points;
      std::size_t top;
    };
    std::vector<PhasePoints> phases;
    const auto add = [&](const PhaseRecord& record, double t_end, double at_end) {
      std::vector<Point> points = record.load_points(k, t_end, at_end);
      const auto top = std::max_element(points.begin(), points.end(), [](const Point& a, const Point& b) { return a.f < b.f; });
      const auto index = static_cast<std::size_t>(top - points.begin());
      phases.push_back({&record, std::move(points), index});
    };
    if (held_record_) add(*held_record_, *result_.t_counterweight_free, held_record_->samples().back().loads[k]);
    add(*phase1_, result_.t_liftoff, phase1_->samples().back().loads[k]);
    add(*phase2_, t_release_, at_release[k]);
    const PhasePoints* best = &phases.front();
    for (const PhasePoints& c : phases)
      if (c.points[c.top].f > best->points[best->top].f) best = &c;
    result_.loads[k] = best->record->refined_load_peak(k, best->points, best->top);
  }
}

// The counterweight's lowest point: sampled at the step ends of the phases up to the release
// and of phase III after it, then, where the lowest sample has a neighbour on each side, the
// minimum between them, so that it does not depend on where the steps fall: its time on the
// interpolant, its height there on the solution integrated anew. The interpolant's error
// (~1e-7, scaled) moves the time, and the height at a minimum only by its square.
void ShotRun::find_lowest_counterweight() {
  std::vector<Point> heights;
  for (const PhaseRecord* record : {held_record_.get(), &*phase1_, &*phase2_})
    if (record)
      for (const auto& sample : record->samples())
        if (sample.t < t_release_ && (heights.empty() || sample.t > heights.back().x)) heights.push_back({sample.t, sample.counterweight_height});
  heights.push_back({t_release_, dynamics_.snapshot(Phase::lifted, result_.release.state).counterweight_height});
  PhaseIntegrator released(dynamics_, Phase::released, settings_);
  const OdeVector y_iii = released.vector_of(result_.release.state, result_.work);
  std::vector<StepEnd> ends_iii{released.step_end(t_release_, y_iii, dynamics_.snapshot(Phase::released, released.state(y_iii)))};
  result_.phase_iii_cut = follow_released(e_, settings_, result_.release.state, result_.work, t_release_, released,
                                          [&](double, const OdeVector&, double time, const OdeVector& at) {
                                            const Snapshot s = dynamics_.snapshot(Phase::released, released.state(at));
                                            ends_iii.push_back(released.step_end(time, at, s));
                                            heights.push_back({time, s.counterweight_height});
                                          });
  const auto height_at = [&](double time, bool exact) {
    if (time > t_release_) {
      const auto after = std::upper_bound(ends_iii.begin() + 1, ends_iii.end() - 1, time, [](double x, const StepEnd& end) { return x < end.t; });
      const StepEnd& start = *(after - 1);
      const OdeVector y = exact ? released.at(start.t, start.y, time) : hermite(start, *after, time, released.angles(), released.dimension());
      return dynamics_.snapshot(Phase::released, released.state(y)).counterweight_height;
    }
    const PhaseRecord& record = held_record_ && time <= *result_.t_counterweight_free ? *held_record_
        : time <= result_.t_liftoff                                                   ? *phase1_
                                                                                      : *phase2_;
    return (exact ? record.snapshot_exact_at(time) : record.snapshot_at(time)).counterweight_height;
  };
  const auto low = std::min_element(heights.begin(), heights.end(), [](const Point& a, const Point& b) { return a.f < b.f; });
  double lowest = low->f;
  if (low != heights.begin() && low + 1 != heights.end()) {
    const Point estimate = parabola_vertex(*(low - 1), *low, *(low + 1));
    const double t = peak_between([&](double time) { return -height_at(time, false); }, (low - 1)->x, estimate.x, (low + 1)->x, 1e-6, 1e-8);
    lowest = std::min(lowest, height_at(t, true));
  }
  result_.lowest_counterweight = lowest;
}

// The motion up to the release (and phase III after it, with TraceSpan::with_phase_iii); with
// `unreleased`, phase II past the release, as far as the search looked.
void ShotRun::write_trace(std::vector<TracePoint>* trace, double trace_dt, TraceSpan span, std::vector<TracePoint>* unreleased) {
  if (trace) {
    record_trace(trace, *lifted_, *phase2_, result_.t_liftoff, t_release_, trace_dt);
    if (!(trace_dt > 0))  // the continuous record ends on the release already
      trace->push_back({Phase::lifted, t_release_, result_.release.state, dynamics_.snapshot(Phase::lifted, result_.release.state), result_.work});
    if (span == TraceSpan::with_phase_iii)
      trace_released(dynamics_, e_, settings_, result_.release.state, result_.work, t_release_, trace_dt, *trace);
  }
  if (unreleased) {
    std::vector<TracePoint> all;
    record_trace(&all, *lifted_, *phase2_, t_release_, search_end_, trace_dt);
    for (const TracePoint& p : all)
      if (p.t > t_release_) unreleased->push_back(p);
  }
}

}  // namespace

ShotResult simulate_shot(const Machine& dynamics, const ReleaseCriterion& criterion, const IntegratorSettings& settings,
                         std::vector<TracePoint>* trace, double trace_dt, std::vector<TracePoint>* unreleased, bool find_loads,
                         const OtherReleases& others, TraceSpan span) {
  use_gsl_return_codes();
  ShotRun shot(dynamics, criterion, settings, others || criterion.given);
  shot.phase_one(trace, trace_dt);
  shot.phase_two();
  if (criterion.given) shot.begin_given(*criterion.given);
  shot.search_window(unreleased != nullptr);
  shot.find_release();
  if (others) shot.follow_others(others);
  shot.mark_onsets();
  if (find_loads) shot.find_loads(), shot.find_lowest_counterweight();
  shot.write_trace(trace, trace_dt, span, unreleased);
  return shot.result();
}

std::vector<GivenShot> simulate_given_shots(const Machine& dynamics, const ReleaseCriterion& criterion, const IntegratorSettings& settings,
                                            const std::vector<GivenRelease>& releases, bool find_loads) {
  use_gsl_return_codes();
  ShotRun shot(dynamics, criterion, settings, true);
  std::vector<GivenShot> out(releases.size());
  try {
    shot.phase_one(nullptr, 0);
    shot.phase_two();
  } catch (const Error& e) {
    for (GivenShot& given : out) given.error = e;
    return out;
  }
  // Given releases only: the optimum's search (and `unreleased`) reads the samples' objective over
  // the whole trajectory stepped, which is one release's own only where it is the only one.
  for (std::size_t i = 0; i < releases.size(); ++i) {
    try {
      shot.begin_given(releases[i]);
      shot.search_window(false);
      shot.find_release();
      shot.mark_onsets();
      if (find_loads) shot.find_loads(), shot.find_lowest_counterweight();
      out[i].shot = shot.result();
    } catch (const Error& e) {
      out[i].error = e;
    }
  }
  return out;
}

}  // namespace trebuchet
