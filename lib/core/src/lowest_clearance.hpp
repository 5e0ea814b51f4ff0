// The contest's clearance of a counterweight: shared by its search (contest.cpp) and its measures
// (contest_measures.cpp).
#pragma once

#include <algorithm>

#include "trebuchet/verification.hpp"

namespace trebuchet {

/// The counterweight's clearance above the ground [m]: the smaller of the geometry's and the shot's.
inline double lowest_clearance(const Verification& v) { return std::min(v.clearance.geometric, v.clearance.in_shot.value_or(v.clearance.geometric)); }

}  // namespace trebuchet
