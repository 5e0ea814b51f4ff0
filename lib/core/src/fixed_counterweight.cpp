#include "trebuchet/fixed_counterweight.hpp"

#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {

FixedCounterweight::FixedCounterweight(const ScaledDesign& design)
    : RigidBeamMachine(design, MachineKind::fixed, "fixed counterweight"), distance_(design_.counterweight_lever()) {
  if (design.parts.hinge_friction > 0)
    throw Error(ErrorKind::usage, "the fixed counterweight is bolted to the beam: it has no hinge pin; leave out {{hinge_friction}}");
  if (!(design.L() >= 0))
    throw Error(ErrorKind::numerical,
                "the fixed counterweight's centre lies inside the short arm: L3/L2 = F l cos(theta_i) - 1 = " + format_significant(design.L(), 4) +
                    " < 0; give {{L3}} >= 0, or a larger {{F}}");
}

// The counterweight, mass 1 at 1 + L along the short arm, turns with the beam: its kinetic
// energy is ((1 + L)^2 + I_c) th'^2/2.
RigidBeamMachine::Share FixedCounterweight::counterweight_share(double, const Path&) const {
  return {distance_ * distance_ + design_.parts.counterweight_inertia, 0};
}

double FixedCounterweight::counterweight_forces(Snapshot& out, const State& s, double th_dd, Vec2, Vec2, double base) const {
  const double d = distance_, st = std::sin(s.theta), ct = std::cos(s.theta), w2 = s.theta_dot * s.theta_dot,
               I_c = design_.parts.counterweight_inertia;
  out.hinge = {-st, ct};
  out.counterweight = {-d * st, d * ct};
  out.counterweight_height = d * ct - base;
  out.energies.counterweight = (d * d + I_c) * w2 / 2 + d * ct;
  // Its centre, at -d along the beam, accelerates by -d (cos th th'' - sin th th'^2, sin th th'' + cos th th'^2).
  out.hinge_force = {-d * (ct * th_dd - st * w2), -d * (st * th_dd + ct * w2) + 1};  // all the beam gives it but its weight
  // It pulls the beam at its centre and resists the turn with its own inertia.
  return d * (st * out.hinge_force.y + ct * out.hinge_force.x) - I_c * th_dd;
}

}  // namespace trebuchet
