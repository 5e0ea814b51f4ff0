#include "trebuchet/shot.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/solve_1d.hpp"

namespace trebuchet {
namespace {

// Phase I integrates (th, psi, th', psi'); phase II (th, psi, phi, th', psi', phi').
// Phase I is singular where the sling stands vertical (cos phi = 0 in eq:EOM_I_1); it is
// abandoned below this cos phi (phi > 88.9 deg), before the step control loses accuracy there.
constexpr double min_trough_cos_phi = 0.02;
struct OdeContext {
  const ScaledEngine* engine;
  Phase phase;
  bool sling_vertical = false;  // set when phase I reaches cos phi <= 0
};

State state_of(const OdeContext& c, const double y[], std::size_t dimension, bool& ok) {
  State s;
  ok = true;
  if (dimension == 4) {  // phase I
    s.theta = y[0], s.psi = y[1], s.theta_dot = y[2], s.psi_dot = y[3];
    ok = complete_trough_state(*c.engine, s) > min_trough_cos_phi;
  } else {
    s.theta = y[0], s.psi = y[1], s.phi = y[2], s.theta_dot = y[3], s.psi_dot = y[4], s.phi_dot = y[5];
  }
  return s;
}

int equations(double, const double y[], double dydt[], void* params) {
  auto* c = static_cast<OdeContext*>(params);
  bool ok = true;
  const State s = state_of(*c, y, c->phase == Phase::trough ? 4 : 6, ok);
  if (!ok) {
    c->sling_vertical = true;
    return GSL_EBADFUNC;
  }
  const auto a = accelerations(*c->engine, c->phase, s);
  if (c->phase == Phase::trough) {
    dydt[0] = s.theta_dot, dydt[1] = s.psi_dot, dydt[2] = a[0], dydt[3] = a[1];
  } else {
    dydt[0] = s.theta_dot, dydt[1] = s.psi_dot, dydt[2] = s.phi_dot, dydt[3] = a[0], dydt[4] = a[1], dydt[5] = a[2];
  }
  return GSL_SUCCESS;
}

const gsl_odeiv2_step_type* stepper_type(const std::string& name) {
  if (name == "rk2") return gsl_odeiv2_step_rk2;
  if (name == "rk4") return gsl_odeiv2_step_rk4;
  if (name == "rkf45") return gsl_odeiv2_step_rkf45;
  if (name == "rkck") return gsl_odeiv2_step_rkck;
  if (name == "rk8pd") return gsl_odeiv2_step_rk8pd;
  throw Error(ErrorKind::usage, "--stepper: '" + name + "' is not a stepper; use rk2, rk4, rkf45, rkck or rk8pd");
}

using DriverPtr = std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)>;

// One phase: a driver for stepping and a second one for evaluating the solution between steps.
class PhaseIntegrator {
 public:
  PhaseIntegrator(const ScaledEngine& engine, Phase phase, const IntegratorSettings& settings)
      : context_{&engine, phase},
        system_{equations, nullptr, phase == Phase::trough ? 4u : 6u, &context_},
        stepping_(make(settings), gsl_odeiv2_driver_free),
        evaluating_(make(settings), gsl_odeiv2_driver_free) {}

  // One accepted step toward t_end; false when the equations failed.
  bool step(double& t, double y[], double t_end, double& h) {
    gsl_odeiv2_driver* d = stepping_.get();
    return gsl_odeiv2_evolve_apply(d->e, d->c, d->s, &system_, &t, t_end, &h, y) == GSL_SUCCESS;
  }

  // The solution at t1, from a stored step start (t0, y0): integrated anew to the same tolerance.
  std::vector<double> at(double t0, const std::vector<double>& y0, double t1) {
    std::vector<double> y = y0;
    if (t1 <= t0) return y;
    gsl_odeiv2_driver_reset_hstart(evaluating_.get(), t1 - t0);
    double t = t0;
    if (gsl_odeiv2_driver_apply(evaluating_.get(), &t, t1, y.data()) != GSL_SUCCESS)
      throw Error(ErrorKind::numerical, "integrator failure while evaluating between steps; tighten --rtol");
    return y;
  }

  State state(const std::vector<double>& y) const {
    bool ok = true;
    return state_of(context_, y.data(), y.size(), ok);
  }
  bool sling_vertical() const { return context_.sling_vertical; }

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

// The samples of one phase at the integrator's step ends, with the running force extremes
// refined on the continuous solution: where a force has a local maximum at a step end, the
// true peak lies within the two neighbouring steps and is found there by Brent's method.
class PhaseRecord {
 public:
  struct Sample {
    double t;
    std::vector<double> y;
    ForceValues forces;
    ForceExtremes extremes;  // over [0, t], refined peaks included
  };
  struct Peak {
    double t;
    ForceValues forces;
  };

  PhaseRecord(const ScaledEngine& engine, Phase phase, PhaseIntegrator& integrator, ForceExtremes before)
      : engine_(engine), phase_(phase), integrator_(integrator), before_(before) {}

