// The calculator as a workbook with live formulas (docs/spreadsheet.md): the constants of a
// table, the optimal engine from (R, T), from R and one parameter, from any log-linear pair and
// from Lb and one parameter, the paper's sites (tab:Alcala_la_Vieja), the derived quantities,
// model scaling and the material, each formula the paper's equation with its label beside it.
// Written with libxlsxwriter, with every formula's value cached.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/scaling_table.hpp"

namespace trebuchet {

/// One row of a user's sites file (trebuchet-calc --spreadsheet FILE --batch SITES.csv).
struct SiteRow {
  int line;  ///< in the file, from 1
  std::vector<std::string> passed;  ///< the cells passed through (a site's name), in the header's order
  std::optional<DesignRequest> request;  ///< as the row reads; none when a cell cannot be read
  std::string refusal;  ///< the calculator's message for the row; empty when it designs
};

/// The most characters a spreadsheet's cell holds (Excel's limit, libxlsxwriter's LXW_STR_MAX):
/// a longer text would leave its cell blank.
inline constexpr std::size_t max_cell_characters = 32767;

/// Why a site row's passed cells cannot stand in the workbook: "column 'site' holds 40000
/// characters, ..." for the first cell longer than a cell holds; empty when each fits. Its
/// cell then shows the text cut to the limit, and the row is refused with this reason.
std::string overlong_cell(const std::vector<std::string>& columns, const std::vector<std::string>& passed);

/// A user's sites: the file's name, its pass-through columns and its rows.
struct UserSites {
  std::string source;
  std::vector<std::string> columns;
  std::vector<SiteRow> rows;
};

/// The values the workbook opens on; the defaults are the paper's examples.
struct SpreadsheetInputs {
  DesignRequest capacity = example(Quantity::R, 425, Quantity::T, 224e3);  ///< Denny's engine, the "Present" row
  DesignRequest range_and_one = example(Quantity::R, 150, Quantity::m, 50);  ///< Alcalá la Vieja, site Ca
  DesignRequest any_pair = example(Quantity::M, 10e3, Quantity::m, 100);  ///< Denny's (M, m)
  DesignRequest beam_length = villard();  ///< Lb and one log-linear quantity: tab:SketchBook-II, row 2
  Engine engine = alcala_ca();  ///< the derived-quantities sheet's engine
  double model_scale = 80.0 / 425;  ///< Denny's 80 m model, on the (R, T) sheet's engine
  Material material{};  ///< beta2, Young's modulus, wood density and g of the designs
  std::optional<UserSites> sites;  ///< the sheet "your sites", on which the workbook then opens
  /// The calculator's refusal of the givens a design sheet opens on (one of the four above), written under that sheet's title.
  std::pair<const DesignRequest*, std::string> refusal{nullptr, ""};

  /// Opens the workbook on two givens and returns the design sheet they go to: R and T the
  /// capacity sheet, R and another the sheet for R and one parameter, Lb and another the sheet
  /// for Lb and one (Lb first), any other pair the last. Every sheet takes `request`'s branch and
  /// material, and its block (theta_i, F) when `block_given`; the sheet opened on takes the block
  /// as the calculator would. No givens: the paper's examples, and nullptr. Throws
  /// Error(given_count) for any other count than none or two.
  DesignRequest* open_on(const DesignRequest& request, std::vector<Given> givens, bool block_given);

  static DesignRequest example(Quantity first, double first_value, Quantity second, double second_value);
  static DesignRequest villard();  ///< Lb = 9 m, l = 4.5, theta_i = 30 deg, F = 1
  static Engine alcala_ca();
};

/// Writes the workbook to `path` (an .xlsx file). The designs take `inputs`; the constants are
/// `table`'s. Throws Error(usage) when the file cannot be written. A pair with Lb, given for any
/// sheet, opens the sheet "from Lb and one" (Lb first); the sheet it was given for then opens on
/// its default.
void write_spreadsheet(const ScalingTable& table, const SpreadsheetInputs& inputs, const std::string& path);

}  // namespace trebuchet
