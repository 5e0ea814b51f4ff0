// The calculator: optimal engines from the fitted constants of tab:CPNC (section 6).
// From (R, T) it applies eq:ZRT; from any other pair of givens it first inverts the
// log-linear relations (eq:RT_ZiZj, eq:ZiZj_RT) in every X-segment and keeps the solutions
// whose X (eq:Xi) lies inside that segment.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/capacity.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/material.hpp"
#include "trebuchet/quantity.hpp"
#include "trebuchet/scaling_table.hpp"

namespace trebuchet {

enum class BranchChoice { automatic, lower, upper };

/// A given value: SI base units (m, kg, J); l is scaled.
struct Given {
  Quantity quantity;
  double value;
};

/// What the user asks for; every default is the paper's standard (section 2, eq:kMkD).
struct DesignRequest {
  Given first{Quantity::R, 0};
  Given second{Quantity::T, 0};
  double theta_i_deg = standard_theta_i_deg;  ///< initial beam angle [deg]; tab:CPNC has 30 and 40
  double F = standard_F;  ///< (L2 + L3)/H, scaled; tab:CPNC has 1 and 2/3
  BranchChoice branch = BranchChoice::automatic;
  Material material{};  ///< may differ from the table's; masses, D and T follow by size_factors
  bool extrapolate = false;  ///< use the nearest segment when X is outside all of them
  double scale = 1;  ///< print the optimum at this factor of its size (a model), scaled
};

/// An optimal engine with the capacity it is designed for.
struct OptimalEngine {
  Engine engine;  ///< with the request's material
  Capacity capacity;  ///< range in vacuum and energy eq:T at the engine's base level [m], [J]
  CapacityCoordinates coordinates;  ///< X, Y of eq:XY_RT in the table's material (masses and T rescaled), scaled
  Branch branch = Branch::none;
  double segment_X_min = 0;  ///< interval of the tab:CPNC segment used
  double segment_X_max = 0;
  double F = 0;  ///< (L2 + L3)/H, scaled
  /// Worst-case relative error of R or T per relative error of the givens (1 for R, T given);
  /// large values mean a near-singular pair (small |D_ij| of eq:ZiZj_RT).
  double amplification = 1;
  /// S_Z = Z_upper/Z_lower at X_d (eq:ZiZj_vs_X), set when X lies where both branches exist.
  std::optional<std::array<double, param_count>> branch_steps;
  /// Set for a model (--scale): the factor of the optimum's size it is built at, and the
  /// capacity of the full-size optimum it was scaled from.
  struct Scaling {
    double factor;
    Capacity full_size;
  };
  std::optional<Scaling> scaled_from;
  std::vector<std::string> warnings;
};

/// The optimal engine for a request, scaled by request.scale. Throws Error(given_count) for an
/// unusable pair, Error(out_of_range) when no (theta_i, F) block or no X-segment gives a
/// consistent solution, and Error(bad_number) when the givens, the material or the scale
/// are so extreme that a number of the engine leaves the range of doubles.
OptimalEngine design_optimal_engine(const ScalingTable& table, const DesignRequest& request);

/// The value of a quantity in a design, in SI units (l scaled): what the same quantity given
/// would have to be to ask for this design.
double quantity_value(const OptimalEngine& design, Quantity quantity);

/// S_Z of eq:ZiZj_vs_X for a block with two branches, at the block's X_d; nullopt without.
std::optional<std::array<double, param_count>> branch_steps(const TableBlock& block);

/// The same optimal engine at lambda times the size (lengths lambda, D lambda^1.5, masses
/// lambda^4, T lambda^5); X is unchanged, so it stays optimal (eq:ExtraScalings). Throws
/// Error(bad_number) when a number leaves the range of doubles.
OptimalEngine scale_optimal_engine(const OptimalEngine& design, double lambda);

}  // namespace trebuchet
