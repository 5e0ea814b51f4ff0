// The calculator's record of an optimal engine, as JSON and CSV (trebuchet-calc, api::design).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/app/records/schema.hpp"

namespace trebuchet {

/// Throws Error(bad_number) naming the first figure of the design that is not finite, as its
/// writers do: for a report that prints it in another form.
void require_finite(const OptimalEngine& design);

/// The calculator's design: R, T, X, Y, the engine's keys, amplification, branch, warnings and,
/// near X_d, branch_steps.
nlohmann::ordered_json design_json(const OptimalEngine& design);

/// The design's CSV columns, keys with units (R_m, T_J, ...), branch, warnings and air (vacuum), and one
/// design's cells with `digits` significant digits, quoted where they must be and joined by commas
/// (no line feed): a batch appends them to a row. A table of another machine adds its column
/// "machine" last (docs/machines.md), so that its designs read back as that machine.
std::vector<std::string> design_csv_header(MachineKind machine = MachineKind::hinged);
/// Every name the calculator's outputs use (CSV columns, JSON keys, a batch's line and error):
/// a column of a batch passed through must not take one of them.
std::vector<std::string> design_output_names();
std::string design_csv_text(const OptimalEngine& design, int digits);

}  // namespace trebuchet
