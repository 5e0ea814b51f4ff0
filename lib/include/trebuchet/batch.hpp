// Batch design from CSV: one request a row, the header names the two givens and optionally
// theta, F and branch. A bad row is reported and the others are still computed.
#pragma once

#include <functional>
#include <istream>

#include "trebuchet/calculator.hpp"
#include "trebuchet/error.hpp"

namespace trebuchet {

/// Called once a data row, in input order: exactly one of design and error is non-null.
using BatchRowHandler = std::function<void(int line, const OptimalEngine* design, const Error* error)>;

/// Reads the CSV from `input`. Cells may carry units ("150m"); blank lines and lines starting
/// with '#' are skipped. `defaults` supplies theta, F, branch and the material for columns the
/// file does not have. Throws Error(usage or given_count) for a bad header; returns the number
/// of rows that failed.
int run_batch(std::istream& input, const ScalingTable& table, const DesignRequest& defaults,
              const BatchRowHandler& handle_row);

}  // namespace trebuchet