  void add(double t, const std::vector<double>& y, const Snapshot& snap) {
    const ForceValues forces = force_values(snap);
    ForceExtremes extremes = samples_.empty() ? before_ : samples_.back().extremes;
    extremes.add(forces);
    samples_.push_back({t, y, forces, extremes});
    if (samples_.size() >= 3) refine_peaks();
  }

  const std::vector<Sample>& samples() const { return samples_; }

  // The state at `time`, from the last sample at or before it.
  std::vector<double> y_at(double time) const {
    return integrator_.at(samples_[base_of(time)].t, samples_[base_of(time)].y, time);
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
  std::size_t base_of(double time) const {
    std::size_t base = 0;
    while (base + 1 < samples_.size() && samples_[base + 1].t <= time) ++base;
    return base;
  }

  ForceValues forces_at(double time) const {
    return force_values(snapshot(engine_, phase_, integrator_.state(y_at(time))));
  }

  // A force peaking at the middle one of the last three samples peaks between the outer two.
  // Time tolerance 1e-9 (scaled): the peak value is quadratic in it, so exact to round-off.
  void refine_peaks() {
    const std::size_t mid = samples_.size() - 2;
    const Sample &a = samples_[mid - 1], &b = samples_[mid], &c = samples_[mid + 1];
    for (int k = 0; k < force_count; ++k) {
      if (!(b.forces[k] > a.forces[k] && b.forces[k] >= c.forces[k])) continue;
      const double t_peak = find_maximum([&](double time) { return forces_at(time)[k]; }, a.t, b.t, c.t, 1e-9);
      const Peak peak{t_peak, forces_at(t_peak)};
      peaks_.push_back(peak);
      for (std::size_t s = mid - 1; s < samples_.size(); ++s)
        if (samples_[s].t >= t_peak) samples_[s].extremes.add(peak.forces);
    }
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
  if (vx < 0 && r.height >= 0) {  // toward the target, -x; vacuum flight to level 0 (g = 1 scaled)
    const double flight = vy + std::sqrt(vy * vy + 2 * r.height);
    r.range = -(r.position.x + vx * flight);
  }
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

}  // namespace

ShotResult simulate_shot(const ScaledEngine& e, const Quality& quality, const IntegratorSettings& settings,
                         std::vector<TracePoint>* trace) {
  gsl_set_error_handler_off();
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
  std::vector<double> y = {e.theta_i, 0, 0, 0};
  double t = 0, h = 1e-3;
  Snapshot snap = snapshot(e, Phase::trough, trough.state(y));
  energy0 = snap.energy;
  phase1.add(t, y, snap);
  while (true) {
    const double t_prev = t;
    const std::vector<double> y_prev = y;
    if (!trough.step(t, y.data(), settings.max_time, h)) {
      if (trough.sling_vertical())
        fail("the sling stands vertical in the trough (phi -> 90 deg) before lift-off; lengthen the sling L4 or lighten the projectile m");
      fail("integrator failure in phase I; tighten --rtol or choose another --stepper");
    }
    count_step("phase I");
    snap = snapshot(e, Phase::trough, trough.state(y));
    if (snap.normal_force <= 0) {  // lift-off inside this step: locate it on the continuous solution
      auto normal_at = [&](double time) { return snapshot(e, Phase::trough, trough.state(trough.at(t_prev, y_prev, time))).normal_force; };
      result.t_liftoff = find_root(normal_at, t_prev, t, 1e-15, 0);
      y = trough.at(t_prev, y_prev, result.t_liftoff);
      t = result.t_liftoff;
      snap = snapshot(e, Phase::trough, trough.state(y));
      phase1.add(t, y, snap);
      track_energy(snap);
      break;
    }
    phase1.add(t, y, snap);
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
  phase2.add(t, y, snapshot(e, Phase::lifted, lift));
  auto point_at = [&](double time) {
    const State s = lifted.state(phase2.y_at(time));
    return release_point(e, quality, time, s, snapshot(e, Phase::lifted, s), phase2.extremes_before(time));
  };
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
    phase2.add(t, y, snap);
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

  // The maximum of the objective on the continuous solution between the neighbouring samples.
  const auto& samples = phase2.samples();
  const std::size_t lo = best > 0 ? best - 1 : 0;
  const std::size_t hi = std::min(best + 1, samples.size() - 1);
  const double t_release = find_maximum([&](double time) { return point_at(time).objective; }, samples[lo].t,
                                        samples[best].t, samples[hi].t, 1e-13);
  result.release = point_at(t_release);
  if (trace) {
    record_trace(trace, e, Phase::lifted, lifted, samples, t_release);
    trace->push_back({Phase::lifted, t_release, result.release.state, snapshot(e, Phase::lifted, result.release.state)});
  }
  return result;
}

}  // namespace trebuchet
