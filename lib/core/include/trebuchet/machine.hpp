// The seam between a machine that throws and the shot that integrates it (shot.hpp). A machine
// gives its scaled design and the equations of motion of the three phases in the coordinates of
// State: the beam's angle theta, the counterweight's psi and the sling's phi, scaled as
// dynamics.hpp says (lengths in L2, masses in M, time in (L2/g)^(1/2), forces in M g). Phase I
// carries the projectile in the trough, phase II swings it in the sling until the release,
// phase III goes on without it. The shot finds the lift-off, the release and the forces of
// eq:F for any machine; the paper's engine of appendix A is Dynamics (dynamics.hpp).
#pragma once

#include <array>
#include <cmath>
#include <memory>

#include "trebuchet/design.hpp"
#include "trebuchet/dynamics_types.hpp"

namespace trebuchet {

/// Phase I is singular where the sling stands vertical (cos phi = 0 in eq:EOM_I_1). A machine's
/// accelerations refuse trial states with cos phi at or below this, so GSL shortens the step
/// rather than evaluate the equations near the singularity; the shot abandons phase I at twice
/// this value.
inline constexpr double refuse_trough_cos_phi = 0.01;

/// What Machine::accelerations found: the accelerations; a trial state of the trough too near its
/// singularity (refuse_trough_cos_phi), which a shorter step avoids; or none (friction that does
/// not settle, or accelerations that are not finite).
enum class Evaluated { found, near_trough_singularity, failed };

class Machine {
 public:
  virtual ~Machine() = default;

  /// The design the release is measured in: l and mu for Q (eq:Q), Delta U for eps (eq:Aux,
  /// energy_drop), theta_i and psi_i for the initial state (eq:InitialConditions), the parts'
  /// friction that may hold a pin, and the pivot's height l cos(theta_i) above the base.
  virtual const ScaledDesign& design() const = 0;

  /// The initial beam angle [rad].
  virtual double theta_i() const = 0;

  /// cos phi of the sling in the trough at beam angle theta (0 where it would stand vertical or
  /// beyond): the shot abandons phase I as it nears 0.
  virtual double trough_cos_phi(double theta) const = 0;

  /// Fills phi and phi_dot of a phase-I state from the trough's constraint; returns cos phi.
  virtual double complete_trough_state(State& state) const = 0;

  /// Accelerations and forces at a state of the given phase.
  virtual Snapshot snapshot(Phase phase, const State& state) const = 0;

  /// The accelerations (theta, psi, phi) alone, the right-hand side of the ODE; with losses,
  /// their powers. Where they are not found, `out` is not set: a trough state whose cos phi is
  /// not above refuse_trough_cos_phi is refused as such, whatever fails else is `failed`. In the
  /// trough, phi and phi_dot of `state` are not set (the integrator carries theta and psi): they
  /// follow from theta by the trough's constraint, as in snapshot.
  virtual Evaluated accelerations(Phase phase, const State& state, std::array<double, 3>& out, Losses* loss_power = nullptr) const = 0;

  /// Whether the machine loses energy other than to its bodies: the shot then integrates the
  /// work of each loss (Losses).
  virtual bool dissipates() const = 0;

  /// Whether the sling swings on after the release: where it has mass (sling.hpp).
  bool swings_after_release() const { return design().parts.sling.any(); }

  /// The phase a shot starts in: the trough, or the whipper's `held`.
  virtual Phase first_phase() const { return Phase::trough; }

  /// The beam angle [rad] past which a phase is given up: the projectile still in the trough when
  /// the beam stands upright (pi), and no release once the beam has turned a whole turn.
  virtual double turn_limit(Phase phase) const { return phase == Phase::trough ? M_PI : theta_i() + 2 * M_PI; }
};

/// The machine a design is built as (ScaledDesign::machine): the paper's engine (Dynamics), the
/// fixed counterweight, the floating arm or the whipper. Throws Error(numerical) for a design that cannot
/// shoot: no room for the hinged counterweight's arm, a counterweight inside the short arm or
/// above its pin (L < 0), or a beam whose long arm outweighs the counterweight.
std::unique_ptr<Machine> machine_of(const ScaledDesign& design);

/// Why the whipper is shot but not designed: optimize, contest, derive-table and the calculator
/// refuse it with this (docs/machines.md, "The whipper").
inline constexpr const char* whipper_not_designed =
    "the whipper is shot here, not designed: its shape has four parameters of its own (theta_i, the rope's angle, the frame's height H and "
    "the rope L3) where the other machines' have theta_i and F, and neither its optimizer nor its scaling table is built; shoot a whipper "
    "with trebuchet-verify shot --machine whipper";

}  // namespace trebuchet
