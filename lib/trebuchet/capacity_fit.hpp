// The capacity fit of section 5, steps 2-4: a scaled design (l, l4, mu_b) at theta_i and F
// is given an absolute size and a projectile ratio mu so that it delivers a requested
// capacity (R, T). The size follows from R, the masses from the size by eq:ExtraScalings,
// and mu is adjusted until T matches.
#pragma once

#include "trebuchet/engine.hpp"
#include "trebuchet/material.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// A scaled design without mu: the shape of an engine.
struct EngineShape {
  double l = 0;            ///< L1/L2, scaled
  double l4 = 0;           ///< L4/L1, scaled
  double mu_b = 0;         ///< mb/M, scaled
  double theta_i_deg = 30; ///< [deg]
  double F = 2.0 / 3;      ///< (L2 + L3)/H, eq:Design
};

/// The shape of an engine, with F from its counterweight arm.
EngineShape engine_shape(const Engine& engine);

/// The engine of this shape with short arm L2 [m] and projectile ratio mu: M from
/// eq:ExtraScalings, m = mu M, mb = mu_b M, D from eq:ExtraScalings.
Engine engine_of_shape(const EngineShape& shape, double mu, double L2, const Material& material);

struct CapacityFit {
  Engine engine;
  Verification verification;  ///< of `engine`, at the shot settings of the fit
  int simulations = 0;        ///< shots it took
};

/// Fits mu and the size so that the shot of the engine lands at R [m] with T [J] at level 0,
/// each to `rtol` relative. Throws Error(out_of_range) when no mu in (1e-6, 1) reaches T,
/// and the shot's Error(numerical) when a trial shot fails.
CapacityFit fit_capacity(const EngineShape& shape, double R, double T, const Material& material,
                         const ShotSettings& settings, double rtol = 1e-6);

}  // namespace trebuchet
