#include "trebuchet/sweep.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <mutex>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/names.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/scaling_table.hpp"
#include "trebuchet/schema.hpp"

namespace trebuchet {

std::vector<double> sweep_grid(const SweepSpec& spec) {
  if (!std::isfinite(spec.X_from) || !std::isfinite(spec.X_to) || !std::isfinite(spec.X_step))
    throw Error(ErrorKind::usage, "the X grid needs finite numbers from:to:step; e.g. -0.55:0.55:0.05");
  if (!(spec.X_step > 0))
    throw Error(ErrorKind::usage, "the X step must be positive, got " + format_number(spec.X_step) + "; e.g. -0.55:0.55:0.05");
  if (!(spec.X_from <= spec.X_to) || !std::isfinite(spec.X_from) || !std::isfinite(spec.X_to))
    throw Error(ErrorKind::usage, "the X interval [" + format_number(spec.X_from) + ", " + format_number(spec.X_to) +
                                      "] is empty; give from:to:step with from <= to");
  // Multiples of the step, so that X = 0 (Z0 of tab:CPNC) is on the grid; 1e-9 absorbs the
  // rounding of from/step when from is itself a multiple. The count is checked in doubles,
  // before anything is converted to an integer or allocated.
  const double first_multiple = std::ceil(spec.X_from / spec.X_step - 1e-9);
  const double last_multiple = std::floor(spec.X_to / spec.X_step + 1e-9);
  if (!(last_multiple - first_multiple < max_grid_points))
    throw Error(ErrorKind::usage, "the X grid from " + format_number(spec.X_from) + " to " + format_number(spec.X_to) + " in steps of " +
                                      format_number(spec.X_step) + " has more than " + std::to_string(max_grid_points) +
                                      " points; use a larger step or a shorter interval");
  const long first = static_cast<long>(first_multiple), last = static_cast<long>(last_multiple);
  std::vector<double> grid;
  // Rounded to 1e-12 so that i * step prints as the user wrote it (-0.3, not -0.30000000000000004).
  for (long i = first; i <= last; ++i) grid.push_back(std::nearbyint(static_cast<double>(i) * spec.X_step * 1e12) / 1e12);
  if (grid.empty()) throw Error(ErrorKind::usage, "no multiple of the X step " + format_number(spec.X_step) + " lies in [" +
                                                      format_number(spec.X_from) + ", " + format_number(spec.X_to) + "]; use a smaller step");
  return grid;
}

Shard parse_shard(const std::string& text) {
  Shard shard;
  const std::size_t slash = text.find('/');
  auto whole = [&](std::string_view digits, int& value) {  // digits only, no sign, and within int
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return ec == std::errc() && end == digits.data() + digits.size() && !digits.empty() && digits.front() != '-';
  };
  const std::string_view view(text);
  if (slash == std::string::npos || !whole(view.substr(0, slash), shard.k) || !whole(view.substr(slash + 1), shard.n) ||
      shard.n < 1 || shard.k < 1 || shard.k > shard.n)
    throw Error(ErrorKind::usage, "--shard: '" + text + "' is not a part; give k/N with 1 <= k <= N <= " +
                                      std::to_string(std::numeric_limits<int>::max()) + ", e.g. 2/8");
  return shard;
}

namespace {

SweepPoint optimize_point(const SweepSpec& spec, double X) {
  SweepPoint point;
  point.X = X;
  point.capacity = capacity_at({X, 0}, spec.R0, spec.T0);
  OptimizeRequest request;
  request.capacity = point.capacity;
  request.theta_i_deg = spec.theta_i_deg, request.F = spec.F;
  request.material = spec.material;
  request.settings.criterion = spec.criterion;
  try {
    const std::vector<Optimum> optima = optimize(request);
    for (const Optimum& o : optima) point.simulations += o.simulations;
    // Two starts that meet (shape within 1 %) found one optimum, not two branches.
    for (std::size_t i = 0; i < optima.size(); ++i) {
      bool distinct = true;
      for (std::size_t j = 0; j < i; ++j)
        distinct = distinct && (std::abs(std::log(optima[i].fit.design.l4 / optima[j].fit.design.l4)) > 0.01 ||
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

std::vector<SweepPoint> run_sweep(const SweepSpec& spec, Shard shard, int threads, const std::function<void(int, int)>& progress) {
  const std::vector<double> grid = sweep_grid(spec);
  std::vector<double> mine;
  for (std::size_t i = shard.k - 1; i < grid.size(); i += shard.n) mine.push_back(grid[i]);
  std::vector<SweepPoint> points(mine.size());
  std::mutex report;
  int done = 0;
  for_each_index(mine.size(), threads, [&](std::size_t i) {
    points[i] = optimize_point(spec, mine[i]);
    const std::lock_guard<std::mutex> lock(report);
    ++done;
    if (progress) progress(done, static_cast<int>(mine.size()));
  });
  return points;
}

namespace {

const char* const part_kind = "trebuchet sweep part";

[[noreturn]] void fail(const std::string& origin, const std::string& problem) {
  throw Error(ErrorKind::data_file, origin + ": " + problem + "; give files written by trebuchet-verify derive-table --shard k/N");
}

}  // namespace

nlohmann::ordered_json sweep_point_json(const SweepPoint& p) {
  nlohmann::ordered_json j;
  j["X"] = p.X, j["R"] = p.capacity.R, j["T"] = p.capacity.T;
  if (!p.error.empty()) {
    j["error"] = p.error;
    return j;
  }
  write_engine(j, p.engine);
  j["Q"] = p.shot.Q, j["eps"] = p.shot.eps, j["force_factor"] = p.shot.force_factor;
  j["theta_release_deg"] = p.shot.theta_release_deg;
  j["optima_found"] = p.optima_found;
  j["simulations"] = p.simulations;
  return j;
}

namespace {

SweepPoint read_point(const nlohmann::json& j, const std::string& where) {
  SweepPoint p;
  p.X = j.at("X").get<double>();
  p.capacity = {j.at("R").get<double>(), j.at("T").get<double>(), 0};
  if (j.contains("error")) {
    p.error = j.at("error").get<std::string>();
    return p;
  }
  p.engine = read_engine(j, where).engine;
  p.shot.capacity = p.capacity;
  p.shot.Q = j.at("Q").get<double>(), p.shot.eps = j.at("eps").get<double>();
  p.shot.force_factor = j.at("force_factor").get<double>();
  p.shot.theta_release_deg = j.at("theta_release_deg").get<double>();
  p.optima_found = j.at("optima_found").get<int>();
  p.simulations = j.at("simulations").get<int>();
  return p;
}

}  // namespace

nlohmann::ordered_json sweep_part_json(const SweepPart& part) {
  const SweepSpec& spec = part.spec;
  nlohmann::ordered_json out;
  out["kind"] = part_kind;
  out["theta_i_deg"] = spec.theta_i_deg;
  out["F"] = spec.F;
  out["X_from"] = spec.X_from, out["X_to"] = spec.X_to, out["X_step"] = spec.X_step;
  out["R0"] = spec.R0, out["T0"] = spec.T0;
  out["reference_material"] = material_json(spec.material);
  out["quality"] = release_name(spec.criterion.release);
  out["n"] = spec.criterion.n;
  out["shard"] = std::to_string(part.shard.k) + "/" + std::to_string(part.shard.n);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const SweepPoint& p : part.points) list.push_back(sweep_point_json(p));
  out["points"] = list;
  return out;
}

SweepPart read_sweep_part(const nlohmann::json& j, const std::string& origin) {
  if (!j.is_object() || j.value("kind", "") != part_kind) fail(origin, "not a sweep part");
  SweepPart part;
  part.origin = origin;
  try {
    SweepSpec& spec = part.spec;
    spec.theta_i_deg = j.at("theta_i_deg").get<double>();
    spec.F = j.at("F").get<double>();
    spec.X_from = j.at("X_from").get<double>(), spec.X_to = j.at("X_to").get<double>(), spec.X_step = j.at("X_step").get<double>();
    spec.R0 = j.at("R0").get<double>(), spec.T0 = j.at("T0").get<double>();
    const nlohmann::json& material = j.at("reference_material");
    spec.material = {material.at("beta2").get<double>(), material.at("youngs_modulus").get<double>(),
                     material.at("wood_density").get<double>(), material.at("g").get<double>()};
    spec.criterion.release = parse_release(j.at("quality").get<std::string>(), "quality");
    spec.criterion.n = j.at("n").get<double>();
    part.shard = parse_shard(j.at("shard").get<std::string>());
    const nlohmann::json& points = j.at("points");
    for (std::size_t i = 0; i < points.size(); ++i) part.points.push_back(read_point(points.at(i), "points[" + std::to_string(i) + "]"));
  } catch (const nlohmann::json::exception& e) {
    fail(origin, std::string("malformed sweep part (") + e.what() + ")");
  } catch (const Error& e) {
    fail(origin, std::string("malformed sweep part (") + e.what() + ")");
  }
  return part;
}

}  // namespace trebuchet
