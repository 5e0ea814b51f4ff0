// sweep: what if one value of an engine changes? Its shot at each point of a range, the rest
// held (app/run/what_if.hpp, docs/verifier.md).
#include <iostream>

#include "program.hpp"
#include "run.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/run/what_if.hpp"

namespace trebuchet::verify {

namespace {

// The design's values the sweep does not hold: the one it varies, and those the varied one fixes
// another way (a design's F where L3 runs), laid over as at its first point: said, not dropped.
std::vector<std::string> given_way(const DesignValues& values, const std::string& where, const WhatIf& what_if, UnitSystem units) {
  DesignValues swept;
  swept.*what_if.field->member = what_if.from;
  std::vector<std::string> unsaid;  // the sweep's own change, said here by field
  const DesignValues at = overlay_flags(values, swept, where, unsaid);
  std::vector<std::string> notes;
  for (const InputField& field : input_fields()) {
    const std::optional<double>& given = values.*field.member;
    // A record's D = 0 is a beam given by its mass, no value; another release than the one swept
    // is refused by the sweep itself (run_what_if).
    if (!given || (field.member == &DesignValues::D && *given == 0)) continue;
    if (&field != what_if.field && field.group == FieldGroup::release && what_if.field->group == FieldGroup::release) continue;
    const std::string value = engine_key_name(where, field.key) + " = " + quantity_text(*given, field.dimension, units);
    if (&field == what_if.field)
      notes.push_back(value + " gives way to the sweep's values at every point");
    else if (!(at.*field.member))
      notes.push_back(value + " gives way to the sweep's " + what_if.field->key + ", which fixes it another way");
  }
  return notes;
}

}  // namespace

int run_sweep(const Options& flags) {
  if (!flags.what_if) throw Error(ErrorKind::usage, "sweep needs the value to vary and its range: --vary L4=2m..5m");
  nlohmann::json passed = nlohmann::json::object();
  std::string where;
  Options o = flags;  // with the file's settings under the flags'
  const DesignValues values = one_design(flags, "sweep", where, passed, o.settings);
  DesignCheck check = design_check(o);
  WhatIf what_if = *o.what_if;
  what_if.points = o.what_if_points;
  print_notes(given_way(values, where, what_if, o.units));
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
