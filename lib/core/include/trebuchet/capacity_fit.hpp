// The capacity fit of section 5, steps 2-4: a scaled design (l, l4, mu_b) at theta_i and F is
// given a projectile ratio mu and an absolute size so that it delivers a requested capacity
// (R, T) at level 0. The work is scaled: a shot gives rho = R/L2 and tau_e = T/(M g L2)
// (eq:Aux), so L2 = R/rho, and eq:ExtraScalings gives T = M g L2 tau_e; mu is adjusted until
// T matches. The engine is made in SI once, at the end.
#pragma once

#include "trebuchet/capacity.hpp"
#include "trebuchet/design.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/material.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// Refuses (Error(bad_number), naming {{R}}, {{T}} or {{m}}) a capacity outside the ordinary, so
/// that every guess and trial of a fit stays finite: R from 1e-6 to 1e6 m, and the stone it takes,
/// `target` itself (a mass [kg]) or, with `energy`, m = 2T/(g R) from T = `target` [J] (section 4),
/// from 1e-9 to 1e12 kg.
void check_capacity_size(double R, double target, bool energy, const Material& material);

struct CapacityFit {
  ScaledDesign design;  ///< the shape with its fitted mu
  Engine engine;  ///< the design at the size that delivers the capacity, in SI
  Verification verification;  ///< of `engine`, at the shot settings of the fit
  int simulations = 0;  ///< shots it took
};

/// Fits mu and the size of `shape` so that its shot lands at R [m] with T [J], each to `rtol`
/// relative, both measured as verify_engine measures them under `settings`: at its target level,
/// through its air, from the pivot or from the release (capacity.target_level is not used). In
/// vacuum to level 0 from the pivot, the paper's, one shot gives the size (section 5); otherwise
/// the size is solved for by shots of the engine in SI. The search for mu starts from
/// shape.mu when it is positive (a warm start, e.g. a neighbouring shape's fitted mu), else from
/// the guess m = 2T/(g R) of section 4. Throws
/// Error(out_of_range) when no mu within a factor 20 of the guess m = 2T/(g R) reaches T, and
/// Error(numerical) when T jumps with mu at the root (the release moves between maxima). The
/// engine it returns passes check_engine, has eps <= 1 and its shot conserved energy.
CapacityFit fit_capacity(const ScaledDesign& shape, const Capacity& capacity, const Material& material, const ShotSettings& settings,
                         double rtol = 1e-6);

/// As fit_capacity, for a range R [m] and a projectile mass m [kg] (a capacity as historians
/// state it): mu and the size are fitted so that the shot lands at R with m = mu M, each to
/// `rtol` relative; T is what follows.
CapacityFit fit_range_and_mass(const ScaledDesign& shape, double R, double m, const Material& material, const ShotSettings& settings,
                               double rtol = 1e-6);

}  // namespace trebuchet
