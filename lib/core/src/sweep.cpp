#include "trebuchet/sweep.hpp"

#include <algorithm>
#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/machine.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/parallel.hpp"

namespace trebuchet {

std::vector<double> sweep_grid(const SweepSpec& spec) {
  if (!std::isfinite(spec.X_from) || !std::isfinite(spec.X_to) || !std::isfinite(spec.X_step))
    throw Error(ErrorKind::usage, "the X grid needs finite numbers from:to:step; e.g. -0.55:0.55:0.05");
  if (!(spec.X_step > 0)) throw Error(ErrorKind::usage, "the X step must be positive, got " + format_number(spec.X_step) + "; e.g. -0.55:0.55:0.05");
  if (!(spec.X_from <= spec.X_to) || !std::isfinite(spec.X_from) || !std::isfinite(spec.X_to))
    throw Error(ErrorKind::usage,
                "the X interval [" + format_number(spec.X_from) + ", " + format_number(spec.X_to) + "] is empty; give from:to:step with from <= to");
  // Multiples of the step, so that X = 0 (Z0 of tab:CPNC) is on the grid; 1e-9 absorbs the
  // rounding of from/step when from is itself a multiple. The count is checked in doubles,
  // before anything is converted to an integer or allocated.
  const double first_multiple = std::ceil(spec.X_from / spec.X_step - 1e-9);
  const double last_multiple = std::floor(spec.X_to / spec.X_step + 1e-9);
  if (!(last_multiple - first_multiple < max_grid_points))
    throw Error(ErrorKind::usage,
                "the X grid from " + format_number(spec.X_from) + " to " + format_number(spec.X_to) + " in steps of " + format_number(spec.X_step) +
                    " has more than " + std::to_string(max_grid_points) + " points; use a larger step or a shorter interval");
  const long first = static_cast<long>(first_multiple), last = static_cast<long>(last_multiple);
  std::vector<double> grid;
  // Rounded to 1e-12 so that i * step prints as the user wrote it (-0.3, not -0.30000000000000004).
  for (long i = first; i <= last; ++i) grid.push_back(std::nearbyint(static_cast<double>(i) * spec.X_step * 1e12) / 1e12);
  if (grid.empty())
    throw Error(ErrorKind::usage,
                "no multiple of the X step " + format_number(spec.X_step) + " lies in [" + format_number(spec.X_from) + ", " +
                    format_number(spec.X_to) + "]; use a smaller step");
  return grid;
}

std::vector<double> what_if_values(double from, double to, int points) {
  if (points < 2 || points > max_what_if_points)
    throw Error(ErrorKind::usage, "a sweep takes 2 to " + std::to_string(max_what_if_points) + " points, got " + std::to_string(points));
  if (!std::isfinite(from) || !std::isfinite(to) || !(from < to))
    throw Error(ErrorKind::bad_number, "a sweep runs from a low value to a higher one, got " + format_number(from) + " to " + format_number(to));
  std::vector<double> values;
  for (int i = 0; i + 1 < points; ++i) values.push_back(from + (to - from) * i / (points - 1));
  values.push_back(to);  // exact, not from + (to - from) rounded
  return values;
}

namespace {

SweepPoint optimize_point(const SweepSpec& spec, double X) {
  SweepPoint point;
  point.X = X;
  point.capacity = capacity_at({X, 0}, spec.R0, spec.T0);
  OptimizeRequest request;
  request.capacity = point.capacity;
  request.theta_i_deg = spec.theta_i_deg, request.F = spec.F, request.machine = spec.machine;
  request.material = spec.material;
  request.settings.criterion = spec.criterion;
  try {
    const std::vector<Optimum> optima = optimize(request);
    for (const Optimum& o : optima) point.simulations += o.simulations;
    // Two starts that meet (shape within 1 %) found one optimum, not two branches.
    for (std::size_t i = 0; i < optima.size(); ++i) {
      bool distinct = true;
      for (std::size_t j = 0; j < i; ++j)
        distinct = distinct &&
            (std::abs(std::log(optima[i].fit.design.l4 / optima[j].fit.design.l4)) > 0.01 ||
             std::abs(std::log(optima[i].fit.design.l / optima[j].fit.design.l)) > 0.01);
      point.optima_found += distinct;
    }
    const Optimum best = best_optimum(optima);
    point.engine = best.fit.engine;
    point.shot = best.fit.verification;
  } catch (const Error& e) {
    point.error = e.what();
  }
  return point;
}

}  // namespace

std::vector<SweepPoint> run_sweep(const SweepSpec& spec, Shard shard, int threads, const Progress& progress) {
  // The settings every point shares are the request's, refused once before any work, not at
  // each point as its failure.
  ShotSettings settings;
  settings.criterion = spec.criterion;
  check_shot_settings(settings);
  check_material(spec.material);
  if (spec.machine == MachineKind::whipper) throw Error(ErrorKind::usage, whipper_not_designed);
  const std::vector<double> grid = sweep_grid(spec);
  std::vector<double> mine;
  for (std::size_t i = shard.k - 1; i < grid.size(); i += shard.n) mine.push_back(grid[i]);
  std::vector<SweepPoint> points(mine.size());
  for_each_index(
      mine.size(), threads, [&](std::size_t i) { points[i] = optimize_point(spec, mine[i]); }, progress);
  return points;
}

}  // namespace trebuchet
