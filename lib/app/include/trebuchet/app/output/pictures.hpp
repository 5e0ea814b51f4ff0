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
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/output/shot_series.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/uncertainty.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

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
