// The fitted constants of tab:CPNC: Z/Z0 = a_Z (R/R0)^p_Z (T/T0)^q_Z (eq:ZRT) for the seven
// absolute parameters of optimal engines, per block (theta_i, F) and X-segment.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "trebuchet/material.hpp"

namespace trebuchet {

/// The seven fitted parameters, in the column order of tab:CPNC.
enum class Param { L1, L2, L4, D, M, m, mb };
inline constexpr int param_count = 7;
inline constexpr std::array<Param, param_count> all_params = {Param::L1, Param::L2, Param::L4, Param::D,
                                                              Param::M,  Param::m,  Param::mb};
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
  ParamVector a;                                   ///< a_Z, scaled
  Eigen::Matrix<double, param_count, 2> exponents;  ///< rows (p_Z, q_Z), scaled
};

/// One (theta_i, F) block of tab:CPNC.
struct TableBlock {
  double theta_i_deg;                       ///< initial beam angle [deg]
  double F;                                 ///< (L2 + L3)/H, scaled
  ParamVector Z0;                           ///< optimum at (R0, T0) [m or kg]
  std::optional<double> branch_switch_X;    ///< X_d where lower and upper branch are equally good
  std::vector<Segment> segments;            ///< sorted by X_min

  double X_covered_min() const;
  double X_covered_max() const;
};

struct ScalingTable {
  std::string origin;                       ///< file name, or "built-in" for data/cpnc.json; not written
  std::string name;                         ///< e.g. "tab:CPNC"
  nlohmann::ordered_json provenance;        ///< where the constants come from, in words (an object)
  double R0;                                ///< reference range [m]
  double T0;                                ///< reference energy [J]
  Material reference;                       ///< material, beta2 and g of the fits
  ParamVector n;                            ///< exponents n_Z of eq:f_ZX
  std::vector<TableBlock> blocks;

  /// The block for (theta_i, F), or nullptr.
  const TableBlock* find_block(double theta_i_deg, double F) const;
  /// "30 deg/F=1, 30 deg/F=2/3, ..." for messages.
  std::string block_list() const;
};

/// Parses and validates a constants table. Throws Error(data_file) naming `origin` and the
/// key: a missing key, a wrong type, a non-finite or non-positive number where one must be
/// positive, an empty interval, overlapping segments without distinct branch labels, two
/// blocks for one (theta_i, F), or a segment whose p_Z + 5 q_Z misses n_Z (eq:ZRT) by more
/// than one unit of the last printed digit of p_Z plus five of q_Z.
ScalingTable parse_scaling_table(std::string_view json_text, const std::string& origin);

/// A value per parameter as a JSON object with keys L1 ... mb.
nlohmann::ordered_json param_json(const ParamVector& values);

/// The material as the JSON object "reference_material" of tables and sweep parts.
nlohmann::ordered_json material_json(const Material& material);

/// The table as JSON, in the schema parse_scaling_table reads (data/cpnc.json).
nlohmann::ordered_json scaling_table_json(const ScalingTable& table);

/// Reads and parses a constants file (Error(data_file) if it cannot be read).
ScalingTable load_scaling_table(const std::string& path);

/// tab:CPNC from data/cpnc.json, compiled into the library.
const ScalingTable& builtin_scaling_table();

/// The text of data/cpnc.json as compiled in.
std::string_view builtin_scaling_table_json();

}  // namespace trebuchet
