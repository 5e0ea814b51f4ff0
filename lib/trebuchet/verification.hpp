// The ab-initio figures of an engine in SI units: a shot (shot.hpp) of its scaled design,
// turned back into metres, joules and newtons with L2, M and g (section 3).
#pragma once

#include "trebuchet/engine.hpp"
#include "trebuchet/shot.hpp"

namespace trebuchet {

struct ShotSettings {
  double g = 9.81;             ///< [m/s^2]
  double target_level = 0;     ///< target height relative to the engine's base [m], e.g. -54
  Quality quality{};
  IntegratorSettings integrator{};
};

/// What trebuchet-verify reports, in SI units (angles in degrees).
struct Verification {
  double R = 0;            ///< pivot to impact at the target level, vacuum [m]
  double T = 0;            ///< kinetic energy at the target level [J] (eq:T at level 0 plus m g |level|)
  double eps = 0;          ///< efficiency T/Delta U at level 0, eq:Aux
  double Q = 0;            ///< quality at the release, eq:Q or eq:Q_n (with the n of the settings)
  double force_factor = 0; ///< F of eq:F
  double v = 0;            ///< release speed [m/s]
  double h = 0;            ///< release height above the base [m]
  double x = 0;            ///< release position along the throw, from the pivot: > 0 behind it [m]
  double A_deg = 0;        ///< initial climb [deg]
  double theta_release_deg = 0;  ///< beam angle at release from the downward vertical [deg]; 180 is upright (section 6.2: below it, lower branch)
  double t_release = 0;    ///< [s]
  double t_liftoff = 0;    ///< [s]
  double FS_perp_mg = 0;   ///< largest perpendicular sling force on the beam / (m g)
  double FR_Mg = 0;        ///< largest |pivot reaction| / (M g)
  double dFRh_Mg = 0;      ///< largest minus smallest horizontal pivot reaction / (M g)
  double energy_drift = 0; ///< max |E(t) - E(0)| / Delta U over phases I and II
};

/// Simulates one shot of `engine`. Throws Error(numerical) as simulate_shot does. With
/// `trace`, the motion up to the release is appended to it (scaled, see simulate_shot).
Verification verify_engine(const Engine& engine, const ShotSettings& settings, std::vector<TracePoint>* trace = nullptr);

}  // namespace trebuchet
