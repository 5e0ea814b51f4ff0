// Two sweeps. The what-if sweep's values: one engine's value from one end to the other, whose
// shots the application makes (app/run/what_if.hpp). And a sweep along the X axis (Y = 0) of eq:XY_RT for one (theta_i, F) block: the ab-initio
// optimum (optimizer.hpp) at each X point, the data from which tab:CPNC is fitted
// (section 6.1, fig:fZ_vs_X). Points can be spread over threads and split into shards; the
// result depends on neither. A shard's points travel as a sweep part (JSON).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "trebuchet/capacity.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

struct SweepSpec {
  double theta_i_deg = standard_theta_i_deg;  ///< [deg]
  double F = standard_F;  ///< (L2 + L3)/H, scaled; not the other machines' (their counterweight at the arm's end)
  MachineKind machine = MachineKind::hinged;  ///< the machine every optimum is built as
  double X_from = -0.55, X_to = 0.55, X_step = 0.05;  ///< X of eq:Xi, scaled
  double R0 = 240, T0 = 26e3;  ///< reference capacity of tab:CPNC [m], [J]
  Material material{};  ///< beta2, wood and g of the engines (section 4)
  ReleaseCriterion criterion{};  ///< what each optimum maximises: eq:Q, eq:Q_n or Q_eps
};

/// The most X points a sweep may have.
inline constexpr int max_grid_points = 10000;

/// The X points of a sweep: the multiples of X_step in [X_from, X_to], so X = 0 is one of them
/// whenever the interval holds it. Throws Error(usage) for a step <= 0, an empty interval or
/// more than max_grid_points points.
std::vector<double> sweep_grid(const SweepSpec& spec);

/// The most points a what-if sweep may have.
inline constexpr int max_what_if_points = 1000;

/// The values of a what-if sweep: `points` values evenly spaced from `from` to `to`, both ends
/// exact. Throws Error(usage) for fewer than 2 or more than max_what_if_points points, and
/// Error(bad_number) for ends that are not finite or not from < to.
std::vector<double> what_if_values(double from, double to, int points);

/// Part k (1-based) of n: every n-th grid point from the k-th, so that parts cost about the same.
struct Shard {
  int k = 1, n = 1;
};

/// The optimum at one X point (capacity_at(X, 0)), or the reason there is none.
struct SweepPoint {
  double X = 0;  ///< scaled
  Capacity capacity;  ///< [m], [J], level 0
  std::string error;  ///< empty when the point has an optimum
  Engine engine;  ///< the optimum, fitted to the capacity
  Verification shot;  ///< its shot at the best release (Q, eps, force_factor, theta_release_deg travel in parts)
  int simulations = 0;  ///< shots of the whole search
  int optima_found = 0;  ///< distinct optima from the starts (two where branches compete)
};

/// Optimises every point of the shard, thread_count(threads, points) at a time (parallel.hpp),
/// telling `progress` of each point done. Results are in grid order.
std::vector<SweepPoint> run_sweep(const SweepSpec& spec, Shard shard, int threads, const Progress& progress = {});

/// A shard's points with the spec that made them, and where they were read from.
struct SweepPart {
  std::string origin;  ///< for messages: a file name, or "the sweep"
  SweepSpec spec;
  Shard shard;
  std::vector<SweepPoint> points;
};

}  // namespace trebuchet
