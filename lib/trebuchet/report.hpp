// What the calculator prints: JSON (for tools), CSV (for spreadsheets), a table (for people).
// All numbers are SI base units (m, kg, J, m/s^2, Pa, kg/m^3); angles in degrees.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "trebuchet/calculator.hpp"

namespace trebuchet {

/// Throws Error(numerical) if any printed number would be NaN or infinite.
void require_finite(const OptimalEngine& design);

/// Keys: R, T, X, Y, branch, theta_i_deg, F, beta2, L1, L2, L3, L4, D, M, m, mb, Lb, H, the
/// scaled design l, l4, L, mu, mu_b, K, DeltaU, the material, amplification, warnings and,
/// near X_d, branch_steps.
nlohmann::ordered_json design_json(const OptimalEngine& design);

/// Comma-separated column names, in the order of design_csv_row.
std::string design_csv_header();
std::string design_csv_row(const OptimalEngine& design);

/// A block of aligned lines with units, for reading at a glance.
std::string design_table(const OptimalEngine& design);

}  // namespace trebuchet
