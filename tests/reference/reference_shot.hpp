// A slow, independent reference for the verified shot (issue 12): it shares no code with the
// library. The equations of motion are assembled from the bodies' positions by Lagrange's
// equations with Eigen (phase I with the trough as a constraint and its normal force as the
// multiplier), integrated with GSL's rk8pd at rtol 1e-14 on a dense grid; force peaks, lift-off,
// the onsets of growth of the running extremes and the release are located by bisection or
// golden section on the solution integrated anew, and the slope of Q by automatic
// differentiation along the flow (Eigen's AutoDiffScalar). Scaled units as in the paper
// (section 3): lengths in L2, masses in M, time in (L2/g)^(1/2), forces in M g.
#pragma once

namespace reference {

/// The free scaled parameters of eq:Design with theta_i [deg] and F of section 2.
struct Design {
  double l, l4, mu_b, mu, theta_i_deg, F;
};

/// The release that maximises Q of eq:Q, with what the issue compares; scaled.
struct Shot {
  double t_liftoff, t_release;
  double rho;  ///< R/L2 from the pivot to impact at the base's level
  double tau_e;  ///< T/(M g L2), eq:T with the height above the base
  double eps;  ///< eq:Aux
  double speed;  ///< v/(g L2)^(1/2)
  double height;  ///< h/L2 above the base
  double Q;  ///< eq:Q
  int onset = -1;  ///< the release sits where this running extreme starts to grow (0 F_S_perp,
      ///< 1 |F_R|, 2 max F_Rh, 3 max -F_Rh); -1 at a smooth maximum
};

/// Shoots `design`; throws std::runtime_error when it has no lift-off or no forward release.
Shot shoot(const Design& design);

/// Shoots `design` released where the projectile's velocity angle above the horizontal toward
/// the target, falling, first reaches angle_deg after lift-off (the library's release_angle_deg);
/// its Q uses the running extremes up to there. Throws std::runtime_error when it is not reached
/// before Q falls to half its best.
Shot shoot_at_velocity_angle(const Design& design, double angle_deg);

}  // namespace reference
