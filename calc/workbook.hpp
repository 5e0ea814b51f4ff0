// trebuchet-calc --spreadsheet: the calculator as a workbook, opening on the givens or on a
// batch's sites (docs/spreadsheet.md).
#pragma once

#include <istream>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/scaling_table.hpp"

namespace trebuchet {

/// Writes the workbook to `spreadsheet` and says so; returns the program's exit code: the
/// calculator's own when it refuses the givens the workbook opens on, the batch's when a site
/// row is refused (the workbook holds every row, each refused one with its reason), 0 otherwise.
/// `batch` names the sites' file read from `input` ("-" for stdin); empty when there is none.
int write_workbook(const ScalingTable& table, const DesignRequest& request, const std::vector<Given>& givens, bool block_given, bool scale_given,
                   std::istream& input, const std::string& batch, const std::string& spreadsheet);

}  // namespace trebuchet
