#include "trebuchet/machine.hpp"

#include <string>

#include "trebuchet/dynamics.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/fixed_counterweight.hpp"
#include "trebuchet/floating_arm.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/whipper.hpp"

namespace trebuchet {

std::unique_ptr<Machine> machine_of(const ScaledDesign& e) {
  const auto refuse = [](const std::string& reason) { throw Error(ErrorKind::numerical, reason); };
  if (e.machine == MachineKind::hinged && !(e.L() > 0))
    refuse("no room for the counterweight arm: L3/L2 = F l cos(theta_i) - 1 = " + format_significant(e.L(), 4) +
           " <= 0 (eq:Design); raise F or l, or lower theta_i");
  if (e.machine == MachineKind::whipper && !(e.L() > 0))
    refuse("the whipper's counterweight hangs on a rope: L3/L2 = F H/L2 - 1 = " + format_significant(e.L(), 4) + " <= 0; give {{L3}} > 0");
  std::unique_ptr<Machine> machine;
  switch (e.machine) {
    case MachineKind::hinged: machine = std::make_unique<Dynamics>(e); break;
    case MachineKind::fixed: machine = std::make_unique<FixedCounterweight>(e); break;
    case MachineKind::floating_arm: machine = std::make_unique<FloatingArm>(e); break;
    case MachineKind::whipper: machine = std::make_unique<Whipper>(e); break;
  }
  const double lever = e.counterweight_lever();
  if (!(lever - e.mu_b * e.beam_cm() > 0))
    refuse("the beam cannot turn: " + std::string(e.parts.beam ? "mu_b c (c its centre of mass from the pivot, in L2) = " : "mu_b (l - 1)/2 = ") +
           format_significant(e.mu_b * e.beam_cm(), 4) + " >= " + format_significant(lever, 4) +
           ", its long arm outweighs the counterweight (eq:DU); lighten the beam or shorten L1");
  return machine;
}

}  // namespace trebuchet
