// trebuchet-calc: optimal engines from the scaling laws of tab:CPNC. Parses, calls the
// library, prints. Exit codes: cli/exit_codes.hpp and docs/exit_codes.md.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>

#include "flags.hpp"
#include "program.hpp"
#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/input/request.hpp"
#include "trebuchet/app/input/settings.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/table_json.hpp"
#include "trebuchet/app/run/batch.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/scaling_table.hpp"
#include "workbook.hpp"

namespace {

using namespace trebuchet;

struct Options {
  std::map<Quantity, std::string> givens;
  std::string theta = format_number(standard_theta_i_deg);
  std::string F = format_fraction(standard_F);
  DesignValues material;  // the material's rows given (beta2, Young's modulus, wood density, g)
  std::map<Setting, std::string> settings;  // the settings' text as given (settings.def): --branch, --format, ...
  bool extrapolate = false;

  std::string setting(Setting id, const std::string& fallback = "") const {  // an empty value is refused as given (run_program)
    const auto given = settings.find(id);
    return given == settings.end() || given->second.empty() ? fallback : given->second;
  }
};

void print(const OptimalEngine& design, const std::string& format, int digits, UnitSystem units) {
  if (format == "json")
    std::cout << pretty_json(design_json(design));
  else if (format == "csv")
    std::cout << csv_line(design_csv_header(design.engine.machine)) << design_csv_text(design, digits) << "\n";
  else
    std::cout << design_table(design, units);
}

// The table's row of a given.
const InputField& given_field(Quantity quantity) { return *find_field(quantity_name(quantity)); }

// The design with its warnings naming the options of this program (error.hpp).
OptimalEngine in_option_words(OptimalEngine design) {
  for (std::string& warning : design.warnings) warning = with_words(warning, option_word);
  return design;
}

// --batch: a design a row, as CSV or JSON. A row is printed only once it is whole, so that a
// failure cannot leave half a row. A failed row keeps its place, with its pass-through cells and
// the message under "error".
int print_batch(std::istream& input, const ScalingTable& table, const DesignRequest& request, bool json, int digits) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  std::vector<std::string> passed_columns;
  const std::size_t design_columns = design_csv_header(table.machine).size();
  const auto progress = progress_bar("rows");  // a file's rows are not counted ahead: no total
  std::size_t rows_done = 0;
  const auto print_header = [&](const std::vector<std::string>& passed) {
    passed_columns = passed;
    std::vector<std::string> header = {"line"};
    header.insert(header.end(), passed.begin(), passed.end());
    for (const std::string& column : design_csv_header(table.machine)) header.push_back(column);
    header.push_back("error");
    if (!json) std::cout << csv_line(header);
  };
  const auto print_row = [&](const BatchRow& row) {
    if (progress) progress(++rows_done, 0);
    // One write a message: the error stream is unbuffered.
    if (row.error)
      std::cerr << message_start() + ("trebuchet-calc: line " + std::to_string(row.line) + ": " + row.error->message(option_word) + "\n");
    if (json) {
      nlohmann::ordered_json out = {{"line", row.line}};
      for (std::size_t k = 0; k < passed_columns.size(); ++k) out[passed_columns[k]] = row.passed[k];
      if (row.design)
        out.update(design_json(in_option_words(*row.design)));
      else
        out.update({{"error", row.error->message(option_word)}, {"exit_code", exit_code(Program::calc, row.error->kind())}});
      rows.push_back(out);
      return;
    }
    std::string line = std::to_string(row.line);
    for (const std::string& cell : row.passed) {
      line += ',';
      append_csv_cell(line, cell);
    }
    line += ',';
    line += row.design ? design_csv_text(in_option_words(*row.design), digits) : std::string(design_columns - 1, ',');
    line += ',';
    append_csv_cell(line, row.error ? row.error->message(option_word) : "");
    line += '\n';
    std::cout << line;
  };
  const int failures = run_batch(input, table, request, print_header, print_row);
  if (progress) progress(rows_done, rows_done);
  if (json) std::cout << pretty_json(rows);
  if (failures > 0) {
    std::cerr << "trebuchet-calc: " << failures << " row(s) failed; the other rows are in the output\n";
    return exit_code(Program::calc, ErrorKind::batch_rows);
  }
  return 0;
}

// The request the givens complete: the block, the branch, the material and the scale as given.
DesignRequest request_of(const Options& options, const ScalingTable& table) {
  DesignRequest request;
  request.theta_i_deg = parse_theta(options.theta, "--theta");
  request.F = parse_positive(options.F, UnitDimension::dimensionless, "--F");
  request.branch = parse_branch_choice(options.setting(Setting::branch, "auto"));
  request.material = material_of(options.material, table.reference);
  check_material(request.material);  // a material beyond the ordinary is named as such, not as a capacity out of range
  request.extrapolate = options.extrapolate;
  const std::string scale = options.setting(Setting::scale);
  if (!scale.empty()) request.scale = parse_positive(scale, UnitDimension::dimensionless, "--scale");
  return request;
}

// The batch's file, opened into `file`, or stdin for "-".
std::istream& batch_input(const std::string& batch, std::ifstream& file) {
  if (batch == "-") return std::cin;
  if (!batch.empty()) {
    std::error_code error;
    if (std::filesystem::is_directory(batch, error))
      throw Error(ErrorKind::usage, "--batch: '" + batch + "' is a directory; give a CSV file or - for stdin");
    file.open(batch);
    if (!file) throw Error(ErrorKind::usage, "--batch: cannot read '" + batch + "'; give a CSV file or - for stdin");
  }
  return file;
}

