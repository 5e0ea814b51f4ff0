#include "trebuchet/verification.hpp"

#include <cmath>

namespace trebuchet {

Verification verify_engine(const Engine& engine, const ShotSettings& settings, std::vector<TracePoint>* trace) {
  const ScaledEngine scaled = ScaledEngine::from(engine);
  const ShotResult shot = simulate_shot(scaled, settings.quality, settings.integrator, trace);
  const ReleasePoint& r = shot.release;
  const double L2 = engine.L2, g = settings.g;
  const double speed_unit = std::sqrt(g * L2), time_unit = std::sqrt(L2 / g);  // section 3
  Verification out;
  const double vx = r.velocity.x * speed_unit, vy = r.velocity.y * speed_unit;
  out.v = std::hypot(vx, vy);
  out.h = r.height * L2;
  out.x = r.position.x * L2;
  out.A_deg = std::atan2(vy, -vx) * 180 / M_PI;
  out.theta_release_deg = r.state.theta * 180 / M_PI;
  const double drop = out.h - settings.target_level;  // release to target level [m]
  out.R = vacuum_range({out.x, 0}, {vx, vy}, drop, g);
  out.T = 0.5 * engine.m * out.v * out.v + engine.m * g * drop;  // eq:T, measured at the target
  out.eps = r.efficiency;
  out.Q = r.quality;
  out.force_factor = r.force_factor;
  out.t_release = r.t * time_unit;
  out.t_liftoff = shot.t_liftoff * time_unit;
  out.FS_perp_mg = r.sling_perpendicular_max / scaled.mu;
  out.FR_Mg = r.pivot_reaction_max;
  out.dFRh_Mg = r.pivot_horizontal_max - r.pivot_horizontal_min;
  out.energy_drift = shot.energy_drift;
  return out;
}

}  // namespace trebuchet
