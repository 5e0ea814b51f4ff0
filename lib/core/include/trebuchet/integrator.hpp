// Settings of the numerical integration of the equations of motion (GSL odeiv2); the
// defaults are chosen from the work-precision chart in docs/performance.md.
#pragma once

#include <array>

#include "trebuchet/error.hpp"

namespace trebuchet {

/// The GSL odeiv2 steppers: explicit Runge-Kutta, Adams, and implicit ones, which get a
/// finite-difference Jacobian.
enum class Stepper { rk2, rk4, rkf45, rkck, rk8pd, msadams, rk1imp, rk2imp, rk4imp, bsimp, msbdf };

inline constexpr std::array<Stepper, 11> all_steppers = {Stepper::rk2,    Stepper::rk4,     Stepper::rkf45,  Stepper::rkck,
                                                         Stepper::rk8pd,  Stepper::msadams, Stepper::rk1imp, Stepper::rk2imp,
                                                         Stepper::rk4imp, Stepper::bsimp,   Stepper::msbdf};

struct IntegratorSettings {
  Stepper stepper = Stepper::rk8pd;
  double rtol = 1e-11;  ///< relative tolerance per step, scaled
  double atol = 1e-11;  ///< absolute tolerance per step, scaled units
  long max_steps = 200000;  ///< step budget over both phases
  double max_energy_drift = 1e-8;  ///< |E(t) - E(0)|/Delta U above this is an error, not a result
  double max_time = 200;  ///< scaled; phase II is abandoned after this
};

/// Refuses (Error(bad_number), naming {{rtol}} or {{atol}}) a tolerance outside 1e-15 to 1e-2.
void check_integrator(const IntegratorSettings& settings);

/// Whether `error` is a failure of the integration (energy drift, step budget, a failed step),
/// whose fix is a setting of the integrator, which its message names ({{rtol}}, {{stepper}}):
/// not a degenerate engine (a beam that cannot turn), which no setting mends.
bool integration_failed(const Error& error);

}  // namespace trebuchet
