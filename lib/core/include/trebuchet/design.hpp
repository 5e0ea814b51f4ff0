// The scaled design of an engine (eq:Design, eq:4free): lengths in units of L2, masses in
// units of M (section 3). The one type for an engine's shape, for the equations of motion,
// the capacity fit and the optimizer.
#pragma once

#include <optional>

#include "trebuchet/drag.hpp"

namespace trebuchet {

/// The paper's standard initial beam angle (section 2) [deg].
inline constexpr double standard_theta_i_deg = 30;
/// The paper's "more realistic" counterweight arm fraction F = (L2 + L3)/H (section 2), scaled.
inline constexpr double standard_F = 2.0 / 3;

/// What a real engine adds to the paper's ideal one, scaled: lengths in L2, masses in M,
/// moments of inertia in M L2^2 (docs/verifier.md, "Real engines"). Left empty, the shot is
/// appendix A's exactly: a uniform beam, a point counterweight, no friction, no air before
/// the release.
struct BuiltParts {
  /// The beam as a body turning about the pivot, of mass mu_b: the distance of its centre of
  /// mass from the pivot (> 0 toward the long arm's tip) and its moment of inertia about the pivot.
  struct Beam {
    double cm = 0, inertia = 0;
  };
  /// A part of the beam: its mass, centre of mass (as Beam's) and moment of inertia about the pivot.
  struct Section {
    double mass = 0, cm = 0, inertia = 0;
  };
  std::optional<Beam> beam;  ///< none: the uniform rod of section 2
  /// The short section, pivot to hinge, of a beam given as built (cm < 0), for the bending moment
  /// at the pivot; none where the beam is given only as a whole.
  std::optional<Section> short_section;
  double counterweight_inertia = 0;  ///< about the counterweight's own centre of mass
  double axle_friction = 0;  ///< the axle's friction circle over L2, r mu/sqrt(1 + mu^2)/L2 (Coulomb)
  double hinge_friction = 0;  ///< the same for the counterweight's hinge pin
  double trough_friction = 0;  ///< mu of the projectile sliding on the trough
  std::optional<Drag> drag;  ///< the air on the projectile in phases I and II
  /// rho_air Cd d L2^2/(2 M) of the sling's rope of diameter d: its drag per scaled length is
  /// this times the square of the air's speed across it. Acts only with `drag`.
  double rope_drag = 0;
  /// The sling's own mass, in M (docs/machines.md, "The sling's mass"): its rope, a uniform rod
  /// about the tip while taut, and its pouch, a point at the rope's end. For the equations of
  /// motion the rope is its first two moments about the tip: half its mass at its end and half
  /// at the tip carry its weight and its centre's motion, and a negative inertia -rope s^2/6
  /// about the tip (s the sling's length) brings its moment of inertia to rope s^2/3.
  struct Sling {
    double rope = 0, pouch = 0;
    /// The point mass at the sling's end: with the projectile (mu) until the release, without it after.
    double end_mass(double mu) const { return mu + pouch + rope / 2; }
    double tip_mass() const { return rope / 2; }
    /// The rope's inertia about the tip beyond its end's share, for a sling of length s (in L2).
    double inertia_beyond(double s) const { return -rope * s * s / 6; }
    bool any() const { return rope > 0 || pouch > 0; }
  } sling;

