// A shot as its pictures show it (issue 13): the motion sampled about 200 times, the moments
// the pictures mark, the flight to its end, and Q, eps and R over phase II. Positions are on the
// site (report.hpp's site_point) in metres: the geometry that the gnuplot scripts (pictures.hpp)
// and the page's viewer (web/viewer.js, through shot_series_json) draw.
#pragma once

#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

#include "trebuchet/engine.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/output/report.hpp"

namespace trebuchet {

/// Indices into a trace of the moments the pictures mark.
struct Moments {
  std::size_t start = 0, liftoff = 0, peak_reaction = 0, first_extreme = 0, second_extreme = 0, release = 0;
};

/// A shot as the pictures and the viewer (web/viewer.js) show it: its figures, its motion sampled
/// about 200 times up to the release and on to the ground after it, its flight to the end
/// (the target level, or back at the release height for Denny's range) through the settings' air
/// or vacuum, Q, eps and R over phase II, on past the release as if the projectile were kept, and
/// R and Q against the pin angle.
struct ShotSeries {
  Verification verification;
  std::vector<TracePoint> trace;  ///< phases I and II up to the release, then phase III (shot.hpp)
  double time_unit = 1;  ///< sqrt(L2/g), the scaled time's unit (section 3) [s]
  std::size_t liftoff = 0, peak_reaction = 0, first_extreme = 0, second_extreme = 0, release = 0;  ///< indices into trace
  std::vector<SitePoint> flight;  ///< the projectile from the release to the end of its flight [m]
  double flight_time = 0;  ///< [s]
  /// A moment of phase II taken as a release (shot.hpp's release_point): Q is the Q_n the shot
  /// maximised, R the range at level 0 in vacuum; the extremes of eq:F so far.
  struct Moment {
    double t;  ///< [s]
    double quality, efficiency, range;  ///< scaled, as release_point gives them
    ForceValues running_max;
  };
  std::vector<Moment> phase_two;
  std::size_t release_row = 0;  ///< the release, in phase_two
  ForceValues final_extremes{};  ///< eq:F's extremes up to the release, scaled
  /// The shot released at pin angles 20 deg either side of its own, every 2 deg, read off its shot (PinScan): R
  /// and Q against the pin, which pin.svg and the viewer's pin chart draw.
  std::vector<PinShot> pins;
  /// The projectile `after` seconds past the release (at the flight's end once it has landed).
  SitePoint stone_at(double after) const;
};
/// `verification` is the shot of `engine` under `settings` (verify_engine), which the caller has.
ShotSeries shot_series(const Engine& engine, const ShotSettings& settings, const Verification& verification);

/// The series as the viewer reads it: every value in SI units (s, m, N, J, N m), angles in
/// degrees, positions on the site (x from the pivot toward the target, y above the base).
nlohmann::ordered_json shot_series_json(const ShotSeries& series, const Engine& engine);

}  // namespace trebuchet
