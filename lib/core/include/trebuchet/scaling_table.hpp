// The fitted constants of tab:CPNC: Z/Z0 = a_Z (R/R0)^p_Z (T/T0)^q_Z (eq:ZRT) for the seven
// absolute parameters of optimal engines, per block (theta_i, F) and X-segment.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "trebuchet/design.hpp"
#include "trebuchet/material.hpp"

namespace trebuchet {

/// The seven fitted parameters, in the column order of tab:CPNC.
enum class Param { L1, L2, L4, D, M, m, mb };
inline constexpr int param_count = 7;
inline constexpr std::array<Param, param_count> all_params = {Param::L1, Param::L2, Param::L4, Param::D, Param::M, Param::m, Param::mb};
std::string_view param_name(Param param);
inline int index(Param param) { return static_cast<int>(param); }

/// Branch label of a segment (section 6.2); `none` where only one optimum exists.
enum class Branch { none, lower, upper };
std::string_view branch_name(Branch branch);

/// A value per fitted parameter, indexed by Param.
using ParamVector = Eigen::Matrix<double, param_count, 1>;

/// Constants valid for X_min <= X <= X_max (X of eq:Xi): the columns of eq:ZRT,
/// Z/Z0 = a_Z (R/R0)^p_Z (T/T0)^q_Z, so that log(Z/(a_Z Z0)) = exponents (log(R/R0), log(T/T0)),
/// the 7x2 system of eq:RT_Z1Z2.
struct Segment {
  double X_min;
  double X_max;
  Branch branch;
  ParamVector a;  ///< a_Z, scaled
  Eigen::Matrix<double, param_count, 2> exponents;  ///< rows (p_Z, q_Z), scaled
};

/// One (theta_i, F) block of tab:CPNC.
struct TableBlock {
  double theta_i_deg;  ///< initial beam angle [deg]
  double F;  ///< (L2 + L3)/H, scaled; 0 in a table of another machine, whose counterweight sits at the short arm's end (L3 = 0)
  ParamVector Z0;  ///< optimum at (R0, T0) [m or kg]
  std::optional<double> branch_switch_X;  ///< X_d where lower and upper branch are equally good
  std::vector<Segment> segments;  ///< sorted by X_min

  double X_covered_min() const;
  double X_covered_max() const;
};

struct ScalingTable {
  std::string origin;  ///< file name, or "built-in" for data/cpnc.json; not written
  std::string name;  ///< e.g. "tab:CPNC"
  /// Where the constants come from, in words: (key, text) pairs in order ("source", "law", ...).
  std::vector<std::pair<std::string, std::string>> provenance;
  double R0;  ///< reference range [m]
  double T0;  ///< reference energy [J]
  Material reference;  ///< material, beta2 and g of the fits
  ParamVector n;  ///< exponents n_Z of eq:f_ZX
  std::vector<TableBlock> blocks;
  /// The machine its engines are built as (docs/machines.md): the paper's, or one whose
  /// counterweight sits at the short arm's end, whose blocks differ in theta_i alone.
  MachineKind machine = MachineKind::hinged;

  /// The block for (theta_i, F) (for another machine, theta_i: F is not its shape), or nullptr.
  const TableBlock* find_block(double theta_i_deg, double F) const;
  /// The block for (theta_i, F); Error(out_of_range) naming {{theta_i_deg}}, {{F}} and the
  /// blocks there are, when the table has none.
  const TableBlock& block(double theta_i_deg, double F) const;
  /// "30 deg/F=1, 30 deg/F=2/3, ..." for messages.
  std::string block_list() const;
};

/// tab:CPNC from data/cpnc.json, compiled into the library (generated from the file when the
/// library is configured; the application layer's parse of the file gives the same table, a test).
const ScalingTable& builtin_scaling_table();

/// The scaling table of a machine, compiled in the same way: tab:CPNC for the hinged engine,
/// data/cpnc-fixed.json and data/cpnc-floating-arm.json for the others (docs/machines.md); the
/// whipper has none yet: Error(usage) with whipper_not_designed (machine.hpp).
const ScalingTable& builtin_scaling_table(MachineKind machine);

}  // namespace trebuchet
