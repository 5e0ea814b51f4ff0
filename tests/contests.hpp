// The contests the tests share, each once.
#pragma once

#include "trebuchet/contest.hpp"

namespace trebuchet::testing {

/// A school contest: a 0.5 kg ball, a beam of 1.5 kg/m, within a box 4 m wide and 3 m high, a
/// counterweight of at most 60 kg; released where the range peaks, as trebuchet-verify contest does.
inline ContestRequest school_contest(MachineKind machine) {
  ContestRequest r;
  r.machine = machine;
  r.projectile_mass = 0.5;
  r.beam_mass_per_length = 1.5;
  r.limits[width_limit] = 4;
  r.limits[height_limit] = 3;
  r.limits[mass_limit] = 60;
  r.settings.criterion.release = Release::range;
  return r;
}

}  // namespace trebuchet::testing
