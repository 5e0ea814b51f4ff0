// compare: one engine's parts built as each machine, side by side (docs/machines.md).
#include <algorithm>
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/output/contest_record.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/run/verifier.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet::verify {

namespace {

// The contest's limits compare measures each column against: those of the contest's record it
// reads (`design`: its "limits" and "min_clearance"), each flag given laid over them as a flag
// beside a file replaces its value, and said in a note; or the flags' alone.
LimitsToMeet comparison_limits(const Options& flags, const nlohmann::json& design, const std::string& where) {
  LimitsToMeet out = contest_record_limits(design);
  const bool recorded = out.any();
  std::vector<std::string> given;
  for (int k = 0; k < contest_limit_count; ++k)
    if (flags.limits[k]) {
      out.limits[k] = flags.limits[k];
      given.push_back(std::string("{{") + contest_limit_key(static_cast<ContestLimit>(k)) + "}}");
    }
  if (flags.min_clearance) out.min_clearance = *flags.min_clearance, given.push_back("{{min_clearance}}");
  check_limits_to_meet(out);  // a record's, by hand or not, as the flags'
  if (recorded)
    print_notes({"measured against the limits of the contest " + where + " records" +
                 (given.empty() ? std::string("; a flag such as {{max_width}} gives one anew") : ", with " + join(given, ", ") + " as given")});
  return out;
}

}  // namespace

int run_compare(const Options& flags) {
  nlohmann::json passed = nlohmann::json::object();
  std::string where;
  Options o = flags;  // with the file's settings under the flags'
  nlohmann::json design;
  const DesignValues values = one_design(flags, "compare", where, passed, o.settings, &design);
  // A record carries the release its shot maximised (a shot's: Q), which compare takes as the
  // file's setting; say so, as compare's own is the range.
  if (o.settings.quality && !flags.settings.quality && *o.settings.quality != Release::range)
    print_notes({"the release maximises " + release_name(*o.settings.quality) + ", as " + where +
                 " says (a shot's record keeps its own); compare's own is the range: give {{quality}} range for it"});
  DesignCheck check = design_check(o);
  check.limits = comparison_limits(flags, design, source_name(flags.input));
  const std::vector<MachineComparison> comparison = compare_design(values, where, o.settings, check);
  int code = exit_success, refused = 0;
  for (const MachineComparison& c : comparison)
    if (c.error) ++refused, code = std::max(code, exit_code(Program::verify, c.error->kind()));
  if (o.format == Format::json) {
    std::cout << pretty_json(comparison_json(comparison, option_word));
  } else if (o.format == Format::csv) {
    std::vector<std::string> header = verification_csv_header();
    header.push_back("error");
    if (check.limits.any()) header.push_back("breaks_limits");  // the contest's limits a column breaks, by key
    std::cout << csv_line(header);
    for (const MachineComparison& c : comparison) {
      std::vector<std::string> cells = c.report ? c.report->csv : std::vector<std::string>(verification_csv_header().size(), "");
      if (!c.report) {  // a refused machine: its name in the machine column, the rest empty
        const auto column = std::find(header.begin(), header.end(), machine_key) - header.begin();
        cells[static_cast<std::size_t>(column)] = machine_name(c.machine);
      }
      cells.push_back(c.error ? c.error->message(option_word) : "");
      if (check.limits.any()) {
        std::string keys;
        for (const BrokenLimit& b : c.broken) keys += (keys.empty() ? "" : " ") + std::string(b.key);
        cells.push_back(c.unmeasured ? "not measured" : keys);
      }
      std::cout << csv_line(cells);
    }
  } else {
    std::cout << comparison_table(comparison, o.units, option_word);
  }
  // Every machine refused: the engine's fault, reported as the worst refusal (on stderr, as
  // every error is); else what shot stands.
  if (refused != static_cast<int>(comparison.size())) return exit_success;
  for (const MachineComparison& c : comparison)
    std::cerr << "trebuchet-verify: " << machine_name(c.machine) << " refused: " << c.error->message(option_word) << "\n";
  return code;
}

}  // namespace trebuchet::verify
