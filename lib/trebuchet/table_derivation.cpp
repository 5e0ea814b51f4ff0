#include "trebuchet/table_derivation.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/scaling_table.hpp"
#include "trebuchet/sweep.hpp"

namespace trebuchet {

ExponentialFit fit_exponential(const std::vector<double>& X, const std::vector<double>& f) {
  if (X.size() != f.size() || X.size() < 2) throw Error(ErrorKind::data_file, "an exponential fit needs two or more points");
  std::vector<double> u, y;  // u = sqrt(26) X, y = log f: a straight line y = log a + b u
  for (std::size_t i = 0; i < X.size(); ++i) {
    if (!(f[i] > 0)) throw Error(ErrorKind::data_file, "f_Z at X = " + format_number(X[i]) + " is not positive");
    u.push_back(std::sqrt(26.0) * X[i]);
    y.push_back(std::log(f[i]));
  }
  double c0, c1, cov00, cov01, cov11, sumsq;
  gsl_fit_linear(u.data(), 1, y.data(), 1, u.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  ExponentialFit fit{std::exp(c0), c1, 0};
  for (std::size_t i = 0; i < u.size(); ++i) fit.max_deviation = std::max(fit.max_deviation, std::abs(std::exp(c0 + c1 * u[i] - y[i]) - 1));
  return fit;
}

namespace {

// n_Z of eq:f_ZX, in the column order of tab:CPNC: lengths 1, D 3/2, masses 4.
constexpr std::array<double, param_count> n_Z = {1, 1, 1, 1.5, 4, 4, 4};

struct Block {
  nlohmann::ordered_json spec;  // the first part's header
  std::string first_origin;
  std::map<double, nlohmann::ordered_json> points;  // by X
  std::map<double, std::string> origin_of;          // the part each point came from, for messages
};

[[noreturn]] void fail(const std::string& where, const std::string& problem) {
  throw Error(ErrorKind::data_file, where + ": " + problem);
}

std::string block_name(const nlohmann::ordered_json& spec) {
  return "block theta " + format_number(spec.at("theta_i_deg").get<double>()) + " deg, F " + format_fraction(spec.at("F").get<double>());
}

// Keys every part of one block must share, and keys every part of the table must share.
const char* const block_keys[] = {"X_from", "X_to", "X_step", "quality", "n"};
const char* const table_keys[] = {"R0_m", "T0_J", "reference_material"};

SweepSpec spec_of(const nlohmann::ordered_json& header) {
  SweepSpec spec;
  spec.X_from = header.at("X_from").get<double>();
  spec.X_to = header.at("X_to").get<double>();
  spec.X_step = header.at("X_step").get<double>();
  return spec;
}

nlohmann::ordered_json per_param(const std::array<double, param_count>& values) {
  nlohmann::ordered_json out;
  for (Param p : all_params) out[std::string(param_name(p))] = values[index(p)];
  return out;
}

// eq:f_ZX fitted for every parameter over the points with X in [lo, hi].
struct SegmentFit {
  std::vector<const nlohmann::ordered_json*> points;
  std::array<ExponentialFit, param_count> fits;
  double worst = 0;  // largest fit_max_deviation over the parameters
};

SegmentFit fit_segment(const std::vector<const nlohmann::ordered_json*>& points, const std::array<double, param_count>& Z0, double R0) {
  SegmentFit out;
  out.points = points;
  for (Param param : all_params) {
    std::vector<double> X, f;
    for (const nlohmann::ordered_json* point : points) {
      const double Z = point->at("Z").at(std::string(param_name(param))).get<double>();
      X.push_back(point->at("X").get<double>());
      f.push_back(Z / Z0[index(param)] / std::pow(point->at("R_m").get<double>() / R0, n_Z[index(param)]));
    }
    out.fits[index(param)] = fit_exponential(X, f);
    out.worst = std::max(out.worst, out.fits[index(param)].max_deviation);
  }
  return out;
}

// A fit worse than this is split in two at the grid point that fits best: the optimum changes
// regime along X (docs/table_derivation.md), which one exponential cannot follow. 1 % keeps the
// table well inside the 2 % at which the verifier checks the calculator's designs.
constexpr double max_fit_deviation = 0.01;
constexpr std::size_t min_segment_points = 3;

void fit_segments(const std::vector<const nlohmann::ordered_json*>& points, const std::array<double, param_count>& Z0, double R0,
                  std::vector<SegmentFit>& out) {
  SegmentFit whole = fit_segment(points, Z0, R0);
  std::optional<std::pair<SegmentFit, SegmentFit>> best;
  if (whole.worst > max_fit_deviation)
    for (std::size_t k = min_segment_points - 1; k + min_segment_points <= points.size(); ++k) {  // both share point k
      SegmentFit left = fit_segment({points.begin(), points.begin() + k + 1}, Z0, R0);
      SegmentFit right = fit_segment({points.begin() + k, points.end()}, Z0, R0);
      if (!best || std::max(left.worst, right.worst) < std::max(best->first.worst, best->second.worst)) best = {left, right};
    }
  if (!best || std::max(best->first.worst, best->second.worst) >= whole.worst) {
    out.push_back(whole);
    return;
  }
  fit_segments(best->first.points, Z0, R0, out);
  fit_segments(best->second.points, Z0, R0, out);
}

nlohmann::ordered_json segment_json(const SegmentFit& fit) {
  std::array<double, param_count> a{}, p{}, q{}, deviation{};
  for (Param param : all_params) {
    const ExponentialFit& f = fit.fits[index(param)];
    a[index(param)] = f.a;
    p[index(param)] = n_Z[index(param)] + 5 * f.b;  // eq:ZRT
    q[index(param)] = -f.b;
    deviation[index(param)] = f.max_deviation;
  }
  nlohmann::ordered_json segment;
  segment["X_min"] = fit.points.front()->at("X").get<double>();
  segment["X_max"] = fit.points.back()->at("X").get<double>();
  segment["branch"] = "none";
  segment["points"] = fit.points.size();
  segment["a"] = per_param(a);
  segment["p"] = per_param(p);
  segment["q"] = per_param(q);
  segment["fit_max_deviation"] = per_param(deviation);
  return segment;
}

nlohmann::ordered_json block_json(const Block& block, double R0) {
  const std::string name = block_name(block.spec);
  const auto zero = block.points.find(0.0);
  if (zero == block.points.end() || zero->second.contains("error"))
    fail(name, "no optimum at X = 0, which sets Z0 (tab:CPNC); give an X interval that holds 0");
  std::array<double, param_count> Z0{};
  for (Param param : all_params) Z0[index(param)] = zero->second.at("Z").at(std::string(param_name(param))).get<double>();
  nlohmann::ordered_json out;
  out["theta_i_deg"] = block.spec.at("theta_i_deg").get<double>();
  out["F"] = block.spec.at("F").get<double>();
  out["Z0"] = per_param(Z0);
  // The paper fits below and above X = 0 separately (tab:CPNC); so do we, and split further
  // where one exponential does not fit.
  std::vector<SegmentFit> fits;
  for (const auto& [lo, hi] : {std::pair{-HUGE_VAL, 0.0}, std::pair{0.0, HUGE_VAL}}) {
    std::vector<const nlohmann::ordered_json*> side;
    for (const auto& [X, point] : block.points)
      if (X >= lo && X <= hi && !point.contains("error")) side.push_back(&point);
    if (side.size() >= min_segment_points) fit_segments(side, Z0, R0, fits);
  }
  if (fits.empty()) fail(name, "fewer than three optima on each side of X = 0; use a finer X step");
  nlohmann::ordered_json segments = nlohmann::ordered_json::array();
  for (const SegmentFit& fit : fits) segments.push_back(segment_json(fit));
  out["segments"] = segments;
  nlohmann::ordered_json sweep = nlohmann::ordered_json::array();
  for (const auto& [X, point] : block.points) sweep.push_back(point);
  out["sweep"] = sweep;
  return out;
}

}  // namespace

nlohmann::ordered_json derive_table(const std::vector<SweepPart>& parts) {
  if (parts.empty()) throw Error(ErrorKind::data_file, "no sweep parts to merge; give the files written by --derive-table --shard k/N");
  std::map<std::pair<double, double>, Block> blocks;  // by (theta_i, F)
  nlohmann::ordered_json table_header;
  std::string table_origin;
  for (const SweepPart& part : parts) {
    const nlohmann::ordered_json& j = part.json;
    try {
      if (!j.is_object() || j.value("kind", "") != "trebuchet sweep part")
        fail(part.origin, "not a sweep part; give files written by trebuchet-verify --derive-table --shard k/N");
      for (const char* key : table_keys) {
        if (table_header.is_null()) continue;
        if (j.at(key) != table_header.at(key))
          fail(part.origin, std::string("its ") + key + " differs from that of " + table_origin + "; merge sweeps of one reference only");
      }
      if (table_header.is_null()) {
        for (const char* key : table_keys) table_header[key] = j.at(key);
        table_origin = part.origin;
      }
      Block& block = blocks[{j.at("theta_i_deg").get<double>(), j.at("F").get<double>()}];
      if (block.spec.is_null()) {
        block.spec = j;
        block.spec.erase("points");
        block.first_origin = part.origin;
      }
      for (const char* key : block_keys)
        if (j.at(key) != block.spec.at(key))
          fail(part.origin, std::string("its ") + key + " differs from that of " + block.first_origin + " for the same " +
                                block_name(j) + "; run every shard with the same --X and --quality");
      for (const nlohmann::ordered_json& point : j.at("points")) {
        const double X = point.at("X").get<double>();
        if (!block.points.emplace(X, point).second)
          fail(part.origin, block_name(j) + ": X = " + format_number(X) + " is also in " + block.origin_of[X] + "; give each shard once");
        block.origin_of[X] = part.origin;
      }
    } catch (const nlohmann::json::exception& e) {
      fail(part.origin, std::string("malformed sweep part (") + e.what() + "); give files written by trebuchet-verify --derive-table");
    }
  }
  nlohmann::ordered_json table;
  table["name"] = "tab:CPNC re-derived ab initio";
  table["provenance"] = {
      {"source", "trebuchet-verify --derive-table: the ab-initio optimum (appendix A, section 5) at each X point of the sweep, Y = 0 (eq:XY_RT)"},
      {"law", "Z/Z0 = a_Z (R/R0)^p_Z (T/T0)^q_Z (eq:ZRT), p_Z = n_Z + 5 b_Z, q_Z = -b_Z from f_Z = a_Z exp(b_Z sqrt(26) X) (eq:f_ZX)"},
      {"fit", "least squares of log f_Z against X, separately for X <= 0 and X >= 0; fit_max_deviation is the largest |fit/f_Z - 1| over a segment's points"},
      {"branches", "one optimum per X point under this program's Q (docs/table_derivation.md); optima_found counts distinct optima from the starts"}};
  for (const char* key : table_keys) table[key] = table_header.at(key);
  table["n"] = per_param(n_Z);
  nlohmann::ordered_json out_blocks = nlohmann::ordered_json::array();
  const double R0 = table_header.at("R0_m").get<double>();
  for (auto& [key, block] : blocks) {
    const std::string name = block_name(block.spec);
    const std::vector<double> grid = sweep_grid(spec_of(block.spec));
    for (double X : grid)
      if (!block.points.count(X))
        fail(name, "X = " + format_number(X) + " is missing; merge every shard k/N of the sweep");
    if (block.points.size() != grid.size()) fail(name, "points off the X grid; merge parts of one sweep only");
    out_blocks.push_back(block_json(block, R0));
  }
  table["blocks"] = out_blocks;
  return table;
}

std::vector<double> failed_points(const nlohmann::ordered_json& table) {
  std::vector<double> failed;
  for (const auto& block : table.at("blocks"))
    for (const auto& point : block.at("sweep"))
      if (point.contains("error")) failed.push_back(point.at("X").get<double>());
  return failed;
}

}  // namespace trebuchet
