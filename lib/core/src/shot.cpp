#include "trebuchet/shot.hpp"

#include <algorithm>
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
    samples_.push_back({end, forces, extremes, load_values(snap), snap.counterweight_height});
    if (samples_.size() >= 3) refine_peaks();
    record_onsets(conditions_of(integrator_.phase(), snap));
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
// slope is the four-point central difference with step 1e-5 (scaled time): truncation
// O(step^4) moves the root by ~1e-20, round-off by ~1e-11, relative; a maximum within two steps
// of an onset is taken at the onset, at most Q'' (2e-5)^2/2 below it. Checked against the
// independent reference (tests/test_reference.cpp).
struct Candidate {
  double t;
  double value;
  std::optional<ForceIndex> at_onset;
};
template <class Objective>
Candidate release_time(const Objective& objective, double lo, double hi, const std::vector<double>& scan,
                       const std::vector<PhaseRecord::Onset>& onsets) {
  constexpr double slope_step = 1e-5;
  std::vector<double> ends{lo};
  for (const auto& onset : onsets)
    if (onset.t > lo && onset.t < hi) ends.push_back(onset.t);
  ends.push_back(hi);
  Candidate best{lo, objective(lo), std::nullopt};
  auto consider = [&](double t) {
    const double value = objective(t);
    if (value > best.value) best = {t, value, std::nullopt};
  };
  // The slope, remembered at the scan points, where the root search evaluates it again.
  std::vector<Point> slopes;
  const auto slope = [&](double t) {
    for (const Point& known : slopes)
      if (known.x == t) return known.f;
    const double value = 8 * (objective(t + slope_step) - objective(t - slope_step)) -
        (objective(t + 2 * slope_step) - objective(t - 2 * slope_step));
    slopes.push_back({t, value});
    return value;
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
      if (previous > 0 && !(here > 0))
        if (const auto root = root_between(slope, points[j - 1], points[j], 1e-11, 0)) consider(*root);
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

// The range the release maximises under Release::range: in vacuum from the pivot to the
// criterion's target level (level 0 is the paper's), else through the criterion's drag, or
// Denny's, from the release point to where the flight dips below the release height (section
// 6.3); 0 where the flight never comes down to its end.
double objective_range(const ReleasePoint& r, const ReleaseCriterion& criterion) {
  if (!criterion.drag && !criterion.range_from_release && criterion.target_level == 0) return r.range;
  const double drop = criterion.range_from_release ? 0 : r.height - criterion.target_level;
  double range = 0;
  if (criterion.drag) {
    const auto end = fly(r.position, r.velocity, drop, *criterion.drag, 1);
    if (!end) return 0;
    range = end->range;
  } else {
    if (!(r.velocity.y * r.velocity.y + 2 * drop > 0)) return 0;  // the target level lies above the apex
    range = vacuum_range(r.position, r.velocity, drop, 1);
  }
  range = criterion.range_from_release ? range + r.position.x : range;
  return std::max(range, 0.0);
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
  r.position = snap.projectile;
  r.velocity = snap.projectile_velocity;
  r.height = e.pivot_height() + r.position.y;
  if (r.velocity.x < 0 && r.height >= 0) r.range = vacuum_range(r.position, r.velocity, r.height, 1);  // toward the target, level 0
  r.energy_at_target = energy_at_target(e.mu, r.velocity, r.height);
  r.efficiency = efficiency(r.energy_at_target, e.energy_drop());
  r.extremes = extremes;
  r.force_factor = force_factor(extremes, e.mu);
  r.velocity_angle = velocity_angle(snap);
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

ShotResult simulate_shot(const Machine& dynamics, const ReleaseCriterion& criterion, const IntegratorSettings& settings,
                         std::vector<TracePoint>* trace, double trace_dt, std::vector<TracePoint>* unreleased, bool find_loads,
                         const OtherReleases& others, TraceSpan span) {
  use_gsl_return_codes();
  const ScaledDesign& e = dynamics.design();
  ShotResult result;
  const double energy_scale = e.energy_drop();
  double energy0 = 0;
  // The bodies' energy and the work of the losses balance (with none, the energy is conserved).
  auto track_energy = [&](const Snapshot& s, const Losses& work) {
    double lost = 0;
    for (double w : work) lost += w;
    result.energy_drift = std::max(result.energy_drift, std::abs(s.energy + lost - energy0) / energy_scale);
  };
  // The hinge pin's friction turns with the counterweight's swing relative to the beam, which
  // reverses a few times in a shot. A pin whose friction can hold that swing makes it stick and
  // slip, which Coulomb's law as modelled here (sliding only) leaves out: the turn then reverses
  // at nearly every step, and the shot says so rather than spend its step budget.
  PinWatch pins;
  // Counts an accepted step against the budget; whether the axle's friction now holds the beam.
  // In the whipper's phase held the counterweight does not turn on its pin: nothing to watch.
  auto count_step = [&](const char* phase, const State& s, bool hinge_turns = true) {
    if (++result.steps > settings.max_steps)
      fail("step budget of " + std::to_string(settings.max_steps) + " steps exceeded in " + phase +
           "; loosen {{rtol}} or choose a higher-order {{stepper}}");
    if (hinge_turns && pins.hinge_holds(e, s))
      fail(
          "the hinge pin's friction makes the counterweight stick to the beam and slip, which the model leaves out "
          "(docs/verifier.md, \"Real engines\"); give a smaller {{hinge_friction}} or {{hinge_radius}}");
    return pins.axle_holds(e, s);
  };

  // Phase I: from rest (eq:InitialConditions: phi_i = 0, and psi_i = 0 unless propped) until
  // the trough's normal force vanishes. The whipper starts with a phase `held`, until its
  // counterweight leaves the arm, and its phase I ends where the projectile leaves it.
  const bool whips = dynamics.first_phase() == Phase::held;
  OdeVector y = {dynamics.theta_i(), radians(e.psi_i_deg), 0, 0, 0, 0};
  double t = 0, h = 1e-3;
  Onsets onsets;
  Snapshot snap = dynamics.snapshot(dynamics.first_phase(), State{y[0], y[1], 0, 0, 0, 0});
  // A counterweight propped forward can pull the short arm the wrong way: the shot never starts.
  if (!(snap.theta_ddot > 0)) {
    if (whips)
      fail(
          "the whipper's beam starts to turn backwards, away from the throw: what rests on its arm, the counterweight (or a heavy ball on a "
          "sling longer than the long arm), lies too far behind the pivot; lengthen the counterweight's rope {{L3}}, turn it less off the arm "
          "(a smaller {{rope_angle_deg}}), or lighten the projectile {{m}}");
    if (e.psi_i_deg != 0)
      fail("the beam starts to turn away from the throw (the counterweight, propped at psi_i = " + format_significant(e.psi_i_deg, 4) +
           " deg, pulls the short arm backwards); " +
           (e.psi_i_deg > 0 ? std::string("prop it less, or back ({{psi_i_deg}} < 0)") : std::string("hold it back less ({{psi_i_deg}} nearer 0)")));
    // Hanging, the counterweight is outweighed at rest by what the long arm holds: name what the engine gives of it.
    std::string held = "the projectile {{m}}, the beam {{mb}}";
    if (e.parts.sling.rope > 0) held += ", the sling's rope {{rope_mass}}";
    if (e.parts.sling.pouch > 0) held += ", the pouch {{pouch_mass}}";
    fail("the beam starts to turn away from the throw: at rest, what the long arm holds (" + held +
         ") outweighs the counterweight {{M}} about the pivot; lighten it, or give a heavier {{M}}");
  }
  energy0 = snap.energy;
  // Runs a phase that carries the projectile (and, held, the counterweight) from (t, y) to where
  // its contact lets go: the root of the contact's value on the interpolant, the state there
  // integrated anew from the step start. Returns the time.
  const auto carry = [&](PhaseIntegrator& integrator, PhaseRecord& record) {
    const Phase phase = integrator.phase();
    const auto contact = [&](const Snapshot& at) { return phase == Phase::held ? at.counterweight_on_arm : at.normal_force; };
    if (phase != dynamics.first_phase()) snap = dynamics.snapshot(phase, integrator.state(y));  // the first's is the start's, above
    record.add(integrator.step_end(t, y, snap), snap);
    if (!(contact(snap) > 0)) return t;  // it lets go at once
    while (true) {
      if (!integrator.step(t, y.data(), settings.max_time, h))
        fail(integrator.friction_unsettled() ? unsettled_friction : "integrator failure in phase I; tighten {{rtol}} or choose another {{stepper}}");
      const bool axle_holds = count_step("phase I", integrator.state(y), phase != Phase::held);
      // Friction that stops the beam holds it (Coulomb's law at rest): the engine jams.
      if (axle_holds || (dynamics.dissipates() && !(y[2] > 0)))
        fail(std::string("friction stops the beam before the projectile ") + (whips ? "leaves the arm" : "lifts off") +
             ": the engine jams; give smaller friction coefficients or pin radii ({{axle_friction}}, {{hinge_friction}}, {{trough_friction}})");
      if (dynamics.trough_cos_phi(y[0]) < abandon_trough_cos_phi)
        fail(
            "the sling stands vertical in the trough (phi -> 90 deg) before lift-off; lengthen the sling {{L4}} or lighten what it carries, the "
            "projectile {{m}}" +
            std::string(e.parts.sling.pouch > 0 ? " and the pouch {{pouch_mass}}" : ""));
      snap = dynamics.snapshot(phase, integrator.state(y));
      if (phase == Phase::held && !(snap.normal_force > 0))
        fail(
            "the whipper's projectile would leave the arm before its counterweight, which the model (pytrebuchet's order) leaves out; "
            "lengthen the sling {{L4}} or the counterweight's rope {{L3}}, or turn the rope further off the arm (a larger {{rope_angle_deg}})");
      if (!(contact(snap) > 0)) {
        const StepEnd& before = record.samples().back();
        const StepEnd after = integrator.step_end(t, y, snap);
        auto contact_at = [&](double time) {
          return contact(dynamics.snapshot(phase, integrator.state(hermite(before, after, time, integrator.angles(), integrator.dimension()))));
        };
        t = find_root(contact_at, before.t, t, 1e-13, 0);
        y = integrator.at(before.t, before.y, t);
        snap = dynamics.snapshot(phase, integrator.state(y));
        record.add(integrator.step_end(t, y, snap), snap);
        track_energy(snap, integrator.work(y));
        return t;
      }
      record.add(integrator.step_end(t, y, snap), snap);
      track_energy(snap, integrator.work(y));
      if (y[0] >= dynamics.turn_limit(phase) || t >= settings.max_time)
        fail(phase == Phase::held ? "the whipper's counterweight never leaves the arm; lengthen its rope {{L3}} or change the masses"
                 : whips          ? "the whipper's projectile never leaves the arm; change the sling length {{L4}} or the masses"
                                  : "the projectile never lifts off: the trough still carries it when the beam is upright; "
                                    "change the sling length L4 or the masses");
    }
  };
  std::unique_ptr<PhaseIntegrator> held;
  std::unique_ptr<PhaseRecord> held_record;
  if (whips) {
    held = std::make_unique<PhaseIntegrator>(dynamics, Phase::held, settings);
    held_record = std::make_unique<PhaseRecord>(*held, ForceExtremes{}, onsets);
    result.t_counterweight_free = carry(*held, *held_record);
    record_trace(trace, *held, *held_record, 0, t, trace_dt);
  }
  PhaseIntegrator trough(dynamics, Phase::trough, settings);
  PhaseRecord phase1(trough, held_record ? held_record->samples().back().extremes : ForceExtremes{}, onsets);
  result.t_liftoff = carry(trough, phase1);
  record_trace(trace, trough, phase1, result.t_counterweight_free.value_or(0), t, trace_dt);

  // Phase II from the located lift-off state.
  const State lift = trough.state(y);
  PhaseIntegrator lifted(dynamics, Phase::lifted, settings);
  PhaseRecord phase2(lifted, phase1.samples().back().extremes, onsets);
  const Losses work_at_liftoff = trough.work(y);
  y = {lift.theta, lift.psi, lift.phi, lift.theta_dot, lift.psi_dot, lift.phi_dot};
  for (std::size_t k = 0; k + 6 < lifted.dimension(); ++k) y[6 + k] = work_at_liftoff[k];
  const Snapshot lift_snapshot = dynamics.snapshot(Phase::lifted, lift);
  phase2.add(lifted.step_end(t, y, lift_snapshot), lift_snapshot);
  auto point_from = [&](double time, const OdeVector& state) {
    const State s = lifted.state(state);
    return release_point(e, criterion, time, s, dynamics.snapshot(Phase::lifted, s), phase2.extremes_before(time));
  };
  auto point_at = [&](double time) { return point_from(time, phase2.y_at(time)); };
  // The objective at every step end of phase II, in the order of the samples.
  const ReleasePoint at_liftoff = point_at(t);
  // The highest apex, in vacuum, of the flights that a release at a step end sends forward
  // (scaled, above the base): what a target level above every flight is told.
  double highest_apex = 0;
  std::vector<double> sampled{at_liftoff.objective};
  double best_quality = sampled.front();
  // What a given release watches at each sample (the snapshot, whether a release there throws),
  // and the energy drift up to it: what a further release replays (OtherReleases), kept only
  // when further releases may be asked for.
  const bool thrown_at_liftoff = throws(e, at_liftoff);
  std::vector<Snapshot> snapshots;
  std::vector<char> throwing;
  std::vector<double> drift_up_to;
  const auto keep_for_others = [&](const Snapshot& at, bool thrown) {
    if (others) snapshots.push_back(at), throwing.push_back(thrown), drift_up_to.push_back(result.energy_drift);
  };
  keep_for_others(lift_snapshot, thrown_at_liftoff);
  // A given release watches its value from lift-off on; one already past there would release in the trough.
  // The whipper's projectile leaves the arm falling forward, and its velocity and pin angles turn
  // through a whole turn before the release: a given angle is the first one below their value
  // there, whole turns apart (docs/machines.md, "The whipper").
  std::optional<GivenWatch> given;
  if (criterion.given) given.emplace(*criterion.given, t, lift_snapshot, thrown_at_liftoff, whips);
  h = 1e-3;
  // The release window (docs/verifier.md, "Window"): one for every shot, every form of release
  // and every machine, lossless or not. It ends where the projectile's velocity turns backward
  // after a forward throw (BackwardWatch; located on the continuous solution, where the last
  // sample of phase II is then taken), or where the beam turns over, friction holds it (the
  // machine stops), or the time is out. Where the beam stops turning forward is no end.
  BackwardWatch backward(throws(e, at_liftoff));
  std::string window_end;  // why the window ended, for a given release that never comes
  // One step of phase II; whether the shot ends there.
  const auto step_ends_shot = [&]() {
    const StepEnd step_start = phase2.samples().back();
    if (!lifted.step(t, y.data(), settings.max_time, h))
      fail(lifted.friction_unsettled() ? unsettled_friction : "integrator failure in phase II; tighten {{rtol}} or choose another {{stepper}}");
    State s = lifted.state(y);
    const bool axle_holds = count_step("phase II", s);
    snap = dynamics.snapshot(Phase::lifted, s);
    track_energy(snap, lifted.work(y));
    if (backward.turns_backward(snap)) {
      // The window closes inside this step: the state where the velocity turns, integrated anew from the step's start.
      const StepEnd after = lifted.step_end(t, y, snap);
      const auto forward_at = [&](double time) {
        return BackwardWatch::forward_speed(dynamics.snapshot(Phase::lifted, lifted.state(hermite(step_start, after, time, 3, lifted.dimension()))));
      };
      t = find_root(forward_at, step_start.t, t, 1e-13, 0);
      y = lifted.at(step_start.t, step_start.y, t);
      s = lifted.state(y);
      snap = dynamics.snapshot(Phase::lifted, s);
      window_end = "the projectile's velocity turns backward first";
    }
    const ReleasePoint here = release_point(e, criterion, t, s, snap, phase2.samples().back().extremes);
    phase2.add(lifted.step_end(t, y, snap), snap);
    sampled.push_back(here.objective);
    const bool thrown = throws(e, here);
    keep_for_others(snap, thrown);
    best_quality = std::max(best_quality, here.objective);
    if (here.range > 0) highest_apex = std::max(highest_apex, here.height + std::pow(std::max(here.velocity.y, 0.0), 2) / 2);  // scaled, g = 1
    if (given) given->add(phase2.samples().size() - 1, t, snap, thrown);
    backward.add(thrown);
    if (window_end.empty()) {
      if (s.theta > dynamics.turn_limit(Phase::lifted))
        window_end = "the beam turns over first";
      else if (t >= settings.max_time)
        window_end = "the time runs out first";
      else if (axle_holds)
        window_end = "the axle's friction stops the beam first";
    }
    return !window_end.empty() || (given && given->spent());
  };
  // Past the release: the objective has fallen to half its maximum, or two steps past a given
  // release, so that the running extremes of eq:F before it are refined as an optimum's are.
  // The whipper's projectile first drops off the arm forward, with an objective that peaks near
  // zero, before the beam whips it round: its optimum is sought over the whole forward swing.
  const auto past_release = [&]() {
    // With `unreleased` asked for, phase II goes on as an optimum's window would (to half the
    // objective's best), so that the pictures show what the given release gave up.
    const bool fallen = !whips && best_quality > 0 && sampled.back() < 0.5 * best_quality;
    if (given) return given->done(phase2.samples().size()) && (!unreleased || fallen);
    return fallen;
  };
  bool ended = false;  // the shot ended (not merely past the release)
  while (!(ended = step_ends_shot()) && !past_release()) {
  }
  // A given release that cannot be made is refused with the values the whole swing runs through:
  // where the search stopped past it, the swing is followed on to its end.
  const auto refuse_given = [&](const std::string& what) {
    while (!ended) ended = step_ends_shot();
    refuse_given_release(*criterion.given, given->watch, what, whips);  // the value as given, not moved by whole turns
  };
  if (given && given->in_trough)
    refuse_given(whips ? "the release would come before the projectile leaves the arm"
                       : "the release would come before lift-off, with the projectile still in the trough");
  if (given && !given->watch.crossed)
    refuse_given("the release never comes: " +
                 (window_end.empty() ? std::string("the watched value never reaches it") : "the release window ends, " + window_end));
  // No release with a positive objective: under Release::range with a target level above the
  // base, the flights go forward but none comes down at that level; else none goes forward.
  const auto fail_no_forward_release = [&] {
    if (criterion.release == Release::range && !criterion.range_from_release && criterion.target_level > 0 && highest_apex > 0)
      throw Error(ErrorKind::usage,
                  "{{target_level}} = " + format_significant(criterion.target_level * criterion.length_unit, 4) +
                      " m lies above the flight of every release: the highest apex, in vacuum, is about " +
                      format_significant(highest_apex * criterion.length_unit, 4) + " m above the engine's base" +
                      (criterion.drag ? " (the air lowers it)" : "") + "; give a lower target level");
    fail("no release sends the projectile forward: over phase II it never flies toward the target");
  };
  if (!given && !(best_quality > 0)) fail_no_forward_release();
  if (result.energy_drift > settings.max_energy_drift)
    fail("energy drift " + format_significant(result.energy_drift, 3) + " of Delta U exceeds " + format_significant(settings.max_energy_drift, 3) +
         "; tighten {{rtol}} or choose another {{stepper}}");

  // The release search (docs/verifier.md, "Release"). The objective is smooth between the onsets
  // of growth of the running extremes, so its maximum over phase II lies at an onset or at the
  // maximum of a smooth piece. Every onset of phase II is located on the continuous solution. A
  // smooth maximum lies within a step of a step end that is at least as high as both its
  // neighbours, as long as no step holds both a minimum and a maximum of one smooth piece: the two
  // steps beside each such step end are searched, each on its own (the slope is scanned at the
  // step end between them). An onset higher than every candidate so far is searched too, within
  // its step.
  const auto& samples = phase2.samples();
  const auto optimal_release = [&]() {
    const auto objective = [&](double time) { return point_at(time).objective; };
    const std::size_t last = samples.size() - 1;
    // The onsets of phase II; none is sought in a step whose ends both have the objective at 0,
    // where the projectile would not fly forward.
    std::vector<PhaseRecord::Onset> onsets_ii;
    for (std::size_t j = 0; j < last; ++j)
      if (sampled[j] > 0 || sampled[j + 1] > 0)
        for (const auto& onset : phase2.growth_onsets(samples[j].t, samples[j + 1].t)) onsets_ii.push_back(onset);
    Candidate found{samples.front().t, 0, std::nullopt};
    auto search = [&](std::size_t first, std::size_t end) {
      std::vector<double> scan;
      for (std::size_t i = first + 1; i < end; ++i) scan.push_back(samples[i].t);
      const Candidate c = release_time(objective, samples[first].t, samples[end].t, scan, onsets_ii);
      if (c.value > found.value) found = c;
    };
    for (std::size_t i = 0; i <= last; ++i) {
      const bool peak = (i == 0 || sampled[i] >= sampled[i - 1]) && (i == last || sampled[i] >= sampled[i + 1]);
      if (peak && sampled[i] > 0) search(i > 0 ? i - 1 : 0, std::min(i + 1, last));
    }
    for (const auto& onset : onsets_ii) {
      if (!(objective(onset.t) > found.value)) continue;
      const std::size_t step_start = phase2.base_of(onset.t);
      search(step_start, std::min(step_start + 1, last));
    }
    // Sampled values within round-off of 0 can leave no candidate with the objective above it.
    if (!(found.value > 0)) fail_no_forward_release();
    return found;
  };
  // A given release is the root of its watched value on the continuous solution, within the step
  // it was crossed in, each value integrated anew from the step's start (y_exact_at).
  const auto given_release = [&](const GivenWatch& g) {
    if (g.given.by == ReleaseBy::time) return g.given.value;
    const std::size_t i = *g.watch.crossed;
    const auto ahead = [&](double time) {
      const State s = lifted.state(phase2.y_exact_at(time));
      return ahead_of(g.given, watched_value(g.given.by, time, dynamics.snapshot(Phase::lifted, s), g.watch.near));
    };
    return find_root(ahead, samples[i - 1].t, samples[i].t, 1e-13, 0);
  };
  double t_release = 0;
  if (given) {
    t_release = given_release(*given);
  } else {
    const Candidate found = optimal_release();
    t_release = found.t;
    result.release_at_growth_of = found.at_onset;
  }
  const OdeVector y_release = phase2.y_exact_at(t_release);
  result.release = point_from(t_release, y_release);
  result.work = lifted.work(y_release);
  if (given && !(result.release.range > 0))
    refuse_given("released there, the projectile does not fly forward from above the engine's base" +
                 (given->given.by == ReleaseBy::velocity_angle
                      ? std::string()
                      : " (its velocity angle is " + format_significant(degrees(result.release.velocity_angle), 4) + " deg)"));
  // The further releases (OtherReleases), each replayed over the samples as its own shot would
  // watch it, phase II stepped on until each is two samples past its release (GivenWatch::done)
  // or cannot come. The shot's own figures stay as found: its search's end, its drift and steps.
  const double search_end = samples.back().t;
  if (others) {
    const double drift = result.energy_drift;
    const long steps = result.steps;
    std::vector<GivenWatch> watches;
    std::vector<std::size_t> seen;  // the samples each watch has replayed
    for (const GivenRelease& asked : others(result.release))
      watches.emplace_back(asked, samples.front().t, snapshots.front(), throwing.front(), whips), seen.push_back(1);
    const auto catch_up = [&] {
      bool waiting = false;
      for (std::size_t k = 0; k < watches.size(); ++k) {
        for (; seen[k] < samples.size(); ++seen[k]) watches[k].add(seen[k], samples[seen[k]].t, snapshots[seen[k]], throwing[seen[k]]);
        waiting = waiting || (!watches[k].in_trough && !watches[k].done(samples.size()) && !watches[k].spent());
      }
      return waiting;
    };
    // A step that fails here fails a further release's own shot as well, if it needed the step.
    try {
      while (catch_up() && window_end.empty()) step_ends_shot();
    } catch (const Error&) {
    }
    catch_up();
    for (const GivenWatch& w : watches) {
      std::optional<OtherRelease> other;
      const auto& crossed = w.watch.crossed;
      // Its own shot ends two samples past the release, or where the window ends or a step failed first.
      const bool stepped = crossed && (w.done(samples.size()) || !window_end.empty() || w.spent());
      if (!w.in_trough && stepped && !(drift_up_to[std::min(*crossed + 2, samples.size() - 1)] > settings.max_energy_drift)) {
        const double time = given_release(w);
        const OdeVector at = phase2.y_exact_at(time);
        const ReleasePoint point = point_from(time, at);
        if (point.range > 0) other = OtherRelease{point, lifted.work(at)};
      }
      result.others.push_back(other);
    }
    result.energy_drift = drift, result.steps = steps;
  }
  // Only what happens before the release invalidates the shot.
  auto before_release = [&](const std::optional<double>& t) { return t && *t <= t_release ? t : std::nullopt; };
  result.slack_sling = before_release(onsets[0]);
  result.counterweight_below_base = before_release(onsets[1]);
  result.tip_below_base = before_release(onsets[2]);
  result.counterweight_pulled = before_release(onsets[3]);
  result.rope_bent = before_release(onsets[4]);
  // The builder's loads: the largest sampled value of each over the phases (each before the
  // release ends on its last sample, phase II on the release), refined once, in its phase.
  const auto at_release = load_values(dynamics.snapshot(Phase::lifted, result.release.state));
  for (int k = 0; k < (find_loads ? load_count : 0); ++k) {
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
    if (held_record) add(*held_record, *result.t_counterweight_free, held_record->samples().back().loads[k]);
    add(phase1, result.t_liftoff, phase1.samples().back().loads[k]);
    add(phase2, t_release, at_release[k]);
    const PhasePoints* best = &phases.front();
    for (const PhasePoints& c : phases)
      if (c.points[c.top].f > best->points[best->top].f) best = &c;
    result.loads[k] = best->record->refined_load_peak(k, best->points, best->top);
  }
  if (find_loads) {
    // The counterweight's lowest point: sampled at the step ends of the phases up to the release
    // and of phase III after it, then, where the lowest sample has a neighbour on each side, the
    // minimum between them, so that it does not depend on where the steps fall: its time on the
    // interpolant, its height there on the solution integrated anew. The interpolant's error
    // (~1e-7, scaled) moves the time, and the height at a minimum only by its square.
    std::vector<Point> heights;
    for (const PhaseRecord* record : {held_record.get(), &phase1, &phase2})
      if (record)
        for (const auto& sample : record->samples())
          if (sample.t < t_release && (heights.empty() || sample.t > heights.back().x)) heights.push_back({sample.t, sample.counterweight_height});
    heights.push_back({t_release, dynamics.snapshot(Phase::lifted, result.release.state).counterweight_height});
    PhaseIntegrator released(dynamics, Phase::released, settings);
    const OdeVector y_iii = released.vector_of(result.release.state, result.work);
    std::vector<StepEnd> ends_iii{released.step_end(t_release, y_iii, dynamics.snapshot(Phase::released, released.state(y_iii)))};
    result.phase_iii_cut = follow_released(e, settings, result.release.state, result.work, t_release, released,
                                           [&](double, const OdeVector&, double time, const OdeVector& at) {
                                             const Snapshot s = dynamics.snapshot(Phase::released, released.state(at));
                                             ends_iii.push_back(released.step_end(time, at, s));
                                             heights.push_back({time, s.counterweight_height});
                                           });
    const auto height_at = [&](double time, bool exact) {
      if (time > t_release) {
        const auto after = std::upper_bound(ends_iii.begin() + 1, ends_iii.end() - 1, time, [](double x, const StepEnd& end) { return x < end.t; });
        const StepEnd& start = *(after - 1);
        const OdeVector y = exact ? released.at(start.t, start.y, time) : hermite(start, *after, time, released.angles(), released.dimension());
        return dynamics.snapshot(Phase::released, released.state(y)).counterweight_height;
      }
      const PhaseRecord& record = held_record && time <= *result.t_counterweight_free ? *held_record : time <= result.t_liftoff ? phase1 : phase2;
      return (exact ? record.snapshot_exact_at(time) : record.snapshot_at(time)).counterweight_height;
    };
    const auto low = std::min_element(heights.begin(), heights.end(), [](const Point& a, const Point& b) { return a.f < b.f; });
    double lowest = low->f;
    if (low != heights.begin() && low + 1 != heights.end()) {
      const Point estimate = parabola_vertex(*(low - 1), *low, *(low + 1));
      const double t = peak_between([&](double time) { return -height_at(time, false); }, (low - 1)->x, estimate.x, (low + 1)->x, 1e-6, 1e-8);
      lowest = std::min(lowest, height_at(t, true));
    }
    result.lowest_counterweight = lowest;
  }
  if (trace) {
    record_trace(trace, lifted, phase2, result.t_liftoff, t_release, trace_dt);
    if (!(trace_dt > 0))  // the continuous record ends on the release already
      trace->push_back({Phase::lifted, t_release, result.release.state, dynamics.snapshot(Phase::lifted, result.release.state), result.work});
    if (span == TraceSpan::with_phase_iii) trace_released(dynamics, e, settings, result.release.state, result.work, t_release, trace_dt, *trace);
  }
  if (unreleased) {  // phase II past the release, as far as the search looked
    std::vector<TracePoint> all;
    record_trace(&all, lifted, phase2, t_release, search_end, trace_dt);
    for (const TracePoint& p : all)
      if (p.t > t_release) unreleased->push_back(p);
  }
  return result;
}

}  // namespace trebuchet
