// The equations of motion of one phase as a GSL odeiv2 system (appendix A), stepped and
// evaluated between steps, and the quintic Hermite interpolant between step ends.
// Internal to the library: the shot is its one user.
#pragma once

#include <gsl/gsl_odeiv2.h>

#include <array>
#include <memory>

#include "trebuchet/dynamics.hpp"
#include "trebuchet/machine.hpp"
#include "trebuchet/integrator.hpp"

namespace trebuchet {

// Phase I (and the whipper's phase held) integrates (th, psi, th', psi'); phase II (th, psi, phi, th', psi', phi'); phase III
// as phase I. An engine that dissipates (BuiltParts::dissipates) appends the work of each loss
// (LossIndex), whose rates are their powers. Fixed size: no allocation per use.
using OdeVector = std::array<double, 6 + loss_count>;

// A step end: time, state y = (angles q, angular speeds q'), y' = (q', q'') and the jerk q'''.
struct StepEnd {
  double t;
  OdeVector y, dy;
  std::array<double, 3> jerk;
};

// Between two step ends, each angle follows the septic Hermite interpolant that matches q, q',
// q'' and q''' at both ends, and each angular speed is that interpolant's derivative. Errors are
// O(h^8) in q and O(h^7) in q', the order of the rk8pd steps themselves. The work of the losses
// after them (up to `dimension`) follows the cubic one of the work and its power: it serves
// pictures, and what is reported is integrated anew (PhaseRecord::y_exact_at).
OdeVector hermite(const StepEnd& a, const StepEnd& b, double time, std::size_t angles, std::size_t dimension);

// One phase of a machine: a driver for stepping and a second one for evaluating the solution between steps.
class PhaseIntegrator {
 public:
  PhaseIntegrator(const Machine& machine, Phase phase, const IntegratorSettings& settings);

  // One accepted step toward t_end; false when the equations failed.
  bool step(double& t, double y[], double t_end, double& h);

  // The solution at t1, from a stored step start (t0, y0): integrated anew to the same
  // tolerance. Throws Error(numerical) when the integrator fails.
  OdeVector at(double t0, const OdeVector& y0, double t1);

  std::size_t dimension() const { return system_.dimension; }
  std::size_t angles() const;
  // The work of each loss so far, in an integrated vector (0 for an engine without losses).
  Losses work(const OdeVector& y) const;
  // Whether an evaluation failed because friction left the accelerations unsettled.
  bool friction_unsettled() const { return context_.friction_unsettled; }
  Phase phase() const { return context_.phase; }
  const Machine& machine() const { return *context_.machine; }

  // The full state of an integrated vector (phi from eq:EOM_I_3 in phase I).
  State state(const OdeVector& y) const;
  /// The integrated vector of a full state and the work done so far.
  OdeVector vector_of(const State& state, const Losses& work) const;

  // y' = f(y): the angular speeds and accelerations at a step end, for the interpolant.
  OdeVector derivative(const OdeVector& y);

  // A step end at (t, y), with the accelerations of its snapshot, and the jerk.
  StepEnd step_end(double t, const OdeVector& y, const Snapshot& snapshot);

  struct Context {
    const Machine* machine;
    Phase phase;
    bool friction_unsettled = false;
  };

 private:
  using DriverPtr = std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)>;
  gsl_odeiv2_driver* make(const IntegratorSettings& settings);
  Context context_;
  gsl_odeiv2_system system_;
  DriverPtr stepping_, evaluating_;
};

}  // namespace trebuchet
