// sweep: what if one value of an engine changes? Its shot at each point of a range, the rest
// held (app/run/what_if.hpp, docs/verifier.md).
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/run/what_if.hpp"

namespace trebuchet::verify {

int run_sweep(const Options& flags) {
  if (!flags.what_if) throw Error(ErrorKind::usage, "sweep needs the value to vary and its range: --vary L4=2m..5m");
  nlohmann::json passed = nlohmann::json::object();
  std::string where;
  Options o = flags;  // with the file's settings under the flags'
  const DesignValues values = one_design(flags, "sweep", where, passed, o.settings);
  DesignCheck check = design_check(o);
  WhatIf what_if = *o.what_if;
  what_if.points = o.what_if_points;
  // A value the design gives and the sweep varies is the sweep's at every point: said, not dropped.
  if (const std::optional<double> given = values.*what_if.field->member)
    print_notes({engine_key_name(where, what_if.field->key) + " = " + quantity_text(*given, what_if.field->dimension, o.units) +
                 " gives way to the sweep's values at every point"});
  // The release is set per point where the sweep varies it (--vary pin_angle=30..40), else once.
  if (what_if.field->group != FieldGroup::release) check.settings.release_at = release_of(values, where);
  const std::vector<WhatIfPoint> points = run_what_if(values, where, what_if, check, o.threads, progress_bar("shots"));
  int code = exit_success, failed = 0;
  for (const WhatIfPoint& p : points)
    if (p.error) ++failed, code = std::max(code, exit_code(Program::verify, p.error->kind()));
  if (o.format == Format::json)
    std::cout << pretty_json(what_if_json(what_if, points, option_word));
  else if (o.format == Format::csv)
    std::cout << what_if_csv(what_if, points, option_word);
  else
    std::cout << what_if_table(what_if, points, o.units, option_word);
  // Every point failed: the engine's fault, reported as the worst failure (on stderr, as every
  // error is); a point that fails among others is a finding.
  if (failed != static_cast<int>(points.size())) return exit_success;
  for (const WhatIfPoint& p : points)
    if (exit_code(Program::verify, p.error->kind()) == code) {
      std::cerr << "trebuchet-verify: every point of the sweep failed; the first that failed worst: " << p.error->message(option_word) << "\n";
      break;
    }
  return code;
}

}  // namespace trebuchet::verify
