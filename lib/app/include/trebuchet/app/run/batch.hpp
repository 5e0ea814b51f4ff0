// Batch design from CSV (docs/csv.md): one request a row; the header names the two givens
// (with an optional unit, "R_m", "M_t") and optionally theta, F and branch. Every other column
// is passed through to the output unchanged, e.g. a site name. A bad row is reported in its
// place and the others are still computed.
#pragma once

#include <functional>
#include <istream>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/scaling_table.hpp"

namespace trebuchet {

/// One data row's outcome: exactly one of design and error is non-null.
struct BatchRow {
  int line;  ///< line number in the input, from 1
  const std::vector<std::string>& passed;  ///< the pass-through cells, in the order of the header
  const DesignRequest* request;  ///< the request the row reads as; null when a cell cannot be read
  const OptimalEngine* design;
  const Error* error;
};

/// Reads the CSV from `input` (CsvReader: BOM, CRLF, ',' ';' or tab, decimal commas).
/// `on_header` receives the names of the pass-through columns before the first row; `on_row`
/// each row in input order. `defaults` supplies theta, F, branch and the material for columns
/// the file does not have. Throws Error(usage or given_count) for a bad header; returns the
/// number of rows that failed.
int run_batch(std::istream& input, const ScalingTable& table, const DesignRequest& defaults,
              const std::function<void(const std::vector<std::string>& passed_columns)>& on_header,
              const std::function<void(const BatchRow&)>& on_row);

}  // namespace trebuchet
