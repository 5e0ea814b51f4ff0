// compare: one engine's parts built as each machine, side by side (docs/machines.md).
#include <algorithm>
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/names.hpp"
#include "trebuchet/app/text_input.hpp"
#include "trebuchet/app/verifier.hpp"

namespace trebuchet::verify {

int run_compare(const Options& flags) {
  nlohmann::json passed = nlohmann::json::object();
  std::string where;
  Options o = flags;  // with the file's settings under the flags'
  const DesignValues values = one_design(flags, "compare", where, passed, o.settings);
  // A record carries the release its shot maximised (a shot's: Q), which compare takes as the
  // file's setting; say so, as compare's own is the range.
  if (o.settings.quality && !flags.settings.quality && *o.settings.quality != Release::range)
    print_notes({"the release maximises " + release_name(*o.settings.quality) + ", as " + where +
                 " says (a shot's record keeps its own); compare's own is the range: give {{quality}} range for it"});
  const std::vector<MachineComparison> comparison = compare_design(values, where, o.settings, design_check(o));
  int code = exit_success, refused = 0;
  for (const MachineComparison& c : comparison)
    if (c.error) ++refused, code = std::max(code, exit_code(Program::verify, c.error->kind()));
  if (o.format == Format::json) {
    std::cout << pretty_json(comparison_json(comparison, option_word));
  } else if (o.format == Format::csv) {
    std::vector<std::string> header = verification_csv_header();
    header.push_back("error");
    std::cout << csv_line(header);
    for (const MachineComparison& c : comparison) {
      std::vector<std::string> cells = c.report ? c.report->csv : std::vector<std::string>(header.size() - 1, "");
      if (!c.report) {  // a refused machine: its name in the machine column, the rest empty
        const auto column = std::find(header.begin(), header.end(), machine_key) - header.begin();
        cells[static_cast<std::size_t>(column)] = machine_name(c.machine);
      }
      cells.push_back(c.error ? c.error->message(option_word) : "");
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
