#include "trebuchet/sweep.hpp"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/optimizer.hpp"

namespace trebuchet {

std::vector<double> sweep_grid(const SweepSpec& spec) {
  if (!(spec.X_step > 0) || !std::isfinite(spec.X_step))
    throw Error(ErrorKind::usage, "the X step must be positive, got " + format_number(spec.X_step) + "; e.g. -0.55:0.55:0.05");
  if (!(spec.X_from <= spec.X_to) || !std::isfinite(spec.X_from) || !std::isfinite(spec.X_to))
    throw Error(ErrorKind::usage, "the X interval [" + format_number(spec.X_from) + ", " + format_number(spec.X_to) +
                                      "] is empty; give from:to:step with from <= to");
  // Multiples of the step, so that X = 0 (Z0 of tab:CPNC) is on the grid; 1e-9 absorbs the
  // rounding of from/step when from is itself a multiple.
  const long first = static_cast<long>(std::ceil(spec.X_from / spec.X_step - 1e-9));
  const long last = static_cast<long>(std::floor(spec.X_to / spec.X_step + 1e-9));
  if (last - first > 10000) throw Error(ErrorKind::usage, "the X grid has " + std::to_string(last - first + 1) + " points; use a larger step");
  std::vector<double> grid;
  // Rounded to 1e-12 so that i * step prints as the user wrote it (-0.3, not -0.30000000000000004).
  for (long i = first; i <= last; ++i) grid.push_back(std::nearbyint(static_cast<double>(i) * spec.X_step * 1e12) / 1e12);
  if (grid.empty()) throw Error(ErrorKind::usage, "no multiple of the X step " + format_number(spec.X_step) + " lies in [" +
                                                      format_number(spec.X_from) + ", " + format_number(spec.X_to) + "]; use a smaller step");
  return grid;
}

AxisCapacity capacity_on_X_axis(double X, double R0, double T0) {
  return {R0 * std::exp(5 * X / std::sqrt(26.0)), T0 * std::exp(-X / std::sqrt(26.0))};
}

Shard parse_shard(const std::string& text) {
  Shard shard;
  char slash = 0, rest = 0;
  const int read = std::sscanf(text.c_str(), "%d%c%d%c", &shard.k, &slash, &shard.n, &rest);
  if (read != 3 || slash != '/' || shard.n < 1 || shard.k < 1 || shard.k > shard.n)
    throw Error(ErrorKind::usage, "--shard: '" + text + "' is not a part; give k/N with 1 <= k <= N, e.g. 2/8");
  return shard;
}

namespace {

SweepPoint optimize_point(const SweepSpec& spec, double X) {
  SweepPoint point;
  point.X = X;
  const AxisCapacity capacity = capacity_on_X_axis(X, spec.R0, spec.T0);
  point.R = capacity.R, point.T = capacity.T;
  OptimizeRequest request;
  request.R = point.R, request.T = point.T;
  request.theta_i_deg = spec.theta_i_deg, request.F = spec.F;
  request.material = spec.material;
  request.settings.g = spec.material.g;
  request.settings.quality = spec.quality;
  try {
    const std::vector<Optimum> optima = optimize(request);
    for (const Optimum& o : optima) point.simulations += o.simulations;
    // Two starts that meet (shape within 1 %) found one optimum, not two branches.
    for (std::size_t i = 0; i < optima.size(); ++i) {
      bool distinct = true;
      for (std::size_t j = 0; j < i; ++j)
        distinct = distinct && (std::abs(std::log(optima[i].shape.l4 / optima[j].shape.l4)) > 0.01 ||
                                std::abs(std::log(optima[i].shape.l / optima[j].shape.l)) > 0.01);
      point.optima_found += distinct;
    }
    const Optimum best = best_optimum(optima);
    point.engine = best.fit.engine;
    point.shot = best.fit.verification;
    point.shape = best.shape;
  } catch (const Error& e) {
    point.error = e.what();
  }
  return point;
}

}  // namespace

std::vector<SweepPoint> run_sweep(const SweepSpec& spec, Shard shard, int threads, const std::function<void(int, int)>& progress) {
  const std::vector<double> grid = sweep_grid(spec);
  std::vector<double> mine;
  for (std::size_t i = shard.k - 1; i < grid.size(); i += shard.n) mine.push_back(grid[i]);
  std::vector<SweepPoint> points(mine.size());
  // Each worker takes the next unclaimed point and writes only its own slot: the order in
  // which points finish cannot change what is written.
  std::atomic<std::size_t> next{0};
  std::mutex report;
  int done = 0;
  auto work = [&] {
    for (std::size_t i = next++; i < mine.size(); i = next++) {
      points[i] = optimize_point(spec, mine[i]);
      const std::lock_guard<std::mutex> lock(report);
      ++done;
      if (progress) progress(done, static_cast<int>(mine.size()));
    }
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < std::max(1, threads); ++t) workers.emplace_back(work);
  work();
  for (std::thread& w : workers) w.join();
  return points;
}

nlohmann::ordered_json sweep_json(const SweepSpec& spec, Shard shard, const std::vector<SweepPoint>& points) {
  nlohmann::ordered_json out;
  out["kind"] = "trebuchet sweep part";
  out["theta_i_deg"] = spec.theta_i_deg;
  out["F"] = spec.F;
  out["X_from"] = spec.X_from, out["X_to"] = spec.X_to, out["X_step"] = spec.X_step;
  out["R0_m"] = spec.R0, out["T0_J"] = spec.T0;
  out["reference_material"] = {{"beta2", spec.material.beta2},
                               {"youngs_modulus_Pa", spec.material.youngs_modulus},
                               {"wood_density_kg_m3", spec.material.wood_density},
                               {"g_m_s2", spec.material.g}};
  out["quality"] = release_name(spec.quality.release);
  out["n"] = spec.quality.n;
  out["shard"] = std::to_string(shard.k) + "/" + std::to_string(shard.n);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const SweepPoint& p : points) {
    nlohmann::ordered_json j;
    j["X"] = p.X, j["R_m"] = p.R, j["T_J"] = p.T;
    if (!p.error.empty()) {
      j["error"] = p.error;
    } else {
      const Engine& e = p.engine;
      j["Z"] = {{"L1", e.L1}, {"L2", e.L2}, {"L4", e.L4}, {"D", e.D}, {"M", e.M}, {"m", e.m}, {"mb", e.mb}};
      j["L3_m"] = e.L3;
      j["l"] = p.shape.l, j["l4"] = p.shape.l4, j["mu_b"] = p.shape.mu_b, j["mu"] = e.m / e.M;
      j["Q"] = p.shot.Q, j["eps"] = p.shot.eps, j["force_factor"] = p.shot.force_factor;
      j["theta_release_deg"] = p.shot.theta_release_deg;
      j["optima_found"] = p.optima_found;
      j["simulations"] = p.simulations;
    }
    list.push_back(j);
  }
  out["points"] = list;
  return out;
}

}  // namespace trebuchet
