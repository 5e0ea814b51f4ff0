// shot and fit: the design from a file, stdin or flags; many designs (a JSON array or CSV rows)
// are checked on every core, each in its place.
#include <filesystem>
#include <iostream>
#include <optional>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/input/text_input.hpp"

namespace trebuchet::verify {
DesignCheck design_check(const Options& o) {
  DesignCheck check;
  // With a file, the flags' settings go over each design's own (a record's assumptions) and
  // are checked there: --wind alone may change a record's air.
  check.settings = settings_of(o, !o.input.empty());
  check.given = o.settings;
  check.material = o.design;  // its material rows, over each design's own
  check.csv = o.format == Format::csv;
  check.table = o.format == Format::table;
  check.csv_digits = o.digits;
  check.inputs = {o.input};
  check.units = o.units;
  return check;
}

namespace {

// shot's and fit's: the capacity's check, the release the flags set, the series and the pictures.
DesignCheck shot_check(const Options& o, bool fit) {
  DesignCheck check = design_check(o);
  check.settings.release_at = release_of(o.design, "");
  check.tolerance = o.settings.tol.value_or(check.tolerance);
  check.fit = fit;
  check.series_path = o.series;
  check.series_dt_s = o.series_dt_s;
  check.plot_dir = o.plot;
  return check;
}

// Many designs: every one is tried, on every core; a failing one is reported in its place, the
// others kept. Each design's report goes to its own slot, and all are printed in input order, so
// the output is the same on any number of threads.
int run_many(const Options& o, const DesignInputs& in, const DesignCheck& check) {
  const std::size_t count = in.rows.size();
  std::vector<DesignReport> reports(count);
  std::vector<std::optional<Error>> errors(count);
  std::vector<std::vector<std::string>> notes(count);
  for_each_index(
      count, o.threads,
      [&](std::size_t i) {
        try {
          // Unreadable, or failed upstream (the calculator's "error" column).
          if (const std::string refusal = row_refusal(in.rows[i], o.settings); !refusal.empty()) throw Error(ErrorKind::usage, refusal);
          const EngineRecord record = read_engine(in.rows[i].design, in.where[i], &o.design);
          notes[i] = record.notes;
          for (std::string& note : settings_notes(record.settings, o.settings, in.where[i])) notes[i].push_back(std::move(note));
          reports[i] = check_design(record, check);
        } catch (const Error& e) {
          errors[i] = e;
        }
      },
      progress_bar("designs"));
  for (const std::vector<std::string>& said : notes) print_notes(said);
  std::vector<std::string> header = in.passed_columns;
  for (const std::string& column : verification_csv_header()) header.push_back(column);
  header.push_back("error");
  if (o.format == Format::csv) std::cout << csv_line(header);
  nlohmann::ordered_json results = nlohmann::ordered_json::array();
  int code = exit_success;
  for (std::size_t i = 0; i < count; ++i) {
    const DesignRows::Row& row = in.rows[i];
    nlohmann::ordered_json record = nlohmann::ordered_json::object();
    for (std::size_t k = 0; k < in.passed_columns.size(); ++k) record[in.passed_columns[k]] = row.passed[k];
    std::vector<std::string> cells = row.passed;
    // Messages name the row by its input line and its pass-through cells, "line 3 (site Saone)".
    std::vector<std::string> described;
    for (std::size_t k = 0; k < in.passed_columns.size(); ++k)
      if (in.passed_columns[k] != "line") described.push_back(in.passed_columns[k] + " " + row.passed[k]);
    const std::string name = in.where[i] + (described.empty() ? "" : " (" + join(described, ", ") + ")");
    if (const auto& e = errors[i]) {
      const int error_code = exit_code(Program::verify, e->kind());
      const std::string message = e->message(option_word);
      std::cerr << message_start() << "trebuchet-verify: " << (message.rfind(in.where[i], 0) == 0 ? "" : name + ": ") << message << "\n";
      record.update({{"error", message}, {"exit_code", error_code}});
      cells.resize(header.size() - 1);
      cells.push_back(message);
      code = std::max(code, error_code);
    } else {
      for (auto it = reports[i].json.begin(); it != reports[i].json.end(); ++it) record[it.key()] = std::move(it.value());
      cells.insert(cells.end(), reports[i].csv.begin(), reports[i].csv.end());
      cells.push_back("");
      if (o.format == Format::table) std::cout << name << "\n" << reports[i].table << "\n";
      if (reports[i].outside_tolerance) code = std::max(code, exit_outside_tolerance);
    }
    results.push_back(std::move(record));
    if (o.format == Format::csv) std::cout << csv_line(cells);
  }
  if (o.format == Format::json) std::cout << pretty_json(results);
  return code;
}

}  // namespace

void print_notes(const std::vector<std::string>& notes) {
  for (const std::string& note : notes) std::cerr << message_start() << "trebuchet-verify: note: " << with_words(note, option_word) << "\n";
}

bool has_engine_flags(const DesignValues& d) {
  for (const InputField& field : input_fields())
    if ((field.operations & op_shot) && field.group != FieldGroup::material && field.group != FieldGroup::capacity &&
        field.group != FieldGroup::release && d.*field.member)
      return true;
  return false;
}

DesignValues one_design(const Options& o, const std::string& subcommand, std::string& where, nlohmann::json& passed, SettingsValues& settings,
                        nlohmann::json* object) {
  settings = o.settings;
  if (o.input.empty()) {
    if (!has_engine_flags(o.design))
      throw Error(ErrorKind::usage,
                  "no design; give a JSON or CSV file, or flags like --L1 4.13m --L2 0.88m --L3 0.6m --L4 3.55m --M 3.11t --m 50kg --mb 174kg");
    return o.design;
  }
  const DesignInputs in = read_design_inputs(read_text(o.input, "a design object like {\"L1\": \"6.13m\", ...}, or CSV with one row"), o.input);
  if (!in.single || in.rows.size() != 1) throw Error(ErrorKind::usage, subcommand + " takes one design; " + source_name(o.input) + " holds more");
  where = in.where.front();
  if (object) *object = in.rows.front().design;
  if (const std::string refusal = row_refusal(in.rows.front(), o.settings); !refusal.empty()) throw Error(ErrorKind::usage, where + ": " + refusal);
  SettingsValues own;
  std::vector<std::string> notes;
  // The flags over the file's values (--machine builds the file's design as that machine), and its settings under theirs.
  const DesignValues values = overlay_flags(read_design_values(in.rows.front().design, where, &passed, &own), o.design, where, notes);
  for (std::string& note : settings_notes(own, o.settings, where)) notes.push_back(std::move(note));
  if (!passed.empty()) {  // as a shot's table says it
    std::vector<std::string> keys;
    for (const auto& [key, value] : passed.items()) keys.push_back(key);
    notes.push_back("passed through, not read: " + join(keys, ", "));
  }
  print_notes(notes);
  settings = overlay(own, o.settings);
  return values;
}

int run_shot(const Options& o, bool fit) {
  const DesignCheck check = shot_check(o, fit);
  DesignInputs in;
  if (!o.input.empty()) {
    // The flags' values replace each design's (--machine builds every design of the file as that machine), with a note.
    in = read_design_inputs(read_text(o.input, "a design object like {\"L1\": \"6.13m\", ...}, an array of them, or CSV with a header (docs/csv.md)"),
                            o.input);
  } else if (!has_engine_flags(o.design)) {
    throw Error(
        ErrorKind::usage,
        "no design; give a JSON or CSV file (or - for stdin), or flags like --L1 6.13m --L2 1.08m --F 1 --L4 5.8m --M 14.3t --m 100kg --mb 660kg");
  }
  const std::size_t count = o.input.empty() ? 1 : in.rows.size();
  // --R/--T on the command line give the capacity of a single design.
  if (!o.input.empty() && !in.single && (o.design.R || o.design.T))
    throw Error(ErrorKind::usage,
                "--R and --T give the capacity of one design, but " + source_name(o.input) + " holds " + std::to_string(count) +
                    "; give R and T in each design instead");
  if (!o.series.empty() && count != 1)
    throw Error(ErrorKind::usage, "--series writes the motion of one design; the input holds " + std::to_string(count));
  if (!o.plot.empty() && count != 1) throw Error(ErrorKind::usage, "--plot draws one design; the input holds " + std::to_string(count));
  if (!o.series.empty()) refuse_output_over_input(o.series, "series", {o.input});
  if (!o.series.empty() && !o.plot.empty() && std::filesystem::weakly_canonical(o.series) == std::filesystem::weakly_canonical(o.plot))
    throw Error(ErrorKind::usage,
                "--series and --plot name the same path '" + o.plot + "'; give the series a file and the pictures a folder of their own");
  if (!o.input.empty() && !in.single) {
    if (!o.spreads.empty())
      throw Error(ErrorKind::usage,
                  "ranges and spreads are for the Monte Carlo run of one design object, but " + source_name(o.input) + " holds " +
                      (count == 1 ? std::string("its design in an array or a CSV row") : std::to_string(count) + " designs") +
                      "; give one JSON object, or each value as one number");
    refuse_monte_carlo_settings(o);
    return run_many(o, in, check);
  }
  // A calibration's report over unknowns, read back: the same run again.
  if (!fit && !o.input.empty() && in.single && is_calibration_record(in.rows.front().design)) {
    if (has_engine_flags(o.design) || !o.spreads.empty())
      throw Error(ErrorKind::usage,
                  source_name(o.input) + " is calibrate's report, which runs again as written; give the flags to calibrate instead");
    // Its settings (samples, seed, the air, ...) under the flags', each change noted.
    CalibrationRunInputs inputs = calibration_run_inputs(in.rows.front().design, in.where.front());
    print_notes(settings_notes(inputs.request.settings, o.settings, in.where.front()));
    inputs.request.settings = overlay(inputs.request.settings, o.settings);
    inputs.samples = inputs.request.settings.samples.value_or(inputs.samples);
    inputs.seed = inputs.request.settings.seed.value_or(inputs.seed);
    return run_calibration(o, inputs);
  }
  // One design whose values (a file's or the flags') hold a range or a spread: its Monte Carlo run.
  if (!fit && !o.input.empty() && in.rows.front().error.empty() && (!o.spreads.empty() || holds_spreads(in.rows.front().design)))
    return run_monte_carlo(o, false, &in.rows.front().design, in.where.front());
  if (!fit && !o.input.empty()) refuse_monte_carlo_settings(o);

  if (!o.input.empty())
    if (const std::string refusal = row_refusal(in.rows.front(), o.settings); !refusal.empty()) throw Error(ErrorKind::usage, refusal);
  const EngineRecord record = o.input.empty() ? engine_record(o.design, "") : read_engine(in.rows.front().design, in.where.front(), &o.design);
  print_notes(record.notes);
  if (!o.input.empty()) print_notes(settings_notes(record.settings, o.settings, in.where.front()));
  const DesignReport report = check_design(record, check);
  if (o.format == Format::json)
    std::cout << pretty_json(report.json);
  else if (o.format == Format::csv)
    std::cout << csv_line(verification_csv_header()) << csv_line(report.csv);
  else
    std::cout << report.table;
  return report.outside_tolerance ? exit_outside_tolerance : exit_success;
}

}  // namespace trebuchet::verify
