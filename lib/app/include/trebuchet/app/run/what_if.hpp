// A what-if sweep: one engine shot again and again as one of its values runs from one end to
// the other, the others held ("what if I lengthen the sling?"). Each point is a whole shot, the
// same as a shot of that engine alone (check_design), at the release the check asks for.
// trebuchet-verify sweep, api::sweep, the page's chart (docs/verifier.md).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "trebuchet/error.hpp"
#include "trebuchet/parallel.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/run/verifier.hpp"

namespace trebuchet {

/// The value varied and its ends, in SI units (angles in degrees).
struct WhatIf {
  const InputField* field = nullptr;
  double from = 0, to = 0;
  int points = 21;
};

/// "L4=2m..5m" (a key, flag or alias of an engine's value, its part's or its release's; a range
/// low..high with units) as `name` ("--vary") gives it, with `points` points. Throws
/// Error(usage) naming the value and the fix for a name that is no such value, and the range's
/// errors (parse_spread) for its ends.
WhatIf parse_what_if(std::string_view text, int points, std::string_view name);

/// One point: the value, and its shot's report or why there is none.
struct WhatIfPoint {
  double value = 0;
  std::optional<DesignReport> report;
  std::optional<Error> error;
};

/// Shoots the engine of `values` (named `where` in messages, as engine_record names it) with `what_if`'s value at each of its points (what_if_values),
/// on thread_count(threads, points) threads, checked and reported as `check` says (no series or
/// pictures). A point that fails keeps its error in its place. The varied value replaces the
/// values' own; a capacity they carry is not checked (each point is another engine). A release's
/// points are read off one trajectory for each run of twenty (check_released_designs), each the
/// same shot; `progress` then hears of the points as each run ends.
std::vector<WhatIfPoint> run_what_if(const DesignValues& values, const std::string& where, const WhatIf& what_if, const DesignCheck& check,
                                     int threads, const Progress& progress = {});

/// {"vary": key, "unit", "from", "to", "values": [the points' values], "points": [each point's
/// shot record (check_design's JSON), or {key: value, "error"}]}; messages' names written by `word` (error.hpp).
nlohmann::ordered_json what_if_json(const WhatIf& what_if, const std::vector<WhatIfPoint>& points,
                                    const std::function<std::string(std::string_view)>& word);

/// A row a point: the value, R, eps, Q, the release, the peak loads and the beam's margin.
std::string what_if_table(const WhatIf& what_if, const std::vector<WhatIfPoint>& points, UnitSystem units,
                          const std::function<std::string(std::string_view)>& word);

/// CSV: the varied value's column (csv_column_of), the shot's columns (verification_csv_header)
/// and "error"; a row a point, each shot's cells as check.csv_digits gives them.
std::string what_if_csv(const WhatIf& what_if, const std::vector<WhatIfPoint>& points, const std::function<std::string(std::string_view)>& word);

}  // namespace trebuchet
