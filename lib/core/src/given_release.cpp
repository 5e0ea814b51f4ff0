#include "given_release.hpp"

#include <algorithm>

#include "trebuchet/angles.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/shot.hpp"

namespace trebuchet {

namespace {

// The angle a moved by whole turns to within half a turn of `near` [rad].
double unwrapped_near(double a, double near) { return near + std::remainder(a - near, 2 * M_PI); }

// A watched value as the user gives it: seconds, or degrees (a pin as bent for its friction).
std::string shown(const GivenRelease& given, double watched) {
  return given.by == ReleaseBy::time ? format_significant(watched * given.time_unit, 5) + " s"
                                     : format_significant(degrees(watched + given.shown_offset), 5) + " deg";
}

}  // namespace

double watched_value(ReleaseBy by, double t, const Snapshot& s, double near) {
  switch (by) {
    case ReleaseBy::time: return t;
    case ReleaseBy::velocity_angle: return unwrapped_near(velocity_angle(s), near);
    case ReleaseBy::pin_angle: return unwrapped_near(pin_angle(s), near);
  }
  return t;
}

double ahead_of(const GivenRelease& given, double watched) { return given.by == ReleaseBy::time ? given.value - watched : watched - given.value; }

void ReleaseWatch::add(double value, bool forward) {
  last = value, lowest = std::min(lowest, value), highest = std::max(highest, value);
  if (forward && !forward_ended) forward_lo = std::min(forward_lo, value), forward_hi = std::max(forward_hi, value);
  forward_ended = forward_ended || (!forward && forward_lo <= forward_hi);
}

GivenWatch::GivenWatch(const GivenRelease& asked, double t, const Snapshot& at_liftoff, bool throws, bool turns) : given(asked), whole_turns(turns) {
  watch.at_liftoff = watch.lowest = watch.highest = watched_value(given.by, t, at_liftoff, M_PI / 2);
  if (whole_turns && given.by != ReleaseBy::time) given.value -= 2 * M_PI * std::ceil((given.value - watch.at_liftoff) / (2 * M_PI));
  watch.add(watch.at_liftoff, throws);
  in_trough = !(ahead_of(given, watch.at_liftoff) > 0);
}

void GivenWatch::add(std::size_t index, double t, const Snapshot& s, bool throws) {
  const double before = watch.last;
  watch.add(watched_value(given.by, t, s, before), throws);
  if (!in_trough && !watch.crossed && !(ahead_of(given, watch.last) > 0)) watch.crossed = index, watch.near = before;
}

bool GivenWatch::spent() const { return given.by != ReleaseBy::time && watch.last < (whole_turns ? given.value - 2 * M_PI : -M_PI); }

void refuse_given_release(const GivenRelease& given, const ReleaseWatch& watch, const std::string& what, bool whole_turns) {
  static const char* names[] = {"{{release_time}}", "{{release_angle}}", "{{pin_angle}}"};
  static const char* quantities[] = {"the time", "the projectile's velocity angle", "the pin angle"};
  const int k = static_cast<int>(given.by);
  const std::string as_bent = given.shown_offset != 0 ? " (as bent for the pin's friction)" : "";
  const bool rises = given.by == ReleaseBy::time;
  // The whipper's angles turn on past -180 deg: their sweep, and its values as angles again.
  const bool turning = whole_turns && !rises;
  const auto wrapped = [&](double a) { return turning ? std::remainder(a, 2 * M_PI) : a; };
  std::string message = std::string(names[k]) + " = " + shown(given, given.value) + ": " + what + "; after " +
      (whole_turns ? "the projectile leaves the arm " : "lift-off ") + quantities[k] + as_bent + " runs from " + shown(given, watch.at_liftoff) +
      (turning ? " down through a further " + shown(given, watch.at_liftoff - watch.lowest)
               : " to " + shown(given, rises ? watch.highest : std::max(watch.lowest, -M_PI)));
  if (watch.forward_lo <= watch.forward_hi)
    message += std::string(", and the projectile flies forward") + (whole_turns ? " and up" : "") + " for values from about " +
        shown(given, wrapped(rises ? watch.forward_lo : watch.forward_hi)) + " to " +
        shown(given, wrapped(rises ? watch.forward_hi : watch.forward_lo));
  else
    message += ", and no release in it throws the projectile forward";
  throw Error(ErrorKind::bad_number, message);
}

double velocity_angle(const Snapshot& s) { return std::atan2(s.projectile_velocity.y, -s.projectile_velocity.x); }

double pin_angle(const Snapshot& s) {
  // The long arm from the pivot, which the floating arm's axle carries away from the frame's origin.
  const Vec2 arm{s.tip.x - s.pivot.x, s.tip.y - s.pivot.y}, sling{s.projectile.x - s.tip.x, s.projectile.y - s.tip.y};
  return std::atan2(-(arm.x * sling.y - arm.y * sling.x), arm.x * sling.x + arm.y * sling.y);
}

}  // namespace trebuchet
