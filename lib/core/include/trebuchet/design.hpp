// The scaled design of an engine (eq:Design, eq:4free): lengths in units of L2, masses in
// units of M (section 3). The one type for an engine's shape, for the equations of motion,
// the capacity fit and the optimizer.
#pragma once

namespace trebuchet {

/// The paper's standard initial beam angle (section 2) [deg].
inline constexpr double standard_theta_i_deg = 30;
/// The paper's "more realistic" counterweight arm fraction F = (L2 + L3)/H (section 2), scaled.
inline constexpr double standard_F = 2.0 / 3;

/// Historical engines start at rest with psi_i = phi_i = 0 (section 2).
struct ScaledDesign {
  double l = 0;     ///< L1/L2, scaled
  double l4 = 0;    ///< L4/L1, scaled
  double mu_b = 0;  ///< mb/M, scaled
  double mu = 0;    ///< m/M, scaled; a capacity fit sets it (section 4)
  double theta_i_deg = standard_theta_i_deg;  ///< initial beam angle from the downward vertical [deg]
  double F = standard_F;                      ///< (L2 + L3)/H, H = L1 cos theta_i (section 2), scaled
  /// Initial counterweight angle psi_i [deg], one of the initial conditions: 0 hangs straight down, as
  /// historical engines were never propped (section 2). Measured from the downward vertical in
  /// the sense theta grows during a shot; a prop that holds the counterweight toward the pivot
  /// side of the hinge's fall is negative (sec:SVdH, section 7.2: the best for the paper's Villard engine
  /// of row 2 is psi_i = -4.6 deg).
  double psi_i_deg = 0;

  /// L = L3/L2 = F l cos(theta_i) - 1 (eq:Design), scaled.
  double L() const;
  /// K = (l + 1)/mu_b (eq:kMkD), scaled.
  double K() const;
  /// The beam's moment of inertia about the pivot, I_b/(M L2^2) = mu_b (l^2 - l + 1)/3 (section 2).
  double beam_inertia() const;
  /// Delta U/(M g L2) of eq:DU: (1 - mu_b (l - 1)/2)(1 + cos theta_i), plus L (1 - cos psi_i)
  /// for a propped counterweight, which starts that much higher above its final rest.
  double energy_drop() const;
};

}  // namespace trebuchet
