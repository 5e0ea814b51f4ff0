// The ab-initio optimum for a capacity (section 5): the shape (l, l4, mu_b) that maximises the
// quality when each candidate is fitted to deliver (R, T) exactly (capacity_fit.hpp). GSL's
// Nelder-Mead simplex in (log l, log l4, log mu_b), started from the calculator's designs.
#pragma once

#include <string>
#include <vector>

#include "trebuchet/capacity_fit.hpp"

namespace trebuchet {

struct OptimizeRequest {
  double R = 0, T = 0;          ///< capacity [m], [J]
  double theta_i_deg = 30;      ///< [deg]
  double F = 2.0 / 3;           ///< (L2 + L3)/H
  Material material{};
  ShotSettings settings{};      ///< quality (Q, Q_n or Q_eps) and integrator
  double shape_tolerance = 1e-4;  ///< simplex size in log shape at which a search stops
  std::vector<EngineShape> starts;  ///< when given, searches start here instead of at the calculator's designs
};

struct Optimum {
  std::string start;            ///< where the search began ("calculator, lower branch", ...)
  EngineShape start_shape;      ///< the shape it began from
  CapacityFit fit;              ///< the best engine, its shot and the shots of its last fit
  EngineShape shape;
  double objective = 0;         ///< the maximised quality
  int simulations = 0;          ///< shots over the whole search
  int iterations = 0;           ///< simplex iterations
};

/// One search per start; each result delivers (R, T) to 1e-6. Starts are the request's, else the
/// calculator's designs for the capacity (both branches where tab:CPNC has two) when it covers
/// it, else a generic shape. Throws Error(out_of_range) when no start can deliver the capacity.
std::vector<Optimum> optimize(const OptimizeRequest& request);

/// The optimum with the highest objective (the first of equals), as a copy, so that it may
/// outlive `optima`; `optima` must not be empty.
Optimum best_optimum(const std::vector<Optimum>& optima);

}  // namespace trebuchet
