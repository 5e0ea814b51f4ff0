#include "trebuchet/shot.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>

#include "trebuchet/error.hpp"
#include "trebuchet/gsl_errors.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/solve_1d.hpp"

namespace trebuchet {
namespace {

// Phase I integrates (th, psi, th', psi'); phase II (th, psi, phi, th', psi', phi').
// Phase I is singular where the sling stands vertical (cos phi = 0 in eq:EOM_I_1). A shot
// whose accepted state passes cos phi = 0.02 (phi > 88.9 deg) is abandoned, before the step
// control loses accuracy there; trial states below half of that are refused, so GSL shortens
// the step rather than evaluate the equations near the singularity.
constexpr double abandon_trough_cos_phi = 0.02;
constexpr double refuse_trough_cos_phi = 0.01;
struct OdeContext {
  const ScaledEngine* engine;
  Phase phase;
};

// The integrated variables; phases I and III use the first four. Fixed size: no allocation per use.
using OdeVector = std::array<double, 6>;

std::size_t dimension_of(Phase phase) { return phase == Phase::lifted ? 6 : 4; }

State state_of(const OdeContext& c, const double y[], bool& ok) {
  State s;
  ok = true;
  if (c.phase != Phase::lifted) {  // (th, psi, th', psi')
    s.theta = y[0], s.psi = y[1], s.theta_dot = y[2], s.psi_dot = y[3];
    if (c.phase == Phase::trough) ok = complete_trough_state(*c.engine, s) > refuse_trough_cos_phi;
  } else {
    s.theta = y[0], s.psi = y[1], s.phi = y[2], s.theta_dot = y[3], s.psi_dot = y[4], s.phi_dot = y[5];
  }
  return s;
}

int equations(double, const double y[], double dydt[], void* params) {
  auto* c = static_cast<OdeContext*>(params);
  bool ok = true;
  const State s = state_of(*c, y, ok);
  if (!ok) return GSL_FAILURE;  // a trial state near the singularity: GSL retries with a shorter step
  const auto a = accelerations(*c->engine, c->phase, s);
  if (c->phase != Phase::lifted) {
    dydt[0] = s.theta_dot, dydt[1] = s.psi_dot, dydt[2] = a[0], dydt[3] = a[1];
  } else {
    dydt[0] = s.theta_dot, dydt[1] = s.psi_dot, dydt[2] = s.phi_dot, dydt[3] = a[0], dydt[4] = a[1], dydt[5] = a[2];
  }
  return GSL_SUCCESS;
}

// The Jacobian for the implicit steppers, by forward differences of `equations` (the system is
// autonomous, so df/dt = 0). Step sqrt(machine epsilon) relative: about 8 good digits, which
// is all a Newton iteration needs.
int jacobian(double t, const double y[], double* dfdy, double dfdt[], void* params) {
  const std::size_t n = dimension_of(static_cast<OdeContext*>(params)->phase);
  std::array<double, 6> f0{}, f1{}, shifted{};
  if (equations(t, y, f0.data(), params) != GSL_SUCCESS) return GSL_FAILURE;
  for (std::size_t j = 0; j < n; ++j) {
    std::copy(y, y + n, shifted.begin());
    const double h = 1.5e-8 * std::max(1.0, std::abs(y[j]));
    shifted[j] += h;
    if (equations(t, shifted.data(), f1.data(), params) != GSL_SUCCESS) return GSL_FAILURE;
    for (std::size_t i = 0; i < n; ++i) dfdy[i * n + j] = (f1[i] - f0[i]) / h;
  }
  for (std::size_t i = 0; i < n; ++i) dfdt[i] = 0;
  return GSL_SUCCESS;
}

const gsl_odeiv2_step_type* stepper_type(const std::string& name) {
  for (const auto& [known, type] : std::initializer_list<std::pair<const char*, const gsl_odeiv2_step_type*>>{
           {"rk2", gsl_odeiv2_step_rk2}, {"rk4", gsl_odeiv2_step_rk4}, {"rkf45", gsl_odeiv2_step_rkf45},
           {"rkck", gsl_odeiv2_step_rkck}, {"rk8pd", gsl_odeiv2_step_rk8pd}, {"msadams", gsl_odeiv2_step_msadams},
           {"rk1imp", gsl_odeiv2_step_rk1imp}, {"rk2imp", gsl_odeiv2_step_rk2imp}, {"rk4imp", gsl_odeiv2_step_rk4imp},
           {"bsimp", gsl_odeiv2_step_bsimp}, {"msbdf", gsl_odeiv2_step_msbdf}})
    if (name == known) return type;
  throw Error(ErrorKind::usage, "--stepper: '" + name + "' is not a stepper; use " + stepper_names());
}

using DriverPtr = std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)>;

// One phase: a driver for stepping and a second one for evaluating the solution between steps.
class PhaseIntegrator {
 public:
  PhaseIntegrator(const ScaledEngine& engine, Phase phase, const IntegratorSettings& settings)
      : context_{&engine, phase},
        system_{equations, jacobian, dimension_of(phase), &context_},
        stepping_(make(settings), gsl_odeiv2_driver_free),
        evaluating_(make(settings), gsl_odeiv2_driver_free) {}

