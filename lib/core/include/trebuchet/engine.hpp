// An engine in absolute SI terms (eq:Parameters) with the material it is built of, and what
// follows from it: its scaled design (eq:Design), geometry and stored energy (eq:DU).
#pragma once

#include <optional>
#include <string>

#include "trebuchet/design.hpp"
#include "trebuchet/material.hpp"

namespace trebuchet {

/// The whipper's initial beam angle unless given [deg]: pytrebuchet's default, the long arm 60 deg
/// above the horizontal, forward.
inline constexpr double whipper_theta_i_deg = -150;

/// A pin that carries a load while its parts turn on it: Coulomb friction gives a torque of
/// F r mu/sqrt(1 + mu^2) against the turn, F the force it carries (the friction circle of a
/// journal in its bearing; mu r F to first order).
struct Pin {
  double friction = 0;  ///< coefficient of sliding friction mu, scaled
  double radius = 0;  ///< r [m]
};

/// What a real engine adds to the paper's ideal one (docs/verifier.md, "Real engines"); each
/// part is ideal until given.
struct EngineParts {
  /// The beam as built instead of the uniform rod of mass mb (section 2): the distance of its
  /// centre of mass from the pivot toward the tip [m] and its moment of inertia about the pivot
  /// [kg m^2], both or neither.
  std::optional<double> beam_cm, beam_inertia;
  /// Or, for the inertia, the radius of gyration k about the pivot [m]: I = mb k^2, with mb as
  /// the run has it (from D and the run's wood, when it follows from them).
  std::optional<double> beam_gyration;
  /// A round beam of the engine's wood whose diameter runs linearly from D_hinge at the short
  /// end to D_tip at the long one [m]; it gives mb, the centre of mass, the inertia, and D at the pivot.
  std::optional<double> D_hinge, D_tip;
  double counterweight_inertia = 0;  ///< about the counterweight's own centre of mass [kg m^2]
  /// A box counterweight's sides [m], both or neither: where it is read, they give its inertia
  /// (M (w^2 + h^2)/12, but the floating arm's, which does not turn); the height also gives its
  /// clearance above the ground (Verification::Clearance).
  std::optional<double> box_width, box_height;
  Pin axle;  ///< the axle at the pivot
  Pin hinge;  ///< the counterweight's hinge pin
  double trough_friction = 0;  ///< mu of the projectile on the trough, scaled
  double rope_diameter = 0;  ///< of the sling's rope, for its drag in air [m]; 0: none
  double rope_cd = 1.2;  ///< Cd of the rope across the flow (a long cylinder), scaled
  /// The sling as built (docs/machines.md, "The sling's mass"): its rope's mass, spread evenly
  /// along L4, and its pouch's, a point at the rope's end that carries the projectile until the
  /// release and stays with the sling after it [kg].
  double rope_mass = 0, pouch_mass = 0;
  /// mu of the sling's loop on the release pin, scaled: it slips off atan(mu) past the pin angle
  /// where it would leave a frictionless pin (verification.hpp, release_pin_angle).
  double pin_friction = 0;

