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
