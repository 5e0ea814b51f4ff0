// The calculator as a workbook with live formulas (docs/spreadsheet.md): the constants of a
// table, the optimal engine from (R, T), from R and one parameter and from any log-linear pair,
// the derived quantities, model scaling and the material, each formula the paper's equation
// with its label beside it. Written with libxlsxwriter, with every formula's value cached.
#pragma once

#include <string>

#include "trebuchet/calculator.hpp"
#include "trebuchet/scaling_table.hpp"

namespace trebuchet {

/// The values the workbook opens on; the defaults are the paper's examples.
struct SpreadsheetInputs {
  DesignRequest capacity = example(Quantity::R, 425, Quantity::T, 224e3);  ///< Denny's engine, the "Present" row
  DesignRequest range_and_one = example(Quantity::R, 150, Quantity::m, 50);  ///< Alcalá la Vieja, site Ca
  DesignRequest any_pair = example(Quantity::M, 10e3, Quantity::m, 100);  ///< Denny's (M, m)
  Engine engine = alcala_ca();  ///< the derived-quantities sheet's engine
  double model_scale = 80.0 / 425;  ///< Denny's 80 m model, on the (R, T) sheet's engine
  Material material{};  ///< beta2, Young's modulus, wood density and g of the designs

  static DesignRequest example(Quantity first, double first_value, Quantity second, double second_value);
  static Engine alcala_ca();
};

/// Writes the workbook to `path` (an .xlsx file). The designs take `inputs`; the constants are
/// `table`'s. Throws Error(usage) when the file cannot be written. Pairs with Lb, which is not
/// log-linear, are the calculator's alone; the workbook's pair sheet offers the others.
void write_spreadsheet(const ScalingTable& table, const SpreadsheetInputs& inputs, const std::string& path);

}  // namespace trebuchet
