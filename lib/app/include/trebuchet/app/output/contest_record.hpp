// What trebuchet-verify contest reports (contest.hpp, docs/machines.md): the best engine within a
// contest's limits as a shot's record, what each limit measures on it and whether it binds, and
// the Pareto front of the objective against the axle's load, as a table, JSON and a chart.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "trebuchet/contest.hpp"
#include "trebuchet/app/output/pictures.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

/// The best engine's shot record (shot_record.hpp), with "limits": {key: {measured, limit,
/// at_limit, binds, and for a limit given gain_if_relaxed_10_percent}}, "min_clearance"
/// and, when a front is given, "pareto": [{axle_load, R, eps, M, L1, L2, L3, L4, pin_angle_deg}].
/// The limits a contest's record (contest_json) was searched under: each "limits" entry's "limit"
/// and "min_clearance"'s "least". None from anything else.
LimitsToMeet contest_record_limits(const nlohmann::json& record);

nlohmann::ordered_json contest_json(const ContestEngine& best, const ContestRequest& request, const std::vector<ContestEngine>& front);

/// The best engine's shot as a table, its limits, and the front's rows.
std::string contest_table(const ContestEngine& best, const ContestRequest& request, const std::vector<ContestEngine>& front, UnitSystem units);

/// The front as pareto.csv and a gnuplot script pareto.gp that draws pareto.svg.
std::vector<PictureFile> pareto_pictures(const std::vector<ContestEngine>& front, const ContestRequest& request);

}  // namespace trebuchet
