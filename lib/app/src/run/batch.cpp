#include "trebuchet/app/run/batch.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/input/request.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {
namespace {

enum class ColumnRole { given, theta, F, branch, passed };

struct BatchColumn {
  ColumnRole role;
  std::string key;  // the given's quantity name, or the option's; the whole name when passed
  std::string unit;  // of bare numbers in the column, from the header ("R_m"); "" for SI
  std::optional<Quantity> quantity;  // a given's
};

std::vector<BatchColumn> parse_header(const std::vector<std::string>& names) {
  std::vector<std::string_view> keys = {"theta", "theta_i_deg", "F", "branch"};
  for (Quantity quantity : all_quantities) keys.push_back(quantity_name(quantity));
  // What a batch reads, for the near misses of a column meant as one of them ("Theta", "theta_i").
  std::vector<std::string> read = input_names(op_given);
  for (const char* name : names_of(field_of(&DesignValues::theta_i_deg))) read.emplace_back(name);
  read.insert(read.end(), {key_of(&DesignValues::F), "branch"});
  std::vector<BatchColumn> columns;
  int givens = 0;
  for (const std::string& name : names) {
    const auto split = split_column_name(name, keys);
    if (split && !split->unit.empty() && !is_unit_word(split->unit)) refuse_near_miss(name, read, "batch header");
    BatchColumn column{ColumnRole::passed, name, "", std::nullopt};
    if (split && (split->unit.empty() || (split->key != "F" && split->key != "branch" && split->key != "theta_i_deg"))) {
      column.key = split->key, column.unit = split->unit;
      if (const auto quantity = quantity_from_name(split->key)) {
        column.role = ColumnRole::given;
        column.quantity = quantity;
        if (!column.unit.empty()) parse_value("1" + column.unit, unit_dimension(quantity_dimension(*quantity)), "column '" + name + "'");
      } else if (split->key == "F") {
        column.role = ColumnRole::F;
      } else if (split->key == "branch") {
        column.role = ColumnRole::branch;
      } else {
        column.role = ColumnRole::theta;
        if (!column.unit.empty()) parse_value("1" + column.unit, UnitDimension::angle, "column '" + name + "'");
      }
    }
    for (const BatchColumn& seen : columns)
      if (seen.role != ColumnRole::passed && seen.role == column.role && (seen.key == column.key || column.role != ColumnRole::given))
        throw Error(ErrorKind::usage, "batch header: column '" + name + "' names " + column.key + " a second time; keep one");
    givens += column.role == ColumnRole::given;
    columns.push_back(column);
  }
  for (const BatchColumn& column : columns)
    if (column.role == ColumnRole::passed) refuse_near_miss(column.key, read, "batch header");
  if (givens != 2) {
    std::string given_names, passed_names;
    for (const BatchColumn& column : columns) {
      std::string& names = column.role == ColumnRole::passed ? passed_names : given_names;
      if (column.role == ColumnRole::given || column.role == ColumnRole::passed) names += (names.empty() ? "'" : ", '") + column.key + "'";
    }
    throw Error(ErrorKind::given_count,
                "batch header: found " + std::to_string(givens) + " given column(s)" + (given_names.empty() ? "" : " (" + given_names + ")") +
                    "; name exactly two of R, T, L1, L2, L4, D, M, m, mb, Lb, l (e.g. 'R,m' or 'R_m,m_kg')" +
                    (passed_names.empty() ? "" : "; " + passed_names + " would pass through, not as givens"));
  }
  // A column passed through must not take the name of one the calculator writes (in CSV or JSON).
  const std::vector<std::string> written = design_output_names();
  for (const BatchColumn& column : columns)
    if (column.role == ColumnRole::passed && std::find(written.begin(), written.end(), column.key) != written.end())
      throw Error(ErrorKind::usage,
                  "batch header: the column '" + column.key + "' would pass through, but the output has a column '" + column.key +
                      "' of its own; rename it, e.g. '" + column.key + "_input'");
  return columns;
}

DesignRequest parse_row(const std::vector<BatchColumn>& columns, const std::vector<std::string>& cells, const DesignRequest& defaults) {
  DesignRequest request = defaults;
  std::vector<Given> givens;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const BatchColumn& column = columns[k];
    const std::string value = column.role == ColumnRole::passed ? "" : cell_value(cells[k], column.unit, column.key);
    switch (column.role) {
      case ColumnRole::given:
        givens.push_back({*column.quantity, parse_positive(value, unit_dimension(quantity_dimension(*column.quantity)), column.key)});
        break;
      case ColumnRole::theta: request.theta_i_deg = parse_theta(value, "theta"); break;
      case ColumnRole::F: request.F = parse_positive(value, UnitDimension::dimensionless, "F"); break;
      case ColumnRole::branch: request.branch = parse_branch_choice(value); break;
      case ColumnRole::passed: break;
    }
  }
  request.first = givens[0];
  request.second = givens[1];
  return request;
}

}  // namespace

int run_batch(std::istream& input, const ScalingTable& table, const DesignRequest& defaults,
              const std::function<void(const std::vector<std::string>& passed_columns)>& on_header,
              const std::function<void(const BatchRow&)>& on_row) {
  CsvReader reader(input, "batch input");
  const std::vector<BatchColumn> columns = parse_header(reader.header());
  std::vector<std::string> passed_names;
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (columns[k].role == ColumnRole::passed) passed_names.push_back(reader.header()[k]);
  on_header(passed_names);
  int failures = 0;
  CsvRow row;
  std::vector<std::string> passed;
  while (true) {
    passed.assign(passed_names.size(), "");
    std::optional<Error> error;
    std::optional<DesignRequest> request;
    try {
      if (!reader.next(row)) break;
      for (std::size_t k = 0, p = 0; k < columns.size(); ++k)
        if (columns[k].role == ColumnRole::passed) passed[p++] = row.cells[k];
      request = parse_row(columns, row.cells, defaults);
      const OptimalEngine design = design_optimal_engine(table, *request);
      on_row({row.line, passed, &*request, &design, nullptr});
      continue;
    } catch (const Error& e) {
      error = e;
    }
    ++failures;
    on_row({row.line, passed, request ? &*request : nullptr, nullptr, &*error});
  }
  return failures;
}

}  // namespace trebuchet
