#include "workbook.hpp"

#include <filesystem>
#include <iostream>
#include <optional>

#include "program.hpp"
#include "trebuchet/app/output/spreadsheet.hpp"
#include "trebuchet/app/run/batch.hpp"
#include "trebuchet/error.hpp"

namespace trebuchet {
namespace {

// The givens the workbook opens on (SpreadsheetInputs::open_on). Givens the calculator refuses
// still open their sheet, which says why: the refusal is returned, for the run to exit as the
// calculator does.
std::optional<Error> open_sheets(const ScalingTable& table, const DesignRequest& request, const std::vector<Given>& givens, bool block_given,
                                 SpreadsheetInputs& inputs) {
  DesignRequest* sheet = inputs.open_on(request, givens, block_given);
  if (!sheet) return std::nullopt;
  try {
    design_optimal_engine(table, *sheet);
  } catch (const Error& e) {
    // The workbook has no extrapolation: the calculator's advice to add it is cut.
    std::string why = e.named_message();
    if (const std::size_t cut = why.find("; or add {{extrapolate}}"); cut != std::string::npos) why.resize(cut);
    const Error refusal(e.kind(), why);
    inputs.refusal = {sheet,
                      "The calculator refuses the givens this sheet opened on (trebuchet-calc: exit " +
                          std::to_string(exit_code(Program::calc, e.kind())) + "): " + refusal.message(option_word)};
    return refusal;
  }
  return std::nullopt;
}

// The user's sites: a row each on the sheet "your sites", a refused row with its reason (a name
// longer than a cell holds too, the good rows kept); how many were refused. --scale sets the
// sheet "model scaling": the sites are designed full size, as the sheet designs them.
int read_sites(std::istream& input, const std::string& batch, const ScalingTable& table, const DesignRequest& request, SpreadsheetInputs& inputs) {
  UserSites sites{batch == "-" ? std::string("stdin") : std::filesystem::path(batch).filename().string(), {}, {}};
  DesignRequest full_size = request;
  full_size.scale = 1;
  int overlong_rows = 0;
  const int failures = run_batch(
      input, table, full_size, [&](const std::vector<std::string>& passed) { sites.columns = passed; },
      [&](const BatchRow& row) {
        const std::string overlong = overlong_cell(sites.columns, row.passed);
        const std::string refusal = row.error ? row.error->message(option_word) : overlong;
        if (!refusal.empty()) std::cerr << message_start() + ("trebuchet-calc: line " + std::to_string(row.line) + ": " + refusal + "\n");
        if (!row.error && !overlong.empty()) ++overlong_rows;
        sites.rows.push_back(
            {row.line, row.passed, row.request && overlong.empty() ? std::optional<DesignRequest>(*row.request) : std::nullopt, refusal});
      });
  inputs.sites = std::move(sites);
  return failures + overlong_rows;
}

}  // namespace

int write_workbook(const ScalingTable& table, const DesignRequest& request, const std::vector<Given>& givens, bool block_given, bool scale_given,
                   std::istream& input, const std::string& batch, const std::string& spreadsheet) {
  SpreadsheetInputs inputs;
  inputs.material = request.material;
  if (scale_given) inputs.model_scale = request.scale;  // the sheet "model scaling" opens on it
  const std::optional<Error> refusal = open_sheets(table, request, givens, block_given, inputs);
  const int failures = batch.empty() ? 0 : read_sites(input, batch, table, request, inputs);
  write_spreadsheet(table, inputs, spreadsheet);
  std::cout << "wrote " << spreadsheet << ": the calculator as a workbook with live formulas (docs/spreadsheet.md)";
  if (inputs.sites)
    std::cout << ", opening on your " << inputs.sites->rows.size() << " site(s) on the sheet 'your sites'"
              << (failures > 0 ? ", " + std::to_string(failures) + " of them refused, each with its reason in its row" : std::string());
  std::cout << "\n";
  if (refusal) {
    std::cerr << "trebuchet-calc: " << refusal->message(option_word) << "\n";
    return exit_code(Program::calc, refusal->kind());
  }
  if (failures > 0) {
    std::cerr << "trebuchet-calc: " << failures << " row(s) refused; the workbook holds every row, the refused ones with their reasons\n";
    return exit_code(Program::calc, ErrorKind::batch_rows);
  }
  return 0;
}

}  // namespace trebuchet
