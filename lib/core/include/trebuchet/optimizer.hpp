// The ab-initio optimum for a capacity (section 5): the shape (l, l4, mu_b) that maximises the
// quality when each candidate is fitted to deliver (R, T) exactly (capacity_fit.hpp). GSL's
// Nelder-Mead simplex in (log l, log l4, log mu_b), started from the calculator's designs.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/capacity_fit.hpp"

namespace trebuchet {

/// The largest beam ratio l = L1/L2 the optimizer considers: appendix B's formal engine has 59.
inline constexpr double max_beam_ratio = 60;

struct OptimizeRequest {
  Capacity capacity;  ///< R [m] and T [J] at level 0
  /// m [kg]: optimise for the range R and this projectile mass, T free (capacity.T is not used).
  std::optional<double> projectile_mass;
  double theta_i_deg = standard_theta_i_deg;  ///< [deg]
  double F = standard_F;  ///< (L2 + L3)/H, scaled
  /// The machine every shape is built as; the fixed counterweight and the floating arm with the
  /// counterweight at the short arm's end (L3 = 0), F unused.
  MachineKind machine = MachineKind::hinged;
  Material material{};
  ShotSettings settings{};  ///< release criterion (Q, Q_n or Q_eps) and integrator
  double shape_tolerance = 1e-4;  ///< simplex size in log shape at which a search stops, scaled
  std::vector<ScaledDesign> starts;  ///< when given, searches start at these shapes instead of the calculator's designs
  /// Appendix B: hold the beam ratio l = L1/L2 at this value and search (l4, mu_b) alone, on
  /// each side of l4 = 1, where the paper finds the efficiency's two maxima.
  std::optional<double> fixed_l;
};

struct Optimum {
  std::string start;  ///< where the search began ("calculator, lower branch", ...)
  ScaledDesign start_design;  ///< the shape it began from
  CapacityFit fit;  ///< the best engine (its design, SI engine and shot) and the shots of its last fit
  double objective = 0;  ///< the maximised quality
  int simulations = 0;  ///< shots over the whole search
  int iterations = 0;  ///< simplex iterations
  /// With a fixed l: where the best shape found is no interior maximum of its side, why (it
  /// lies at l4 = 1, the side's edge, or at the least mu_b searched); empty otherwise.
  std::string note;
};

/// One search per start; each result delivers (R, T) to 1e-6. Starts are the request's, else the
/// calculator's designs for the capacity (both branches where tab:CPNC has two) when it covers
/// it, else a generic shape. Throws Error(out_of_range) when no start can deliver the capacity.
std::vector<Optimum> optimize(const OptimizeRequest& request);

/// The optimum with the highest objective (the first of equals), as a copy, so that it may
/// outlive `optima`; `optima` must not be empty.
Optimum best_optimum(const std::vector<Optimum>& optima);

}  // namespace trebuchet