int run(const Options& options, bool format_given, bool F_given, bool block_given) {
  const std::string format = options.setting(Setting::format, "table"), digits_text = options.setting(Setting::digits);
  const std::string batch = options.setting(Setting::batch), spreadsheet = options.setting(Setting::spreadsheet);
  const std::string table_file = options.setting(Setting::table), machine_text = options.setting(Setting::machine);
  if (format != "table" && format != "csv" && format != "json")
    throw Error(ErrorKind::usage, "--format: '" + format + "' is not a format; use table, csv or json");
  const int digits = digits_text.empty() ? default_csv_digits : parse_digits(digits_text, "--digits");
  const UnitSystem units = parse_unit_system(options.setting(Setting::units, "si"), "--units");  // read first, whatever the mode
  if (!spreadsheet.empty()) refuse_output_over_input(spreadsheet, "spreadsheet", {table_file, batch});
  const MachineKind machine = machine_text.empty() ? MachineKind::hinged : parse_machine(machine_text, "--machine");
  if (!machine_text.empty() && !table_file.empty())
    throw Error(ErrorKind::usage, "--table: a table names its own machine (its key \"machine\"); drop --machine");
  if (machine != MachineKind::hinged && !spreadsheet.empty())
    throw Error(ErrorKind::usage, "--spreadsheet writes the paper's engine's calculator (tab:CPNC); drop --machine");
  const ScalingTable table_from_file = table_file.empty() ? ScalingTable{} : load_scaling_table(table_file);
  const ScalingTable& table = table_file.empty() ? builtin_scaling_table(machine) : table_from_file;
  if (table.machine != MachineKind::hinged && F_given)
    throw Error(ErrorKind::usage,
                "--F: the " + machine_name(table.machine) + " machine's table holds the counterweight at the short arm's end; drop --F");
  DesignRequest request = request_of(options, table);
  std::vector<Given> givens;
  for (const auto& [quantity, text] : options.givens)
    if (!text.empty()) givens.push_back(parse_given(quantity_name(quantity), text));
  if (!batch.empty() && !givens.empty())
    throw Error(ErrorKind::given_count,
                "--batch takes the givens from its file; drop --" + std::string(quantity_name(givens.front().quantity)) + " from the command line");
  std::ifstream file;
  std::istream& input = batch_input(batch, file);
  if (!spreadsheet.empty()) {
    if (request.extrapolate)
      throw Error(ErrorKind::usage,
                  "--extrapolate: the workbook has no extrapolation (its status says where no segment holds the givens, "
                  "docs/spreadsheet.md); drop it with --spreadsheet");
    if (format_given || !digits_text.empty())
      throw Error(ErrorKind::usage,
                  std::string(format_given ? "--format" : "--digits") + " sets what is printed; --spreadsheet writes an .xlsx workbook, drop it");
    return write_workbook(table, request, givens, block_given, !options.setting(Setting::scale).empty(), input, batch, spreadsheet);
  }
  if (!batch.empty()) return print_batch(input, table, request, format == "json", digits);
  if (givens.size() != 2) {
    std::string flags;
    for (Quantity quantity : all_quantities) flags += std::string(flags.empty() ? "" : " ") + given_field(quantity).flag;
    throw Error(ErrorKind::given_count,
                "found " + std::to_string(givens.size()) + " given(s); give exactly two of " + flags + ", e.g. --R 150m --m 50kg");
  }
  request.first = givens[0];
  request.second = givens[1];
  print(in_option_words(design_optimal_engine(table, request)), format, digits, units);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "trebuchet-calc: the optimal swinging-counterweight trebuchet for a capacity (R, T), for R and a\n"
      "projectile mass, or for any two engine parameters, from the scaling laws of Horsdal's tab:CPNC.\n"
      "Values take unit suffixes (150m, 3.1t, 40kJ, 500ft, 220lb); bare numbers are SI base units.",
      "trebuchet-calc"};
  app.set_version_flag("--version", version_text("trebuchet-calc"));
  Options options;
  // The givens, in the calculator's order (all_quantities), and its settings: the table's rows.
  for (Quantity quantity : all_quantities) {
    const InputField& field = given_field(quantity);
    app.add_option(field.flag, options.givens[quantity], option_help(field));
  }
  const auto flag = [](std::optional<double> DesignValues::*member) { return field_of(member).flag; };
  app.add_option(flag(&DesignValues::theta_i_deg), options.theta, "initial beam angle theta_i [deg]: 30 or 40")->capture_default_str();
  app.add_option(flag(&DesignValues::F), options.F, "counterweight arm fraction (L2+L3)/H: 1 or 2/3")->capture_default_str();
  for (const InputField& field : input_fields())
    if (field.group == FieldGroup::material && (field.operations & op_calculator))
      parsed_option(
          &app, field.flag,
          [&options, &field](const std::string& text) { options.material.*field.member = parse_positive(text, field.dimension, field.flag); },
          option_help(field));
  for (const SettingRow& row : setting_rows())
    if (row.doors & cmd_calc) {
      if (row.id == Setting::extrapolate)  // the one switch
        app.add_flag(row.flag, options.extrapolate, setting_help(row));
      else
        app.add_option(row.flag, options.settings[row.id], setting_help(row));
    }

  return run_program(app, Program::calc, argc, argv,
                     [&] { return run(options, app.count("--format") > 0, app.count("--F") > 0, app.count("--F") + app.count("--theta") > 0); });
}
