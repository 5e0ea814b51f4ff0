// One shot of an engine, ab initio: phases I and II of appendix A integrated with GSL odeiv2,
// lift-off located where the trough's normal force vanishes, and the release at the maximum
// of the quality function over phase II (section 5). Everything here is scaled (dynamics.hpp).
#pragma once

#include <string>
#include <vector>

#include "trebuchet/dynamics.hpp"

namespace trebuchet {

/// Settings of the integration; defaults are chosen in docs/verifier.md.
struct IntegratorSettings {
  std::string stepper = "rk8pd";   ///< a GSL odeiv2 stepper, one of stepper_names()
  double rtol = 1e-12;             ///< relative tolerance per step
  double atol = 1e-13;             ///< absolute tolerance per step, scaled units
  long max_steps = 200000;         ///< step budget over both phases
  double max_energy_drift = 1e-8;  ///< |E(t) - E(0)|/DeltaU above this is an error, not a result
  double max_time = 200;           ///< scaled; phase II is abandoned after this
};

/// The GSL odeiv2 steppers the shot can use, for messages and help: explicit Runge-Kutta,
/// Adams, and implicit ones with a finite-difference Jacobian.
std::string stepper_names();

/// What the release maximises: the quality eq:Q (n = 1) or eq:Q_n, Q_eps = eps (appendix B),
/// or the range (Denny's criterion; the paper's tab:Denny "Present" row).
struct Quality {
  enum class Release { quality, efficiency, range };
  Release release = Release::quality;
  double n = 1;  ///< exponent of eps in eq:Q_n; Q is reported with it whatever the release
};

/// "Q", "eps" or "range": the names --quality takes.
std::string release_name(Quality::Release release);

/// The release criterion of a --quality name; Error(usage) names the text and the choices.
Quality::Release parse_release(const std::string& name);

/// The projectile's state and the engine's figures at one moment of phase II, scaled.
struct ReleasePoint {
  double t = 0;                 ///< scaled time
  State state;
  Vec2 position, velocity;      ///< projectile, relative to the pivot
  double height = 0;            ///< above the engine's base (l cos th_i + y), in L2
  double range = 0;             ///< rho: pivot to impact at level 0, in L2; <= 0: not forward
  double energy_at_target = 0;  ///< tau_e = T/(M g L2), eq:Aux, level 0
  double efficiency = 0;        ///< eps = T/Delta U, eq:Aux
  // Running extremes over [0, t], peaks between step ends included (found on the continuous solution).
  double sling_perpendicular_max = 0;  ///< running max of F_S_perp over [0, t], in Mg
  double pivot_reaction_max = 0;       ///< running max of |F_R|, in Mg
  double pivot_horizontal_max = 0;     ///< running max of F_Rh, in Mg
  double pivot_horizontal_min = 0;     ///< running min of F_Rh, in Mg
  double force_factor = 0;      ///< F of eq:F
  double quality = 0;           ///< Q of eq:Q or eq:Q_n, at level 0
  double objective = 0;         ///< what the release maximises: Q, eps or the range
};

struct ShotResult {
  double t_liftoff = 0;         ///< scaled
  ReleasePoint release;
  double energy_drift = 0;      ///< max |E(t) - E(0)| / Delta U over phases I and II
  long steps = 0;               ///< accepted steps, both phases
};

/// One moment of the motion for a time series (--series), scaled.
struct TracePoint {
  Phase phase;
  double t;
  State state;
  Snapshot snapshot;
};

/// Integrates the shot and finds the release. Throws Error(numerical) with a named reason:
/// the beam cannot turn, no lift-off, sling vertical in the trough, no forward release,
/// integrator failure or step budget, or energy drift above the limit.
/// With `trace`, the integrator's step ends up to the release, the release itself, and phase III
/// (beam and counterweight alone) for as long again, are appended to it.
ShotResult simulate_shot(const ScaledEngine& engine, const Quality& quality, const IntegratorSettings& settings,
                         std::vector<TracePoint>* trace = nullptr);

}  // namespace trebuchet
