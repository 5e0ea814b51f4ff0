#include "trebuchet/scaling_table.hpp"

#include <algorithm>
#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {

std::string_view param_name(Param param) {
  static constexpr std::array<std::string_view, param_count> names = {"L1", "L2", "L4", "D", "M", "m", "mb"};
  return names[index(param)];
}

std::string_view branch_name(Branch branch) {
  switch (branch) {
    case Branch::none: return "none";
    case Branch::lower: return "lower";
    case Branch::upper: return "upper";
  }
  return "?";
}

double TableBlock::X_covered_min() const {
  double x = segments.front().X_min;
  for (const Segment& s : segments) x = std::min(x, s.X_min);
  return x;
}

double TableBlock::X_covered_max() const {
  double x = segments.front().X_max;
  for (const Segment& s : segments) x = std::max(x, s.X_max);
  return x;
}

const TableBlock* ScalingTable::find_block(double theta_i_deg, double F) const {
  for (const TableBlock& block : blocks)
    if (std::abs(block.theta_i_deg - theta_i_deg) < 1e-9 && std::abs(block.F - F) < 1e-9) return &block;
  return nullptr;
}

const TableBlock& ScalingTable::block(double theta_i_deg, double F) const {
  if (const TableBlock* found = find_block(theta_i_deg, F)) return *found;
  throw Error(ErrorKind::out_of_range,
              "tab:CPNC has no constants for theta_i = " + format_number(theta_i_deg) + " deg with F = " + format_fraction(F) + "; it has " +
                  block_list() + " ({{theta_i_deg}}, {{F}})");
}

std::string ScalingTable::block_list() const {
  std::string list;
  for (const TableBlock& block : blocks) {
    if (!list.empty()) list += ", ";
    list += "theta " + format_number(block.theta_i_deg) + " with F " + format_fraction(block.F);
  }
  return list;
}

}  // namespace trebuchet
