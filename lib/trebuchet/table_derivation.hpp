// tab:CPNC re-derived from sweeps (sweep.hpp): per (theta_i, F) block, Z0 is the optimum at
// X = 0, and below and above X = 0 the form f_Z(X) = a_Z exp(b_Z sqrt(26) X) of eq:f_ZX is
// fitted to (Z/Z0)/(R/R0)^n_Z; eq:ZRT then gives p_Z = n_Z + 5 b_Z and q_Z = -b_Z.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace trebuchet {

/// a and b of f(X) = a exp(b sqrt(26) X) (eq:f_MX), fitted by least squares in log f.
struct ExponentialFit {
  double a = 0;              ///< scaled
  double b = 0;              ///< scaled
  double max_deviation = 0;  ///< largest |fit/f - 1| over the points, scaled
};

/// Needs two or more points with f > 0 (throws Error(data_file) otherwise).
ExponentialFit fit_exponential(const std::vector<double>& X, const std::vector<double>& f);

/// A sweep part as read back, with the name of where it came from for messages.
struct SweepPart {
  std::string origin;
  nlohmann::ordered_json json;
};

/// Joins sweep parts into a constants table in the schema of data/cpnc.json, which the
/// calculator reads with --table. Blocks are sorted by (theta_i, F) and points by X, so the
/// bytes do not depend on the order of the parts or how the sweep was split. Each block's
/// points keep their optimum under "sweep". Throws Error(data_file) naming the part and the
/// fix: not a sweep part, parts that disagree, a grid point missing or given twice, no
/// optimum at X = 0, or a block with no segment of three or more points.
nlohmann::ordered_json derive_table(const std::vector<SweepPart>& parts);

/// The X of points whose optimisation failed, over all blocks of a derived table.
std::vector<double> failed_points(const nlohmann::ordered_json& table);

}  // namespace trebuchet