  // One accepted step toward t_end; false when the equations failed.
  bool step(double& t, double y[], double t_end, double& h) {
    gsl_odeiv2_driver* d = stepping_.get();
    return gsl_odeiv2_evolve_apply(d->e, d->c, d->s, &system_, &t, t_end, &h, y) == GSL_SUCCESS;
  }

  // The solution at t1, from a stored step start (t0, y0): integrated anew to the same tolerance.
  OdeVector at(double t0, const OdeVector& y0, double t1) {
    OdeVector y = y0;
    if (t1 <= t0) return y;
    gsl_odeiv2_driver_reset_hstart(evaluating_.get(), t1 - t0);
    double t = t0;
    if (gsl_odeiv2_driver_apply(evaluating_.get(), &t, t1, y.data()) != GSL_SUCCESS)
      throw Error(ErrorKind::numerical, "integrator failure while evaluating between steps; tighten --rtol");
    return y;
  }

  std::size_t dimension() const { return system_.dimension; }

  State state(const OdeVector& y) const {
    bool ok = true;
    return state_of(context_, y.data(), ok);
  }

  // y' = f(y): the angular speeds and accelerations at a step end, for the interpolant.
  OdeVector derivative(const OdeVector& y) {
    OdeVector dy{};
    if (equations(0, y.data(), dy.data(), &context_) != GSL_SUCCESS)
      throw Error(ErrorKind::numerical, "the equations of motion failed at an accepted state; tighten --rtol");
    return dy;
  }

