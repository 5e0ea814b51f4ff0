// tab:CPNC re-derived from sweeps (sweep.hpp): per (theta_i, F) block, Z0 is the optimum at
// X = 0, and below and above X = 0 the form f_Z(X) = a_Z exp(b_Z sqrt(26) X) of eq:f_ZX is
// fitted to (Z/Z0)/(R/R0)^n_Z; eq:ZRT then gives p_Z = n_Z + 5 b_Z and q_Z = -b_Z.
#pragma once

#include <vector>

#include "trebuchet/scaling_table.hpp"
#include "trebuchet/sweep.hpp"

namespace trebuchet {

/// a and b of f(X) = a exp(b sqrt(26) X) (eq:f_MX), fitted by least squares in log f.
struct ExponentialFit {
  double a = 0;  ///< scaled
  double b = 0;  ///< scaled
  double max_deviation = 0;  ///< largest |fit/f - 1| over the points, scaled
};

/// Needs two or more points with f > 0 (throws Error(data_file) otherwise).
ExponentialFit fit_exponential(const std::vector<double>& X, const std::vector<double>& f);

/// How well a derived segment fits its sweep points.
struct SegmentFitQuality {
  int points = 0;  ///< sweep points in the segment
  ParamVector fit_max_deviation;  ///< largest |fit/f_Z - 1| per parameter, scaled
};

/// A constants table with what it was derived from: per block of `table`, the quality of each
/// segment's fit (in segment order) and the sweep's points in X order.
struct DerivedTable {
  ScalingTable table;
  std::vector<std::vector<SegmentFitQuality>> fits;  ///< [block][segment]
  std::vector<std::vector<SweepPoint>> sweeps;  ///< [block][point]
};

/// Joins sweep parts into a constants table. Blocks are sorted by (theta_i, F) and points by
/// X, so the result does not depend on the order of the parts or how the sweep was split.
/// Throws Error(data_file) naming the part and the fix: parts that disagree, a grid point
/// missing or given twice, no optimum at X = 0, or a block with no segment of three or more points.
DerivedTable derive_table(const std::vector<SweepPart>& parts);

/// The X of points whose optimisation failed, over all blocks.
std::vector<double> failed_points(const DerivedTable& derived);

}  // namespace trebuchet
