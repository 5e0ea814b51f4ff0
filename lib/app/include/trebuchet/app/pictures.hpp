// Pictures of one shot for a class or a report (issue 13): the engine drawn to scale, the
// paths, the forces, the energies, the release and an animation, as gnuplot scripts with their
// data, and an index.html that gathers them; write_picture_folder writes them and runs gnuplot.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "trebuchet/engine.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/app/report.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// A shot as the pictures and the viewer (web/viewer.js) show it: its figures, its motion sampled
/// about 200 times up to the release and on to the ground after it, its flight to the end
/// (the target level, or back at the release height for Denny's range) through the settings' air
/// or vacuum, and Q, eps and R over phase II, on past the release as if the projectile were kept.
struct ShotSeries {
  Verification verification;
  std::vector<TracePoint> trace;    ///< phases I and II up to the release, then phase III (shot.hpp)
  double time_unit = 1;             ///< sqrt(L2/g), the scaled time's unit (section 3) [s]
  std::size_t liftoff = 0, peak_reaction = 0, first_extreme = 0, second_extreme = 0, release = 0;  ///< indices into trace
  std::vector<SitePoint> flight;    ///< the projectile from the release to the end of its flight [m]
  double flight_time = 0;           ///< [s]
  /// A moment of phase II taken as a release (shot.hpp's release_point): Q is the Q_n the shot
  /// maximised, R the range at level 0 in vacuum; the extremes of eq:F so far.
  struct Moment {
    double t;  ///< [s]
    double quality, efficiency, range;  ///< scaled, as release_point gives them
    ForceValues running_max;
  };
  std::vector<Moment> phase_two;
  std::size_t release_row = 0;      ///< the release, in phase_two
  ForceValues final_extremes{};     ///< eq:F's extremes up to the release, scaled
  /// The projectile `after` seconds past the release (at the flight's end once it has landed).
  SitePoint stone_at(double after) const;
};
/// `verification` is the shot of `engine` under `settings` (verify_engine), which the caller has.
ShotSeries shot_series(const Engine& engine, const ShotSettings& settings, const Verification& verification);

/// The series as the viewer reads it: every value in SI units (s, m, N, J, N m), angles in
/// degrees, positions on the site (x from the pivot toward the target, y above the base).
nlohmann::ordered_json shot_series_json(const ShotSeries& series, const Engine& engine);

/// One file of the picture set: its name in the folder, and its text.
struct PictureFile {
  std::string name;
  std::string text;
};

/// The picture set of a shot of `engine` under `settings` (`verification`, its figures): it simulates the shot, sampled about
/// 200 times up to the release, and phase II past the release for the release picture. The
/// gnuplot scripts (*.gp) write engine.svg, paths.svg, forces.svg, energy.svg, release.svg and
/// shot.gif in the folder they are run in. index.html is the browser page's viewer with the
/// shot inside: `report` (the program's JSON of it) and its series, in `units`.
std::vector<PictureFile> shot_pictures(const Engine& engine, const ShotSettings& settings, const Verification& verification,
                                       const nlohmann::ordered_json& report, UnitSystem units = UnitSystem::si);

/// The viewer's script and style (web/viewer.js, web/style.css), compiled in.
std::string_view viewer_script();
std::string_view viewer_style();

/// The gnuplot scripts of the set, in the order to run them.
std::vector<std::string> picture_scripts();

/// The histograms of a Monte Carlo run (uncertainty.hpp): R and T of the samples that worked,
/// with their 5, 50 and 95 % percentiles marked; `title` says what was uncertain and how the
/// shots flew (gnuplot text: a backslash and n between lines, no double quotes). The script
/// histogram.gp writes histogram.svg.
std::vector<PictureFile> histogram_pictures(const MonteCarloSummary& summary, const std::string& title);

/// Writes `files` into the folder `dir` (made if missing), then runs gnuplot on each of
/// `scripts` there; gnuplot's own messages go to gnuplot.log in the folder. Throws Error(usage)
/// naming what failed and the fix (a folder that cannot be written, gnuplot missing or failing).
/// Nothing is moved into the folder when one of its files would replace one of `inputs`.
void write_picture_folder(const std::string& dir, const std::vector<PictureFile>& files, const std::vector<std::string>& scripts,
                          const std::vector<std::string>& inputs = {});

}  // namespace trebuchet
