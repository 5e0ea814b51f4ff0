// What the machines whose counterweight moves with the beam share (issue 36): the fixed
// counterweight (fixed_counterweight.hpp) and the floating arm (floating_arm.hpp). Their beam and
// counterweight are one body of one degree of freedom, the beam's angle theta, whose pivot may
// run along a level rail; the sling and its trough are the paper's (appendix A). Scaled as
// dynamics.hpp says: lengths in L2, masses in M, time in (L2/g)^(1/2), forces in M g. psi
// follows the beam (psi'' = theta''), phi is the sling's angle. A machine gives the pivot's path
// a(theta) (it stays at the height of the frame's pivot), the counterweight's share of the
// body's inertia and its forces; the equations of the three phases follow here from the
// Lagrangian (docs/machines.md, "The equations"). The engine as built adds the axle's friction,
// the floating arm's pin's, the trough's and the air on the projectile before the release, as
// generalized forces (docs/machines.md, "Friction and air").
#pragma once

#include <array>
#include <optional>

#include "trebuchet/design.hpp"
#include "trebuchet/machine.hpp"

namespace trebuchet {

class RigidBeamMachine : public Machine {
 public:
  const ScaledDesign& design() const override { return design_; }
  double theta_i() const override { return theta_i_; }
  double trough_cos_phi(double theta) const override;
  double complete_trough_state(State& state) const override;
  Snapshot snapshot(Phase phase, const State& state) const override;
  Evaluated accelerations(Phase phase, const State& state, std::array<double, 3>& out, Losses* loss_power = nullptr) const override;
  bool dissipates() const override { return design_.parts.dissipates(); }

 protected:
  /// `design` built as `kind`, which the user knows as `name`; the sling's rope drag is refused
  /// (Error(usage)), a propped counterweight is not this machine's (psi_i = 0).
  RigidBeamMachine(const ScaledDesign& design, MachineKind kind, const char* name);

  /// Whether the counterweight turns with the beam (the fixed one) or keeps its attitude (the
  /// floating arm's, in its guide): psi follows theta, or stays 0. Its pin's friction, if it has
  /// a pin, acts on the beam's turn relative to it.
  virtual bool counterweight_turns() const = 0;

  /// The pivot's position along x and its first two derivatives in theta, scaled (L2).
  struct Path {
    double x = 0, slope = 0, curve = 0;
  };
  virtual Path pivot_path(double theta) const = 0;

  /// The counterweight's kinetic energy is inertia theta_dot^2/2: its inertia in that sense
  /// (M L2^2) and its derivative in theta.
  struct Share {
    double inertia = 0, slope = 0;
  };
  virtual Share counterweight_share(double theta, const Path& pivot) const = 0;

  /// Fills the counterweight's place (out.hinge, out.counterweight, out.counterweight_height
  /// with `base` the pivot's height over the engine's base), its energy and the force of the
  /// beam on it (out.hinge_force), given the pivot's position, the beam's angular acceleration
  /// and what the beam needs besides that force to move as it does (`need`, its mass times the
  /// acceleration of its centre, its weight and the sling's pull: the frame gives
  /// out.hinge_force + need at the pivot). Returns the counterweight's moment on the beam about
  /// the pivot (for the bending moment, M g L2).
  virtual double counterweight_forces(Snapshot& out, const State& state, double theta_ddot, Vec2 pivot, Vec2 need, double base) const = 0;

  ScaledDesign design_;
  double theta_i_;  // [rad]

 private:
  double weight_;  // G = lever - mu_b c: the body's potential is G cos(theta), scaled (M g L2)
  /// The body's inertia J(theta) about theta (beam and counterweight) and dJ/dtheta.
  Share body_inertia(double theta, const Path& pivot) const;
  /// Generalized forces on theta and phi (M g L2) besides gravity's.
  struct Generalized {
    double theta = 0, phi = 0;
  };
  std::array<double, 3> accelerations_of(Phase phase, const State& state, Generalized extra) const;
  /// The snapshot of a state whose accelerations are `a`, with the air's force on the projectile
  /// `drag` and the trough's friction `friction` (along x), scaled.
  Snapshot snapshot_with(Phase phase, const State& state, const std::array<double, 3>& a, Vec2 drag, double friction) const;
  /// The accelerations with the losses, settled by fixed-point iteration on the forces they
  /// depend on, and the snapshot there with each loss's power; none where they do not settle.
  std::optional<Snapshot> resisted(Phase phase, const State& state) const;
};

}  // namespace trebuchet