  /// Whether any part is given: the engine is not the paper's ideal one.
  bool any() const;
};

/// A swinging counterweight trebuchet at rest before a shot (psi_i = phi_i = 0, section 2).
/// theta_i is measured between the long beam section and the downward vertical.
struct Engine {
  double L1 = 0;  ///< long beam section, pivot to spigot [m]
  double L2 = 0;  ///< short beam section, pivot to hinge [m]
  double L3 = 0;  ///< counterweight arm, hinge to counterweight [m]
  double L4 = 0;  ///< sling, spigot to projectile [m]
  double D = 0;  ///< beam diameter [m]; not in the equations of motion
  double M = 0;  ///< counterweight mass [kg]
  double m = 0;  ///< projectile mass [kg]
  double mb = 0;  ///< beam mass [kg]
  double theta_i_deg = standard_theta_i_deg;  ///< initial beam angle theta_i [deg]
  double psi_i_deg = 0;  ///< initial counterweight angle [deg]: 0 unpropped (design.hpp gives the sign)
  Material material{};  ///< beta2, wood and g: what sized it, and the g it is shot under
  EngineParts parts{};  ///< as built; empty: the paper's ideal engine
  /// The machine it is built as; for the fixed counterweight and the floating arm L3 places the
  /// counterweight's centre beyond the short arm's end, or below its pin, and may be 0 (design.hpp).
  MachineKind machine = MachineKind::hinged;
  /// The projectile's diameter [m]: with m, its density, and so its drag in air
  /// (verification.hpp, settings_for); the whipper's ball also rests on its arm by it. None: a
  /// sphere of the air's projectile density, or the whipper's of stone in vacuum.
  std::optional<double> projectile_diameter;
  /// The whipper's start (whipper.hpp) besides theta_i (-90 deg less its long arm's angle above
  /// the horizontal, forward: pytrebuchet's 60 deg is -150): its pivot's height over the base
  /// [m] and its counterweight's rope's angle off the arm [deg] (pytrebuchet's 10).
  struct WhipperStart {
    double H = 0;
    double rope_angle_deg = 10;
  };
  WhipperStart whipper{};
};

/// The scaled design of eq:Design, with F from the counterweight arm, and the engine's parts
/// scaled (BuiltParts; the drag before the release comes with a shot's settings, verification.hpp).
ScaledDesign scaled_design(const Engine& engine);

/// The beam of a tapered engine (EngineParts::D_hinge, D_tip) as bodies about the pivot [kg, m,
/// kg m^2]: the whole and its short section; mb is the whole's mass.
struct TaperedBeam {
  BuiltParts::Section whole, short_section;
  double D_pivot = 0;  ///< the diameter at the pivot [m]
};
TaperedBeam tapered_beam(double L1, double L2, double D_hinge, double D_tip, double wood_density);

/// The moment of inertia about the pivot of a beam given by its centre of mass [kg m^2]: as
/// given, or mb k^2 from its radius of gyration; none for the uniform or the tapered beam.
std::optional<double> given_beam_inertia(const Engine& engine);

/// The mass of the engine's beam from its wood [kg]: tapered (EngineParts::D_hinge, D_tip), or
/// round of diameter D (eq:BeamMass).
double wood_beam_mass(const Engine& engine);

/// The engine of a scaled design at short arm L2 [m] (eq:Design), its counterweight mass and
/// beam diameter from eq:ExtraScalings, m = mu M and mb = mu_b M; a whipper's frame, rope angle
/// and ball as the design has them.
Engine engine_of(const ScaledDesign& design, double L2, const Material& material);

/// The validation every engine passes, given or computed: lengths and masses positive (mb may
/// be 0), theta_i in (0, 90) degrees (the whipper's in (-180, -90]), a positive material. Throws Error(bad_number) naming the
/// parameter by its key, "{{L4}}" (error.hpp).
void check_engine(const Engine& engine);

double beam_length(const Engine& engine);  ///< Lb = L1 + L2 [m]
double pivot_height(const Engine& engine);  ///< H = L1 cos(theta_i), or the whipper's [m]
double arm_fraction(const Engine& engine);

/// Gives `engine` (its machine and M set) a box counterweight of these sides [m]: kept in its
/// parts, with its inertia M (w^2 + h^2)/12 about its centre (0 on the floating arm, whose box
/// falls in its guide without turning).
void give_box(Engine& engine, double width, double height);  ///< F = (L2 + L3)/H, section 2, scaled

/// L3 from L2 + L3 = F H, H = L1 cos(theta_i) (section 2) [m].
double counterweight_arm(double L1, double L2, double theta_i_deg, double F);

/// Delta U of eq:DU: potential energy released by a whole shot, under the engine's g [J].
double potential_energy_drop(const Engine& engine);

/// The engine with its lengths (the whipper's H and ball too), masses and D multiplied by the size factors (eq:ExtraScalings).
Engine resized(const Engine& engine, const SizeFactors& factors);

}  // namespace trebuchet