  /// Friction or drag before the release: the shot then tracks the work of each (Losses).
  bool dissipates() const { return axle_friction > 0 || hinge_friction > 0 || trough_friction > 0 || drag.has_value(); }
};

/// The machine a design is built as (docs/machines.md). The paper's engine hangs its
/// counterweight from a hinge at the short arm's end, on an arm L3 (appendix A). The fixed
/// counterweight bolts it to the short arm, its centre L3 beyond the arm's end, turning with the
/// beam (Trebuchator's "fixed": its hanger is more short arm). The floating arm's axle rolls on
/// a level rail while the counterweight, pinned to the short arm's end and hanging L3 below the
/// pin, falls in a vertical guide without turning (Trebuchator's "floating"). The whipper
/// (pytrebuchet's WhipperTrebuchet) is the hinged engine started with its long arm forward and
/// up, the counterweight and the projectile resting on the arm (whipper.hpp).
enum class MachineKind { hinged, fixed, floating_arm, whipper };

/// Historical engines start at rest with psi_i = phi_i = 0 (section 2).
struct ScaledDesign {
  double l = 0;  ///< L1/L2, scaled
  double l4 = 0;  ///< L4/L1, scaled
  double mu_b = 0;  ///< mb/M, scaled
  double mu = 0;  ///< m/M, scaled; a capacity fit sets it (section 4)
  double theta_i_deg = standard_theta_i_deg;  ///< initial beam angle from the downward vertical [deg]
  double F = standard_F;  ///< (L2 + L3)/H, H = L1 cos theta_i (section 2), scaled
  /// Initial counterweight angle psi_i [deg], one of the initial conditions: 0 hangs straight down, as
  /// historical engines were never propped (section 2). Measured from the downward vertical in
  /// the sense theta grows during a shot; a prop that holds the counterweight toward the pivot
  /// side of the hinge's fall is negative (sec:SVdH, section 7.2: the best for the paper's Villard engine
  /// of row 2 is psi_i = -4.6 deg).
  double psi_i_deg = 0;
  BuiltParts parts{};  ///< the engine as built; empty: the paper's ideal engine
  MachineKind machine = MachineKind::hinged;  ///< the paper's unless chosen
  /// The whipper's frame: the pivot's height over the base, in L2 (for the others it is the long
  /// arm's reach l cos theta_i, the tip resting on the base), and the projectile's radius, in L2,
  /// which sets where the ball rests on the arm (whipper.hpp). theta_i_deg is then its beam's start,
  /// -90 deg less the arm's angle above the horizontal, and psi_i_deg its rope's.
  std::optional<double> H{};
  double projectile_radius = 0;

  /// The pivot's height over the engine's base, in L2: H/L2 = l cos(theta_i) (section 2), or the
  /// whipper's as given.
  double pivot_height() const;
  /// L = L3/L2 = F H/L2 - 1 = F l cos(theta_i) - 1 (eq:Design), scaled; for the fixed counterweight
  /// and the floating arm 0 where that is within 1e-12 of it (their counterweight at the arm's end).
  double L() const;
  /// K = (l + 1)/mu_b (eq:kMkD), scaled.
  double K() const;
  /// The beam's moment of inertia about the pivot, I_b/(M L2^2): mu_b (l^2 - l + 1)/3 for the
  /// uniform rod (section 2), else as built.
  double beam_inertia() const;
  /// The distance of the beam's centre of mass from the pivot toward the tip, in L2: (l - 1)/2
  /// for the uniform rod, else as built.
  double beam_cm() const;
  /// The beam's short section as a body: for the uniform rod mass mu_b/(l + 1), centre at -1/2
  /// and inertia mu_b/(3 (l + 1)); none for a beam given only as a whole.
  std::optional<BuiltParts::Section> short_section() const;
  /// The counterweight's centre's distance from the pivot along the beam when it turns with it,
  /// as its weight's lever (in L2): 1 + L for the fixed counterweight, 1 (the hinge) for the others.
  double counterweight_lever() const;
  /// Delta U/(M g L2) of eq:DU: (1 - mu_b c)(1 + cos theta_i), c = beam_cm() ((l - 1)/2 in the
  /// paper), plus L (1 - cos psi_i) for a propped counterweight, which starts that much higher
  /// above its final rest, as the whipper's does: (lever - mu_b c)(1 + cos theta_i) for the
  /// machines whose counterweight moves with the beam.
  double energy_drop() const;
  /// The counterweight's fall from rest to its lowest point, in L2: Delta U without the beam's
  /// rise, lever (1 + cos theta_i) plus L (1 - cos psi_i) for a propped counterweight that hangs.
  double counterweight_fall() const;

 private:
  double fall_with_lever(double lever) const;
};

}  // namespace trebuchet
