#include "ode.hpp"

#include <gsl/gsl_errno.h>

#include <algorithm>
#include <cmath>

#include "trebuchet/error.hpp"

namespace trebuchet {
namespace {

using Context = PhaseIntegrator::Context;

std::size_t dimension_of(Phase phase) { return phase == Phase::lifted ? 6 : 4; }

State state_of(const Context& c, const double y[], bool& ok) {
  State s;
  ok = true;
  if (c.phase != Phase::lifted) {  // (th, psi, th', psi')
    s.theta = y[0], s.psi = y[1], s.theta_dot = y[2], s.psi_dot = y[3];
    if (c.phase == Phase::trough) ok = c.dynamics->complete_trough_state(s) > refuse_trough_cos_phi;
  } else {
    s.theta = y[0], s.psi = y[1], s.phi = y[2], s.theta_dot = y[3], s.psi_dot = y[4], s.phi_dot = y[5];
  }
  return s;
}

int equations(double, const double y[], double dydt[], void* params) {
  auto* c = static_cast<Context*>(params);
  bool ok = true;
  const State s = state_of(*c, y, ok);
  if (!ok) return GSL_FAILURE;  // a trial state near the singularity: GSL retries with a shorter step
  const auto a = c->dynamics->accelerations(c->phase, s);
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
  const std::size_t n = dimension_of(static_cast<Context*>(params)->phase);
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

OdeVector hermite(const StepEnd& a, const StepEnd& b, double time, std::size_t n) {
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
  const std::size_t angles = n / 2;
  const double h2 = h * h, h3 = h2 * h;
  OdeVector y{};
  for (std::size_t i = 0; i < angles; ++i) {
    const double q0 = a.y[i], v0 = a.y[angles + i], acc0 = a.dy[angles + i], j0 = a.jerk[i];
    const double q1 = b.y[i], v1 = b.y[angles + i], acc1 = b.dy[angles + i], j1 = b.jerk[i];
    y[i] = p0 * q0 + r0 * q1 + h * (p1 * v0 + r1 * v1) + h2 * (p2 * acc0 + r2 * acc1) + h3 * (p3 * j0 + r3 * j1);
    y[angles + i] = (dp0 * q0 + dr0 * q1) / h + dp1 * v0 + dr1 * v1 + h * (dp2 * acc0 + dr2 * acc1) + h2 * (dp3 * j0 + dr3 * j1);
  }
  return y;
}

PhaseIntegrator::PhaseIntegrator(const Dynamics& dynamics, Phase phase, const IntegratorSettings& settings)
    : context_{&dynamics, phase},
      system_{equations, jacobian, dimension_of(phase), &context_},
      stepping_(make(settings), gsl_odeiv2_driver_free),
      evaluating_(make(settings), gsl_odeiv2_driver_free) {}

gsl_odeiv2_driver* PhaseIntegrator::make(const IntegratorSettings& settings) {
  return gsl_odeiv2_driver_alloc_y_new(&system_, stepper_type(settings.stepper), 1e-3, settings.atol, settings.rtol);
}

bool PhaseIntegrator::step(double& t, double y[], double t_end, double& h) {
  gsl_odeiv2_driver* d = stepping_.get();
  return gsl_odeiv2_evolve_apply(d->e, d->c, d->s, &system_, &t, t_end, &h, y) == GSL_SUCCESS;
}

OdeVector PhaseIntegrator::at(double t0, const OdeVector& y0, double t1) {
  OdeVector y = y0;
  if (t1 <= t0) return y;
  gsl_odeiv2_driver_reset_hstart(evaluating_.get(), t1 - t0);
  double t = t0;
  if (gsl_odeiv2_driver_apply(evaluating_.get(), &t, t1, y.data()) != GSL_SUCCESS)
    throw Error(ErrorKind::numerical, "integrator failure while evaluating between steps; tighten --rtol");
  return y;
}

// The jerk by a central difference along the flow, y +- delta y': truncation delta^2 q^(5)/6 and
// round-off 1e-16/delta, both ~1e-10 of q''' at delta = 1e-4 (scaled time); the interpolant
// multiplies it by h^3/100 or less.
StepEnd PhaseIntegrator::step_end(double t, const OdeVector& y) {
  constexpr double delta = 1e-4;
  StepEnd end{t, y, derivative(y), {}};
  OdeVector ahead = y, behind = y;
  for (std::size_t i = 0; i < dimension(); ++i) ahead[i] += delta * end.dy[i], behind[i] -= delta * end.dy[i];
  const OdeVector rate_ahead = derivative(ahead), rate_behind = derivative(behind);
  const std::size_t angles = dimension() / 2;
  for (std::size_t i = 0; i < angles; ++i) end.jerk[i] = (rate_ahead[angles + i] - rate_behind[angles + i]) / (2 * delta);
  return end;
}

State PhaseIntegrator::state(const OdeVector& y) const {
  bool ok = true;
  return state_of(context_, y.data(), ok);
}

OdeVector PhaseIntegrator::derivative(const OdeVector& y) {
  OdeVector dy{};
  if (equations(0, y.data(), dy.data(), &context_) != GSL_SUCCESS)
    throw Error(ErrorKind::numerical, "the equations of motion failed at an accepted state; tighten --rtol");
  return dy;
}

}  // namespace trebuchet
