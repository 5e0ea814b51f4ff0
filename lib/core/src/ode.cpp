#include "ode.hpp"

#include <gsl/gsl_errno.h>

#include <algorithm>
#include <cmath>

#include "trebuchet/error.hpp"

namespace trebuchet {
namespace {

using Context = PhaseIntegrator::Context;

// The sling swings in phase II, and in phase III where it has mass (Machine::swings_after_release).
std::size_t angles_of(const Context& c) {
  return c.phase == Phase::lifted || (c.phase == Phase::released && c.machine->swings_after_release()) ? 3 : 2;
}
std::size_t dimension_of(const Context& c) { return 2 * angles_of(c) + (c.machine->dissipates() ? loss_count : 0); }

// The full state of an integrated vector: in the trough phi and phi_dot from eq:EOM_I_3 (on the
// whipper's arm, from the arm).
State state_of(const Context& c, const double y[]) {
  State s;
  if (angles_of(c) == 2) {  // (th, psi, th', psi')
    s.theta = y[0], s.psi = y[1], s.theta_dot = y[2], s.psi_dot = y[3];
    if (c.phase == Phase::trough || c.phase == Phase::held) c.machine->complete_trough_state(s);
  } else {
    s.theta = y[0], s.psi = y[1], s.phi = y[2], s.theta_dot = y[3], s.psi_dot = y[4], s.phi_dot = y[5];
  }
  return s;
}

int equations(double, const double y[], double dydt[], void* params) {
  auto* c = static_cast<Context*>(params);
  State s;
  const std::size_t angles = angles_of(*c);
  if (angles == 2) {  // (th, psi, th', psi'); the accelerations need no phi in the trough
    s.theta = y[0], s.psi = y[1], s.theta_dot = y[2], s.psi_dot = y[3];
  } else {
    s.theta = y[0], s.psi = y[1], s.phi = y[2], s.theta_dot = y[3], s.psi_dot = y[4], s.phi_dot = y[5];
  }
  std::array<double, 3> a;
  Losses power;
  const bool losses = c->machine->dissipates();
  const Evaluated found = c->machine->accelerations(c->phase, s, a, losses ? &power : nullptr);
  if (found != Evaluated::found) {
    // A trial state near the trough's singularity fails, and GSL retries with a shorter step;
    // any other failure is taken for friction that does not settle.
    if (found == Evaluated::failed) c->friction_unsettled = true;
    return GSL_FAILURE;
  }
  if (angles == 2) {
    dydt[0] = s.theta_dot, dydt[1] = s.psi_dot, dydt[2] = a[0], dydt[3] = a[1];
  } else {
    dydt[0] = s.theta_dot, dydt[1] = s.psi_dot, dydt[2] = s.phi_dot, dydt[3] = a[0], dydt[4] = a[1], dydt[5] = a[2];
  }
  if (losses)
    for (int k = 0; k < loss_count; ++k) dydt[2 * angles + k] = power[k];
  return GSL_SUCCESS;
}

// The Jacobian for the implicit steppers, by forward differences of `equations` (the system is
// autonomous, so df/dt = 0). Step sqrt(machine epsilon) relative: about 8 good digits, which
// is all a Newton iteration needs.
int jacobian(double t, const double y[], double* dfdy, double dfdt[], void* params) {
  const std::size_t n = dimension_of(*static_cast<Context*>(params));
  OdeVector f0{}, f1{}, shifted{};
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

// Step size control. GSL's standard control keeps h while the error stays within 0.5 to 1.1 of
// the tolerance, so where the motion quickens toward the release, and the error at a given h
// grows threefold from step to step, every second step is rejected (17 of 77 on Denny's
// engine), each a whole step's work lost. This one is Gustafsson's predictive control (Hairer
// and Wanner, section IV.8): after an accepted step h is scaled by the smaller of
// 0.9 r^(-1/k) and that times (h/h_prev) (r_prev/r)^(1/k), k = order + 1, within [0.2, 5];
// the second follows the trend of the error. A step is rejected only above the tolerance,
// r > 1. The error measure is GSL's: r = max |error_i| / (atol + rtol (a_y |y_i| + a_dydt h |y'_i|)).
struct ControlState {
  double eps_abs = 0, eps_rel = 0, a_y = 0, a_dydt = 0;
  double h_previous = 0, r_previous = 0;  // of the last accepted step; 0: none yet
};

double error_level(const ControlState& c, double y, double dydt, double h) {
  return c.eps_rel * (c.a_y * std::abs(y) + c.a_dydt * std::abs(h * dydt)) + c.eps_abs;
}

int adjust_step(void* state, std::size_t dim, unsigned int order, const double y[], const double yerr[], const double yp[], double* h) {
  ControlState& c = *static_cast<ControlState*>(state);
  double r = 0;
  for (std::size_t i = 0; i < dim; ++i) r = std::max(r, std::abs(yerr[i]) / error_level(c, y[i], yp[i], *h));
  if (r > 1) {
    *h *= std::max(0.9 * std::pow(r, -1.0 / order), 0.2);
    return GSL_ODEIV_HADJ_DEC;
  }
  r = std::max(r, 1e-10);
  const double k = order + 1.0;
  double factor = 0.9 * std::pow(r, -1 / k);
  if (c.h_previous > 0) factor = std::min(factor, factor * (*h / c.h_previous) * std::pow(c.r_previous / r, 1 / k));
  factor = std::clamp(factor, 0.2, 5.0);
  c.h_previous = *h, c.r_previous = r;
  *h *= factor;
  return factor > 1 ? GSL_ODEIV_HADJ_INC : GSL_ODEIV_HADJ_NIL;
}

const gsl_odeiv2_control_type predictive_control = {
    "trebuchet-predictive",
    []() -> void* { return new ControlState{}; },
    [](void* state, double eps_abs, double eps_rel, double a_y, double a_dydt) {
      *static_cast<ControlState*>(state) = {eps_abs, eps_rel, a_y, a_dydt, 0, 0};
      return int(GSL_SUCCESS);
    },
    adjust_step,
    [](void* state, double y, double dydt, double h, std::size_t, double* level) {
      *level = error_level(*static_cast<ControlState*>(state), y, dydt, h);
      return int(GSL_SUCCESS);
    },
    [](void*, const gsl_odeiv2_driver*) { return int(GSL_SUCCESS); },
    [](void* state) { delete static_cast<ControlState*>(state); },
};

const gsl_odeiv2_step_type* stepper_type(Stepper stepper) {
  switch (stepper) {
    case Stepper::rk2: return gsl_odeiv2_step_rk2;
    case Stepper::rk4: return gsl_odeiv2_step_rk4;
    case Stepper::rkf45: return gsl_odeiv2_step_rkf45;
    case Stepper::rkck: return gsl_odeiv2_step_rkck;
    case Stepper::rk8pd: return gsl_odeiv2_step_rk8pd;
    case Stepper::msadams: return gsl_odeiv2_step_msadams;
    case Stepper::rk1imp: return gsl_odeiv2_step_rk1imp;
    case Stepper::rk2imp: return gsl_odeiv2_step_rk2imp;
    case Stepper::rk4imp: return gsl_odeiv2_step_rk4imp;
    case Stepper::bsimp: return gsl_odeiv2_step_bsimp;
    case Stepper::msbdf: return gsl_odeiv2_step_msbdf;
  }
  return gsl_odeiv2_step_rk8pd;
}

}  // namespace

OdeVector hermite(const StepEnd& a, const StepEnd& b, double time, std::size_t angles, std::size_t dimension) {
  const double h = b.t - a.t, s = (time - a.t) / h;
  // The basis on [0, 1] for q, q', q'', q''' at 0 (p0..p3) and at 1 (r0..r3), and its derivative.
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s;
  const double p0 = 1 + s4 * (-35 + s * (84 + s * (-70 + 20 * s))), r0 = 1 - p0;
  const double p1 = s * (1 + s3 * (-20 + s * (45 + s * (-36 + 10 * s))));
  const double p2 = s2 * (0.5 + s2 * (-5 + s * (10 + s * (-7.5 + 2 * s))));
  const double p3 = s3 * (1.0 / 6 + s * (-2.0 / 3 + s * (1 + s * (-2.0 / 3 + s / 6))));
  const double r1 = s4 * (-15 + s * (39 + s * (-34 + 10 * s)));
  const double r2 = s4 * (2.5 + s * (-7 + s * (6.5 - 2 * s)));
  const double r3 = s4 * (-1.0 / 6 + s * (0.5 + s * (-0.5 + s / 6)));
  const double dp0 = s3 * (-140 + s * (420 + s * (-420 + 140 * s))), dr0 = -dp0;
  const double dp1 = 1 + s3 * (-80 + s * (225 + s * (-216 + 70 * s)));
  const double dp2 = s * (1 + s2 * (-20 + s * (50 + s * (-45 + 14 * s))));
  const double dp3 = s2 * (0.5 + s * (-8.0 / 3 + s * (5 + s * (-4 + 7 * s / 6))));
  const double dr1 = s3 * (-60 + s * (195 + s * (-204 + 70 * s)));
  const double dr2 = s3 * (10 + s * (-35 + s * (39 - 14 * s)));
  const double dr3 = s3 * (-2.0 / 3 + s * (2.5 + s * (-3 + 7 * s / 6)));
  const double h2 = h * h, h3 = h2 * h;
  OdeVector y{};
  for (std::size_t i = 0; i < angles; ++i) {
    const double q0 = a.y[i], v0 = a.y[angles + i], acc0 = a.dy[angles + i], j0 = a.jerk[i];
    const double q1 = b.y[i], v1 = b.y[angles + i], acc1 = b.dy[angles + i], j1 = b.jerk[i];
    y[i] = p0 * q0 + r0 * q1 + h * (p1 * v0 + r1 * v1) + h2 * (p2 * acc0 + r2 * acc1) + h3 * (p3 * j0 + r3 * j1);
    y[angles + i] = (dp0 * q0 + dr0 * q1) / h + dp1 * v0 + dr1 * v1 + h * (dp2 * acc0 + dr2 * acc1) + h2 * (dp3 * j0 + dr3 * j1);
  }
  if (dimension > 2 * angles) {
    const double c00 = (1 + 2 * s) * (1 - s) * (1 - s), c10 = s * (1 - s) * (1 - s), c01 = s2 * (3 - 2 * s), c11 = s2 * (s - 1);
    for (std::size_t i = 2 * angles; i < dimension; ++i) y[i] = c00 * a.y[i] + c01 * b.y[i] + h * (c10 * a.dy[i] + c11 * b.dy[i]);
  }
  return y;
}

PhaseIntegrator::PhaseIntegrator(const Machine& machine, Phase phase, const IntegratorSettings& settings)
    : context_{&machine, phase},
      system_{equations, jacobian, dimension_of(context_), &context_},
      stepping_(make(settings), gsl_odeiv2_driver_free),
      evaluating_(make(settings), gsl_odeiv2_driver_free) {}

void check_integrator(const IntegratorSettings& settings) {
  // Below 1e-15 a step's error cannot be told from the round-off of doubles (2.2e-16), and the
  // step shrinks until the step budget is spent; above 1e-2 the motion is not the engine's.
  check_ordinary(settings.rtol, 1e-15, 1e-2, "rtol", "", "relative tolerance per step");
  check_ordinary(settings.atol, 1e-15, 1e-2, "atol", "", "absolute tolerance per step");
}

bool integration_failed(const Error& error) {
  if (error.kind() != ErrorKind::numerical) return false;
  for (const std::string& name : error.names())
    if (name == "rtol" || name == "atol" || name == "stepper") return true;
  return false;
}

gsl_odeiv2_driver* PhaseIntegrator::make(const IntegratorSettings& settings) {
  check_integrator(settings);
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&system_, stepper_type(settings.stepper), 1e-3, settings.atol, settings.rtol);
  gsl_odeiv2_control_free(d->c);
  d->c = gsl_odeiv2_control_alloc(&predictive_control);
  gsl_odeiv2_control_init(d->c, settings.atol, settings.rtol, 1, 0);
  gsl_odeiv2_control_set_driver(d->c, d);
  gsl_odeiv2_driver_set_nmax(d, static_cast<unsigned long>(settings.max_steps));  // bounds at(): it fails rather than run on
  return d;
}

bool PhaseIntegrator::step(double& t, double y[], double t_end, double& h) {
  gsl_odeiv2_driver* d = stepping_.get();
  return gsl_odeiv2_evolve_apply(d->e, d->c, d->s, &system_, &t, t_end, &h, y) == GSL_SUCCESS;
}

OdeVector PhaseIntegrator::at(double t0, const OdeVector& y0, double t1) {
  OdeVector y = y0;
  if (t1 <= t0) return y;
  gsl_odeiv2_driver_reset_hstart(evaluating_.get(), t1 - t0);
  static_cast<ControlState*>(evaluating_->c->state)->h_previous = 0;  // a new interval: no trend yet
  double t = t0;
  if (gsl_odeiv2_driver_apply(evaluating_.get(), &t, t1, y.data()) != GSL_SUCCESS)
    throw Error(ErrorKind::numerical, "integrator failure while evaluating between steps; tighten {{rtol}}");
  return y;
}

// The jerk by a forward difference of q'' along the flow, y + delta y': truncation
// delta q^(5)/2 and round-off 1e-16 |q''|/delta, both ~1e-8 at delta = 1e-8 (scaled time); the
// interpolant multiplies the jerk by h^3/100 or less.
StepEnd PhaseIntegrator::step_end(double t, const OdeVector& y, const Snapshot& snapshot) {
  constexpr double delta = 1e-8;
  const std::size_t angles = this->angles();
  const std::array<double, 3> acceleration{snapshot.theta_ddot, snapshot.psi_ddot, snapshot.phi_ddot};
  StepEnd end{t, y, {}, {}};
  for (std::size_t i = 0; i < angles; ++i) end.dy[i] = y[angles + i], end.dy[angles + i] = acceleration[i];
  for (std::size_t i = 2 * angles; i < dimension(); ++i) end.dy[i] = snapshot.loss_power[i - 2 * angles];
  OdeVector ahead = y;
  for (std::size_t i = 0; i < dimension(); ++i) ahead[i] += delta * end.dy[i];
  const OdeVector rate_ahead = derivative(ahead);
  for (std::size_t i = 0; i < angles; ++i) end.jerk[i] = (rate_ahead[angles + i] - acceleration[i]) / delta;
  return end;
}

State PhaseIntegrator::state(const OdeVector& y) const { return state_of(context_, y.data()); }

std::size_t PhaseIntegrator::angles() const { return angles_of(context_); }

OdeVector PhaseIntegrator::vector_of(const State& s, const Losses& work) const {
  OdeVector y{};
  if (angles() == 2)
    y = {s.theta, s.psi, s.theta_dot, s.psi_dot};
  else
    y = {s.theta, s.psi, s.phi, s.theta_dot, s.psi_dot, s.phi_dot};
  for (std::size_t k = 0; k + 2 * angles() < dimension(); ++k) y[2 * angles() + k] = work[k];
  return y;
}

Losses PhaseIntegrator::work(const OdeVector& y) const {
  Losses out{};
  if (dimension() > 2 * angles())
    for (int k = 0; k < loss_count; ++k) out[k] = y[2 * angles() + k];
  return out;
}

OdeVector PhaseIntegrator::derivative(const OdeVector& y) {
  OdeVector dy{};
  if (equations(0, y.data(), dy.data(), &context_) != GSL_SUCCESS)
    throw Error(ErrorKind::numerical,
                context_.friction_unsettled ? unsettled_friction : "the equations of motion failed at an accepted state; tighten {{rtol}}");
  return dy;
}

}  // namespace trebuchet