 private:
  gsl_odeiv2_driver* make(const IntegratorSettings& settings) {
    return gsl_odeiv2_driver_alloc_y_new(&system_, stepper_type(settings.stepper), 1e-3, settings.atol, settings.rtol);
  }
  OdeContext context_;
  gsl_odeiv2_system system_;
  DriverPtr stepping_, evaluating_;
};

// The forces that enter eq:F, at one moment, in Mg. Each is maximised over [0, t]; the
// horizontal pivot reaction is tracked both ways (its largest and its smallest value).
constexpr int force_count = 4;
using ForceValues = std::array<double, force_count>;  // F_S_perp, |F_R|, F_Rh, -F_Rh

ForceValues force_values(const Snapshot& s) {
  return {s.sling_perpendicular, std::hypot(s.pivot_reaction.x, s.pivot_reaction.y), s.pivot_reaction.x, -s.pivot_reaction.x};
}

struct ForceExtremes {
  ForceValues max{0, 0, 0, 0};
  void add(const ForceValues& v) {
    for (int k = 0; k < force_count; ++k) max[k] = std::max(max[k], v[k]);
  }
};

// A step end: time, state y = (angles q, angular speeds q') and y' = (q', q'').
struct StepEnd {
  double t;
  OdeVector y, dy;
};

// Between two step ends, each angle follows the quintic Hermite interpolant that matches q, q'
// and q'' at both ends, and each angular speed is that interpolant's derivative. Errors are
// O(h^6) in q and O(h^5) in q', far below the integrator's tolerance for rk8pd's steps.
OdeVector hermite(const StepEnd& a, const StepEnd& b, double time, std::size_t n) {
  const double h = b.t - a.t, s = (time - a.t) / h;
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  const double h0 = 1 - 10 * s3 + 15 * s4 - 6 * s5, h1 = s - 6 * s3 + 8 * s4 - 3 * s5;
  const double h2 = 0.5 * s2 - 1.5 * s3 + 1.5 * s4 - 0.5 * s5, h3 = 0.5 * s3 - s4 + 0.5 * s5;
  const double h4 = -4 * s3 + 7 * s4 - 3 * s5, h5 = 10 * s3 - 15 * s4 + 6 * s5;
  const double d0 = -30 * s2 + 60 * s3 - 30 * s4, d1 = 1 - 18 * s2 + 32 * s3 - 15 * s4;  // d/ds of h0, h1, ...
  const double d2 = s - 4.5 * s2 + 6 * s3 - 2.5 * s4, d3 = 1.5 * s2 - 4 * s3 + 2.5 * s4;
  const double d4 = -12 * s2 + 28 * s3 - 15 * s4, d5 = 30 * s2 - 60 * s3 + 30 * s4;
  const std::size_t angles = n / 2;
  OdeVector y{};
  for (std::size_t i = 0; i < angles; ++i) {
    const double q0 = a.y[i], v0 = a.y[angles + i], acc0 = a.dy[angles + i];
    const double q1 = b.y[i], v1 = b.y[angles + i], acc1 = b.dy[angles + i];
    y[i] = h0 * q0 + h * h1 * v0 + h * h * h2 * acc0 + h * h * h3 * acc1 + h * h4 * v1 + h5 * q1;
    y[angles + i] = (d0 * q0 + h * d1 * v0 + h * h * d2 * acc0 + h * h * d3 * acc1 + h * d4 * v1 + d5 * q1) / h;
  }
  return y;
}

// The samples of one phase at the integrator's step ends, with the running force extremes
// refined on the continuous solution: where a force has a local maximum at a step end, the
// true peak lies within the two neighbouring steps and is found there by Brent's method.
class PhaseRecord {
 public:
  struct Sample : StepEnd {
    ForceValues forces;
    ForceExtremes extremes;  // over [0, t], refined peaks included
  };
  struct Peak {
    double t;
    ForceValues forces;
  };

  PhaseRecord(const ScaledEngine& engine, Phase phase, PhaseIntegrator& integrator, ForceExtremes before)
      : engine_(engine), phase_(phase), integrator_(integrator), before_(before) {}

  void add(const StepEnd& end, const Snapshot& snap) {
    const ForceValues forces = force_values(snap);
    ForceExtremes extremes = samples_.empty() ? before_ : samples_.back().extremes;
    extremes.add(forces);
    samples_.push_back({end, forces, extremes});
    if (samples_.size() >= 3) refine_peaks();
  }

  const std::vector<Sample>& samples() const { return samples_; }

  // The state at `time` from the interpolant between the samples around it.
  OdeVector y_at(double time) const {
    const std::size_t base = base_of(time);
    if (time <= samples_[base].t || base + 1 == samples_.size()) return y_exact_at(time);
    return hermite(samples_[base], samples_[base + 1], time, integrator_.dimension());
  }

