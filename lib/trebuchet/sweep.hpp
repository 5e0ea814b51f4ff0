// A sweep along the X axis (Y = 0) of eq:XY_RT for one (theta_i, F) block: the ab-initio
// optimum (optimizer.hpp) at each X point, the data from which tab:CPNC is fitted
// (section 5.1, fig:fZ_vs_X). Points can be spread over threads and split into shards; the
// result depends on neither.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/scaling_table.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

struct SweepSpec {
  double theta_i_deg = 30;  ///< [deg]
  double F = 2.0 / 3;       ///< (L2 + L3)/H, scaled
  double X_from = -0.55, X_to = 0.55, X_step = 0.05;  ///< X of eq:Xi, scaled
  double R0 = 240, T0 = 26e3;  ///< reference capacity of tab:CPNC [m], [J]
  Material material{};      ///< beta2, wood and g of the engines (section 4)
  Quality quality{};        ///< what each optimum maximises: eq:Q, eq:Q_n or Q_eps
};

/// The X points of a sweep: the multiples of X_step in [X_from, X_to], so X = 0 is one of them
/// whenever the interval holds it. Throws Error(usage) for a step <= 0 or an empty interval.
std::vector<double> sweep_grid(const SweepSpec& spec);

/// A capacity on the X axis: eq:XY_RT inverted at Y = 0.
struct AxisCapacity {
  double R;  ///< R0 e^{5X/sqrt26} [m]
  double T;  ///< T0 e^{-X/sqrt26} [J]
};

AxisCapacity capacity_on_X_axis(double X, double R0, double T0);

/// Part k (1-based) of n: every n-th grid point from the k-th, so that parts cost about the same.
struct Shard {
  int k = 1, n = 1;
};

/// Parses "k/N" with 1 <= k <= N; Error(usage) names the text and the fix.
Shard parse_shard(const std::string& text);

/// The optimum at one X point (capacity_on_X_axis), or the reason there is none.
struct SweepPoint {
  double X = 0;
  double R = 0, T = 0;          ///< capacity [m], [J]
  std::string error;            ///< empty when the point has an optimum
  Engine engine;                ///< the optimum, fitted to (R, T)
  Verification shot;            ///< its shot at the best release
  EngineShape shape;            ///< its shape, scaled
  int simulations = 0;          ///< shots of the whole search
  int optima_found = 0;         ///< distinct optima from the starts (two where branches compete)
};

/// Optimises every point of the shard, `threads` at a time; `progress(done, total)` is called
/// after each point, from one thread at a time. Results are in grid order.
std::vector<SweepPoint> run_sweep(const SweepSpec& spec, Shard shard, int threads,
                                  const std::function<void(int, int)>& progress = {});

/// A sweep part as JSON: the spec, the shard and its points, numbers written to round-trip.
nlohmann::ordered_json sweep_json(const SweepSpec& spec, Shard shard, const std::vector<SweepPoint>& points);

}  // namespace trebuchet
