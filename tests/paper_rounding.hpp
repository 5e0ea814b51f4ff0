// Tolerances that follow from the rounding of printed numbers: the paper's tables, and the
// constants of tab:CPNC as transcribed (digit for digit) in data/cpnc.json.
#pragma once

#include <functional>
#include <string>

#include <vector>

#include "trebuchet/engine.hpp"
#include "trebuchet/scaling_table.hpp"

namespace trebuchet::testing {

/// A value as printed in the paper ("40.3"), with half a unit of its last digit.
struct Printed {
  double value;
  double half_unit;
};
Printed printed(const std::string& text);

/// Worst-case change of `result(table)` when every constant of tab:CPNC in the block
/// (theta_i, F) moves by half a unit of its last printed digit, summed over constants
/// (first order). `result` must not throw for the perturbed tables.
double table_rounding_effect(double theta_i_deg, double F, const std::function<double(const ScalingTable&)>& result);

/// Half a unit of the last printed digit of each constant, read from the JSON text.
double constant_half_unit(const std::string& json_pointer);

}  // namespace trebuchet::testing

namespace trebuchet::testing {

/// CHECKs |ours - paper| <= half a unit of the printed digit + `extra` and prints how close
/// it came: label, our value, the paper's, the difference and the share of the tolerance used.
/// `scale` converts ours into the paper's printed unit (1e-3 for kJ from J).
void check_printed(const std::string& label, double ours, const std::string& paper_text, double extra, double scale = 1.0);

}  // namespace trebuchet::testing

namespace trebuchet::testing {

/// First-order effect on `result` of the rounding of a printed engine: each input, given as
/// printed ("6.13"), moves by half a unit of its last digit in turn; the changes are summed.
/// `build` makes the engine from the input values in the order given.
double input_rounding_effect(const std::vector<std::string>& printed_inputs, const std::function<Engine(const std::vector<double>&)>& build,
                             const std::function<double(const Engine&)>& result);

}  // namespace trebuchet::testing