  // The state at `time`, integrated anew from the last sample at or before it.
  OdeVector y_exact_at(double time) const {
    const Sample& base = samples_[base_of(time)];
    return integrator_.at(base.t, base.y, time);
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
  // The last sample at or before `time` (the first one for earlier times); samples are in time order.
  std::size_t base_of(double time) const {
    const auto after = std::upper_bound(samples_.begin() + 1, samples_.end(), time,
                                        [](double value, const Sample& sample) { return value < sample.t; });
    return static_cast<std::size_t>(after - samples_.begin()) - 1;
  }

  ForceValues forces_at(double time) const {
    return force_values(snapshot(engine_, phase_, integrator_.state(y_at(time))));
  }

  // A force peaking at the middle one of the last three samples peaks between the outer two.
  // A peak that stays well below the running maximum before it cannot change any later
  // maximum and is skipped: the parabola through the three samples estimates it, and 1 %
  // covers that estimate's error. Time tolerance 1e-7 (scaled): the peak value is quadratic in
  // it, so it is exact to 1e-14.
  void refine_peaks() {
    const std::size_t mid = samples_.size() - 2;
    const Sample &a = samples_[mid - 1], &b = samples_[mid], &c = samples_[mid + 1];
    for (int k = 0; k < force_count; ++k) {
      const double fa = a.forces[k], fb = b.forces[k], fc = c.forces[k];
      if (!(fb > fa && fb >= fc)) continue;
      if (parabola_peak(a.t, fa, b.t, fb, c.t, fc) < 0.99 * a.extremes.max[k]) continue;
      const double t_peak = find_maximum([&](double time) { return forces_at(time)[k]; }, a.t, b.t, c.t, 1e-7);
      const Peak peak{t_peak, forces_at(t_peak)};
      peaks_.push_back(peak);
      for (std::size_t s = mid - 1; s < samples_.size(); ++s)
        if (samples_[s].t >= t_peak) samples_[s].extremes.add(peak.forces);
    }
  }

  // The largest value of the parabola through three points with y1 >= y0, y2.
  static double parabola_peak(double x0, double y0, double x1, double y1, double x2, double y2) {
    const double d0 = (y1 - y0) / (x1 - x0), d1 = (y2 - y1) / (x2 - x1);
    const double curvature = (d1 - d0) / (x2 - x0);  // half the second derivative
    if (!(curvature < 0)) return y1;
    const double slope_mid = d0 + curvature * (x1 - x0);  // derivative at x1
    return y1 - slope_mid * slope_mid / (4 * curvature);
  }

  const ScaledEngine& engine_;
  Phase phase_;
  PhaseIntegrator& integrator_;
  ForceExtremes before_;
  std::vector<Sample> samples_;
  std::vector<Peak> peaks_;
};

ReleasePoint release_point(const ScaledEngine& e, const Quality& quality, double t, const State& s,
                           const Snapshot& snap, ForceExtremes extremes) {
  extremes.add(force_values(snap));
  ReleasePoint r;
  r.t = t;
  r.state = s;
  r.position = snap.projectile;
  r.velocity = snap.projectile_velocity;
  r.height = e.l * std::cos(e.theta_i) + r.position.y;
  const double vx = r.velocity.x, vy = r.velocity.y;
  if (vx < 0 && r.height >= 0) r.range = vacuum_range(r.position, r.velocity, r.height, 1);  // toward the target, level 0
  r.energy_at_target = e.mu * (0.5 * (vx * vx + vy * vy) + r.height);  // eq:T
  r.efficiency = r.energy_at_target / e.energy_drop();                  // eq:Aux
  r.sling_perpendicular_max = extremes.max[0];
  r.pivot_reaction_max = extremes.max[1];
  r.pivot_horizontal_max = extremes.max[2];
  r.pivot_horizontal_min = -extremes.max[3];
  const double sling = r.sling_perpendicular_max / e.mu;  // F_S_perp / (m g)
  const double spread = r.pivot_horizontal_max - r.pivot_horizontal_min;
  r.force_factor = std::pow(sling * sling * r.pivot_reaction_max * spread, 0.25);  // eq:F
  if (r.range > 0) {
    r.quality = r.range / e.l * e.mu * std::pow(r.efficiency, quality.n) / r.force_factor;  // eq:Q, eq:Q_n
    switch (quality.release) {
      case Quality::Release::quality: r.objective = r.quality; break;
      case Quality::Release::efficiency: r.objective = r.efficiency; break;
      case Quality::Release::range: r.objective = r.range; break;
    }
  }
  return r;
}

[[noreturn]] void fail(const std::string& reason) { throw Error(ErrorKind::numerical, reason); }

void record_trace(std::vector<TracePoint>* trace, const ScaledEngine& e, Phase phase, PhaseIntegrator& integrator,
                  const std::vector<PhaseRecord::Sample>& samples, double t_end) {
  if (!trace) return;
  for (const auto& sample : samples) {
    if (sample.t > t_end) break;
    const State s = integrator.state(sample.y);
    trace->push_back({phase, sample.t, s, snapshot(e, phase, s)});
  }
}

// Phase III for the series: beam and counterweight without the projectile (mu = 0), from the
// release for as long again as the shot took, so that the ringing of appendix B shows.
void trace_released(const ScaledEngine& e, const IntegratorSettings& settings, const State& release, double t_release,
                    std::vector<TracePoint>& trace) {
  PhaseIntegrator released(e, Phase::released, settings);
  OdeVector y = {release.theta, release.psi, release.theta_dot, release.psi_dot, 0, 0};
  double t = t_release, h = 1e-3;
  for (long steps = 0; t < 2 * t_release && steps < settings.max_steps; ++steps) {
    if (!released.step(t, y.data(), 2 * t_release, h)) fail("integrator failure in phase III; tighten --rtol");
    const State s = released.state(y);
    trace.push_back({Phase::released, t, s, snapshot(e, Phase::released, s)});
  }
}

}  // namespace

std::string stepper_names() { return "rk2, rk4, rkf45, rkck, rk8pd, msadams, rk1imp, rk2imp, rk4imp, bsimp or msbdf"; }

ShotResult simulate_shot(const ScaledEngine& e, const Quality& quality, const IntegratorSettings& settings,
                         std::vector<TracePoint>* trace) {
  use_gsl_return_codes();
  if (!(1 - e.mu_b * (e.l - 1) / 2 > 0))
    fail("the beam cannot turn: mu_b (l - 1)/2 = " + format_significant(e.mu_b * (e.l - 1) / 2, 4) +
         " >= 1, its long arm outweighs the counterweight (eq:DU); lighten the beam or shorten L1");
  ShotResult result;
  const double energy_scale = e.energy_drop();
  double energy0 = 0;
  auto track_energy = [&](const Snapshot& s) { result.energy_drift = std::max(result.energy_drift, std::abs(s.energy - energy0) / energy_scale); };
  auto count_step = [&](const char* phase) {
    if (++result.steps > settings.max_steps)
      fail("step budget of " + std::to_string(settings.max_steps) + " steps exceeded in " + phase +
           "; loosen --rtol or choose a higher-order --stepper");
  };

  // Phase I: from rest (psi_i = phi_i = 0, section 2) until the trough's normal force vanishes.
  PhaseIntegrator trough(e, Phase::trough, settings);
  PhaseRecord phase1(e, Phase::trough, trough, ForceExtremes{});
  auto step_end = [](PhaseIntegrator& integrator, double time, const OdeVector& state) {
    return StepEnd{time, state, integrator.derivative(state)};
  };
  OdeVector y = {e.theta_i, 0, 0, 0, 0, 0};
  double t = 0, h = 1e-3;
  Snapshot snap = snapshot(e, Phase::trough, trough.state(y));
  energy0 = snap.energy;
  phase1.add(step_end(trough, t, y), snap);
  while (true) {
    if (!trough.step(t, y.data(), settings.max_time, h)) fail("integrator failure in phase I; tighten --rtol or choose another --stepper");
    count_step("phase I");
    if (std::cos(trough.state(y).phi) < abandon_trough_cos_phi)
      fail("the sling stands vertical in the trough (phi -> 90 deg) before lift-off; lengthen the sling L4 or lighten the projectile m");
    snap = snapshot(e, Phase::trough, trough.state(y));
    if (snap.normal_force <= 0) {
      // Lift-off inside this step: the root of the normal force on the interpolant, then the
      // state there integrated anew from the step start.
      const StepEnd& before = phase1.samples().back();
      const StepEnd after = step_end(trough, t, y);
      auto normal_at = [&](double time) { return snapshot(e, Phase::trough, trough.state(hermite(before, after, time, 4))).normal_force; };
      result.t_liftoff = find_root(normal_at, before.t, t, 1e-13, 0);
      y = trough.at(before.t, before.y, result.t_liftoff);
      t = result.t_liftoff;
      snap = snapshot(e, Phase::trough, trough.state(y));
      phase1.add(step_end(trough, t, y), snap);
      track_energy(snap);
      break;
    }
    phase1.add(step_end(trough, t, y), snap);
    track_energy(snap);
    if (y[0] >= M_PI || t >= settings.max_time)
      fail("the projectile never lifts off: the trough still carries it when the beam is upright; "
           "change the sling length L4 or the masses");
  }
  record_trace(trace, e, Phase::trough, trough, phase1.samples(), t);

  // Phase II from the located lift-off state.
  const State lift = trough.state(y);
  PhaseIntegrator lifted(e, Phase::lifted, settings);
  PhaseRecord phase2(e, Phase::lifted, lifted, phase1.samples().back().extremes);
  y = {lift.theta, lift.psi, lift.phi, lift.theta_dot, lift.psi_dot, lift.phi_dot};
  phase2.add(step_end(lifted, t, y), snapshot(e, Phase::lifted, lift));
  auto point_from = [&](double time, const OdeVector& state) {
    const State s = lifted.state(state);
    return release_point(e, quality, time, s, snapshot(e, Phase::lifted, s), phase2.extremes_before(time));
  };
  auto point_at = [&](double time) { return point_from(time, phase2.y_at(time)); };
  std::size_t best = 0;
  double best_quality = point_at(t).objective;
  h = 1e-3;
  while (true) {
    if (!lifted.step(t, y.data(), settings.max_time, h)) fail("integrator failure in phase II; tighten --rtol or choose another --stepper");
    count_step("phase II");
    const State s = lifted.state(y);
    snap = snapshot(e, Phase::lifted, s);
    track_energy(snap);
    const double quality_here = release_point(e, quality, t, s, snap, phase2.samples().back().extremes).objective;
    phase2.add(step_end(lifted, t, y), snap);
    if (quality_here > best_quality) {
      best_quality = quality_here;
      best = phase2.samples().size() - 1;
    }
    // Past the maximum: the objective has fallen to half of it, or the beam has turned over.
    if ((best_quality > 0 && quality_here < 0.5 * best_quality) || s.theta > e.theta_i + 2 * M_PI || t >= settings.max_time) break;
  }
  if (!(best_quality > 0)) fail("no release sends the projectile forward: over phase II it never flies toward the target");
  if (result.energy_drift > settings.max_energy_drift)
    fail("energy drift " + format_significant(result.energy_drift, 3) + " of Delta U exceeds " +
         format_significant(settings.max_energy_drift, 3) + "; tighten --rtol or choose another --stepper");

  // The maximum of the objective on the interpolant between the neighbouring samples; the
  // state there is then integrated anew from the step start.
  const auto& samples = phase2.samples();
  // The bracket spans at least 4 slope steps of 1e-5 (scaled time), which puts the argmax to
  // ~1e-10 in time: truncation ~ step^2, round-off ~ 1e-16/step.
  const double slope_step = 1e-5;
  std::size_t lo = best > 0 ? best - 1 : 0, hi = std::min(best + 1, samples.size() - 1);
  while (samples[hi].t - samples[lo].t < 4 * slope_step && (lo > 0 || hi + 1 < samples.size())) {
    if (lo > 0) --lo;
    if (hi + 1 < samples.size()) ++hi;
  }
  const double t_release = find_argmax([&](double time) { return point_at(time).objective; }, samples[lo].t,
                                       samples[best].t, samples[hi].t, slope_step, 1e-13);
  result.release = point_from(t_release, phase2.y_exact_at(t_release));
  if (trace) {
    record_trace(trace, e, Phase::lifted, lifted, samples, t_release);
    trace->push_back({Phase::lifted, t_release, result.release.state, snapshot(e, Phase::lifted, result.release.state)});
    trace_released(e, settings, result.release.state, t_release, *trace);
  }
  return result;
}

std::string release_name(Quality::Release release) {
  switch (release) {
    case Quality::Release::quality: return "Q";
    case Quality::Release::efficiency: return "eps";
    case Quality::Release::range: return "range";
  }
  return "?";
}

Quality::Release parse_release(const std::string& name) {
  for (Quality::Release r : {Quality::Release::quality, Quality::Release::efficiency, Quality::Release::range})
    if (name == release_name(r)) return r;
  throw Error(ErrorKind::usage, "--quality: '" + name + "' is not a release criterion; use Q (eq:Q, eq:Q_n with --n), eps or range");
}

}  // namespace trebuchet
