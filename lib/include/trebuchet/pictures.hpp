// Pictures of one shot for a class or a report (issue 13): the engine drawn to scale, the
// paths, the forces, the energies, the release and an animation, as gnuplot scripts with their
// data, and an index.html that gathers them. The library writes the text; a program runs gnuplot.
#pragma once

#include <string>
#include <vector>

#include "trebuchet/engine.hpp"
#include "trebuchet/shot.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// One file of the picture set: its name in the folder, and its text.
struct PictureFile {
  std::string name;
  std::string text;
};

/// The picture set of a shot. `trace` is the motion sampled every `trace_dt_s` seconds
/// (verify_engine with a trace), `v` its verification, `target_level` the one it was shot at [m].
/// The gnuplot scripts (*.gp) write engine.svg, paths.svg, forces.svg, energy.svg,
/// release.svg and shot.gif in the folder they are run in.
std::vector<PictureFile> shot_pictures(const Engine& engine, const Verification& v, const std::vector<TracePoint>& trace,
                                       double target_level);

/// The gnuplot scripts of the set, in the order to run them.
std::vector<std::string> picture_scripts();

/// The sampling interval [s] the pictures want for a shot released at t_release_s: about 200
/// points up to the release.
double picture_sampling(double t_release_s);

}  // namespace trebuchet
