// A release the user sets (quality.hpp, GivenRelease) as the shot watches for it over phase II:
// the value it watches (the time, or the velocity or pin angle unwrapped through the throw), how
// far the release still lies ahead, and the refusal, with the values that occur, of a release
// that cannot be made (docs/verifier.md, "A given release"). Internal to the shot (shot.cpp).
#pragma once

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>

#include "trebuchet/dynamics_types.hpp"
#include "trebuchet/quality.hpp"

namespace trebuchet {

/// The value a given release watches at scaled time t with snapshot s: the time itself, or the
/// velocity or pin angle [rad] unwrapped to within half a turn of `near`, so that it runs on
/// continuously through the throw.
double watched_value(ReleaseBy by, double t, const Snapshot& s, double near);

/// How far the release still lies ahead of a watched value: positive before it, falling through
/// 0 there (the time rises to the given value, an angle falls to it).
double ahead_of(const GivenRelease& given, double watched);

/// What a given release saw over phase II: its value at lift-off and its extremes after, and the
/// values at which the projectile would fly forward, in their first stretch.
struct ReleaseWatch {
  double at_liftoff = 0, last = 0, lowest = 0, highest = 0;
  double forward_lo = INFINITY, forward_hi = -INFINITY;
  std::optional<std::size_t> crossed;  ///< the first sample past the release
  double near = 0;  ///< the value at the sample before it, which the root's values are unwrapped near
  bool forward_ended = false;  ///< the forward values are those of the first forward stretch only
  void add(double value, bool forward);
};

/// One given release followed over phase II's samples, as the shot steps or replayed from them
/// afterwards (a further release read off the same trajectory): both see the same values.
struct GivenWatch {
  /// Starts at lift-off (sample 0) at scaled time t; the whipper's given angle moves by whole
  /// turns to the first one below its value there (docs/machines.md, "The whipper").
  GivenWatch(const GivenRelease& asked, double t, const Snapshot& at_liftoff, bool throws, bool whole_turns);
  /// Adds sample `index` at scaled time t.
  void add(std::size_t index, double t, const Snapshot& s, bool throws);
  /// Whether an angle has passed every value it could be given (below -180 deg, or the whipper's
  /// whole turn below the given one).
  bool spent() const;
  /// Whether the shot has stepped two samples past the release, as a given release's shot does
  /// to refine the running extremes of eq:F before it.
  bool done(std::size_t samples) const { return watch.crossed && samples > *watch.crossed + 2; }
  GivenRelease given;  ///< as watched: the whipper's angle moved by whole turns
  ReleaseWatch watch;
  bool in_trough = false;  ///< already past at lift-off: the release would come in the trough
  bool whole_turns = false;
};

/// Error(bad_number) for a given release that does not come after lift-off, or that throws the
/// projectile backward: `what` went wrong, and the values that do occur, in seconds or degrees.
/// With `whole_turns` (the whipper's angles, which turn through -180 deg) the angles run on, unwrapped.
[[noreturn]] void refuse_given_release(const GivenRelease& given, const ReleaseWatch& watch, const std::string& what, bool whole_turns = false);

}  // namespace trebuchet
