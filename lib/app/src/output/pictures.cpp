#include "trebuchet/app/output/pictures.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/angles.hpp"

namespace trebuchet {
namespace {

std::string gnuplot_number(double x) { return format_significant(x, 6); }

// The engine at one moment as gnuplot commands: frame, beam, counterweight arm and weight,
// sling and projectile, to scale in metres on the site (x toward the target, y above the base).
// With `angles`, the angles theta, psi and phi are drawn as arcs with their values.
std::string engine_commands(const Engine& engine, const TracePoint& p, bool projectile_on, bool labels, bool angles) {
  const Snapshot& s = p.snapshot;
  const double H = pivot_height(engine);
  const SitePoint pivot = site_point(s.pivot, engine), hinge = site_point(s.hinge, engine), cw = site_point(s.counterweight, engine),
                  tip = site_point(s.tip, engine), pr = site_point(s.projectile, engine);
  std::ostringstream g;
  auto segment = [&](SitePoint a, SitePoint b, const char* style) {
    g << "set arrow from " << gnuplot_number(a.x) << "," << gnuplot_number(a.y) << " to " << gnuplot_number(b.x) << "," << gnuplot_number(b.y)
      << " nohead " << style << "\n";
  };
  auto label = [&](const std::string& text, SitePoint at, const char* where) {
    g << "set label \"" << text << "\" at " << gnuplot_number(at.x) << "," << gnuplot_number(at.y) << " " << where << " font \",12\" front\n";
  };
  const double foot = 0.3 * H;
  if (engine.machine == MachineKind::floating_arm) {
    // The rail the axle rolls on, over the pivot's travel (from the guide to L2 behind it), on
    // two posts; the guide the counterweight falls in, from the base to above its start.
    const double back = -engine.L2 - 0.15 * H, front = 0.15 * H;
    segment({back, H}, {front, H}, "lw 3 lc rgb '#8b5a2b'");
    segment({back, 0}, {back, H}, "lw 3 lc rgb '#8b5a2b'");
    segment({front, 0}, {front, H}, "lw 3 lc rgb '#8b5a2b'");
    segment({0, 0}, {0, H + engine.L2}, "lw 2 dt 3 lc rgb '#8b5a2b'");
  } else {
    segment({-foot, 0}, pivot, "lw 3 lc rgb '#8b5a2b'");
    segment({foot, 0}, pivot, "lw 3 lc rgb '#8b5a2b'");
  }
  segment(hinge, tip, "lw 5 lc rgb '#a0522d'");
  segment(hinge, cw, engine.machine == MachineKind::fixed ? "lw 5 lc rgb '#a0522d'" : "lw 2 lc rgb 'black'");  // bolted on, or hung
  g << "set object circle at " << gnuplot_number(cw.x) << "," << gnuplot_number(cw.y) << " size " << gnuplot_number(0.12 * engine.L2 + 0.04 * H)
    << " fc rgb '#555555' fs solid front\n";
  g << "set object circle at " << gnuplot_number(pivot.x) << "," << gnuplot_number(H) << " size " << gnuplot_number(0.015 * H)
    << " fc rgb 'black' fs solid front\n";
  if (projectile_on) {
    segment(tip, pr, "lw 2 lc rgb '#1f5fbf' front");
    g << "set object circle at " << gnuplot_number(pr.x) << "," << gnuplot_number(pr.y) << " size " << gnuplot_number(0.03 * H)
      << " fc rgb '#d62728' fs solid front\n";
  }
  if (labels) {
    auto mid = [](SitePoint a, SitePoint b) { return SitePoint{(a.x + b.x) / 2, (a.y + b.y) / 2}; };
    // The whipper's rope and folded sling lie along its arm, up and forward: L1 and L4 stand below
    // the arm, L3 left of its rope.
    const bool whipper = engine.machine == MachineKind::whipper;
    label("L_1", mid(pivot, tip), whipper ? "offset 1.2,-0.8" : "offset -2.2,0.3");
    label("L_2", mid(pivot, hinge), "offset -2.2,0.6");
    if (engine.L3 > 0) label("L_3", mid(hinge, cw), whipper ? "offset -2.8,0.4" : "offset 1,0");
    if (projectile_on)
      label("L_4", whipper ? SitePoint{pr.x + 0.8 * (tip.x - pr.x), pr.y + 0.8 * (tip.y - pr.y)} : mid(tip, pr),
            whipper ? "offset 1.2,-0.8" : "offset 0,0.8 center");
    segment({pivot.x, 0}, pivot, "lw 1 dt 2 lc rgb 'gray40'");
    label("H", {pivot.x, H / 2}, "offset 0.5,0");
  }
  if (angles) {
    // Each angle from its reference line (dashed) to its part, as an arc; site angles in degrees
    // from +x, counterclockwise: the long arm points at 270 - theta, the counterweight's arm at
    // 270 - psi, the sling at -phi (dynamics.hpp's positions on the site).
    const double theta = degrees(p.state.theta), psi = degrees(p.state.psi), phi = degrees(p.state.phi);
    auto arc = [&](SitePoint at, double radius, double from, double to, SitePoint reference_end, const std::string& text, const char* colour) {
      segment(at, reference_end, (std::string("lw 1 dt 2 lc rgb '") + colour + "' front").c_str());
      g << "set object circle at " << gnuplot_number(at.x) << "," << gnuplot_number(at.y) << " size " << gnuplot_number(radius) << " arc ["
        << gnuplot_number(std::min(from, to)) << ":" << gnuplot_number(std::max(from, to)) << "] nowedge fs empty border lc rgb '" << colour
        << "' lw 2 front\n";
      const double middle = radians((from + to) / 2);
      label(text, {at.x + 1.35 * radius * std::cos(middle), at.y + 1.35 * radius * std::sin(middle)},
            (std::string("center tc rgb '") + colour + "'").c_str());
    };
    const double r = 0.22 * std::min(engine.L1, H);
    arc(pivot, r, 270 - theta, 270, {pivot.x, H - 1.3 * r}, "θ = " + format_significant(theta, 3) + "°", "#b22222");
    if (engine.machine == MachineKind::hinged)  // the others' counterweight has no angle of its own
      arc(hinge, 0.6 * engine.L3, 270 - psi, 270, {hinge.x, hinge.y - 0.8 * engine.L3}, "ψ = " + format_significant(psi, 3) + "°", "#1f7a1f");
    arc(tip, 0.35 * engine.L4, -phi, 0, {tip.x + 0.5 * engine.L4, tip.y}, "φ = " + format_significant(phi, 3) + "°", "#1f5fbf");
  }
  return g.str();
}

std::string header(const std::string& terminal_and_output) {
  return "# Made by trebuchet-verify shot --plot; run with gnuplot in this folder.\n"
         "set encoding utf8\nset datafile separator ','\n" +
      terminal_and_output + "\nset grid lc rgb '#dddddd'\nset key noenhanced\n";
}

// Text inside a gnuplot double-quoted string.
std::string gnuplot_quoted(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

// Where the model stops holding, in red across a picture's frame: "NOT PHYSICAL" large (or "NOT
// BUILDABLE", where the one warning is the counterweight's clearance), and each warning on an
// opaque box at the top of the frame (or, `at_foot`, at the foot of the picture, for pictures of
// several small frames), so that such a shot never looks like a normal one.
std::string warning_labels(const Verification& v, bool at_foot = false) {
  if (v.warnings.empty()) return "";
  const bool physical = v.warnings.size() == 1 && !v.clearance.buildable();
  // Large across a frame of its own; at the top of each of several small frames, clear of the engine.
  std::string g = "set style textbox opaque noborder\nset label 89 '" + std::string(physical ? "NOT BUILDABLE" : "NOT PHYSICAL") +
      "' at graph 0.5, graph " + std::string(at_foot ? "0.93" : "0.5") + " center tc rgb '#cc0000' font '," + std::string(at_foot ? "16" : "40") +
      "' front\n";
  for (std::size_t k = 0; k < v.warnings.size(); ++k)
    g += "set label " + std::to_string(90 + k) + " \"" + gnuplot_quoted(v.warnings[k]) + "\" at " +
        (at_foot ? "screen 0.01, screen " + gnuplot_number(0.012 + 0.03 * k) : "graph 0.01, graph " + gnuplot_number(0.96 - 0.06 * k)) +
        " left tc rgb '#cc0000' font ',10' noenhanced boxed front\n";
  return g;
}

// The shot that was computed, for every picture's title: air or vacuum, then the release and the
// target level as every report says them (describe_release).
std::string scene_of(const ShotSettings& settings) {
  const std::string air = settings.air
      ? "in air (Cd " + (settings.air->drag_coefficient ? format_significant(*settings.air->drag_coefficient, 3) : std::string("of Re")) +
          (settings.air->wind != 0 ? ", wind " + format_significant(settings.air->wind, 3) + " m/s" : std::string()) + ")"
      : std::string("in vacuum");
  return air + ", " + describe_release(settings);
}

// What every picture of one shot draws on: the engine, its series and its figures, the moments
// the pictures mark, the scale of its forces and energies, and the shot's words for the titles.
struct PictureShot {
  PictureShot(const Engine& engine, const ShotSettings& settings, const Verification& verification)
      : engine(engine),
        settings(settings),
        series(shot_series(engine, settings, verification)),
        H(pivot_height(engine)),
        mg_kN(engine.m * engine.material.g / 1000),
        Mg_kN(engine.M * engine.material.g / 1000),
        energy_kJ(engine.M * engine.material.g * engine.L2 / 1000),
        scaled(scaled_design(engine)),
        scene(scene_of(settings)),
        warnings(warning_labels(series.verification)) {
    moments.liftoff = series.liftoff, moments.peak_reaction = series.peak_reaction, moments.first_extreme = series.first_extreme,
    moments.second_extreme = series.second_extreme, moments.release = series.release;
  }
  double seconds(std::size_t i) const { return series.trace[i].t * series.time_unit; }
  const Engine& engine;
  const ShotSettings& settings;
  const ShotSeries series;
  const double H;  // the pivot's height [m]
  const double mg_kN, Mg_kN, energy_kJ;  // the projectile's and the counterweight's weights [kN], M g L2 [kJ]
  const ScaledDesign scaled;  // the engine in the paper's scaled units
  const std::string scene, warnings;  // the shot in words for the titles, and its warnings as labels
  const Verification& v = series.verification;
  const std::vector<TracePoint>& trace = series.trace;
  const std::vector<SitePoint>& flight = series.flight;
  const bool whipper = engine.machine == MachineKind::whipper;
  Moments moments;  // the samples the pictures mark

  // Each picture's files: the data, then a gnuplot script each, the pin's data and script, the
  // animation, and the page with the viewer.
  std::vector<PictureFile> data_files() const;
  PictureFile engine_script() const;
  PictureFile paths_script() const;
  PictureFile forces_script() const;
  PictureFile energy_script() const;
  PictureFile release_script() const;
  std::vector<PictureFile> pin_files() const;
  PictureFile animation_script() const;
  PictureFile page_html(const nlohmann::ordered_json& report, UnitSystem units) const;
};

// The data the scripts plot: every sample (shot.csv), the flight (flight.csv), and Q(t), eps(t), R(t)
// and the running extremes of eq:F, each over its value at the release (release.csv).
std::vector<PictureFile> PictureShot::data_files() const {
  std::vector<PictureFile> files;
  files.push_back({"shot.csv", trace_csv(trace, engine)});
  std::ostringstream flight_csv;
  flight_csv << "x_m,y_m\n";
  for (const SitePoint& p : flight) flight_csv << gnuplot_number(p.x) << "," << gnuplot_number(p.y) << "\n";
  files.push_back({"flight.csv", flight_csv.str()});
  std::ostringstream release_csv;
  release_csv << "t_s,Q_over_Q_release,eps_over_eps_release,R_over_R_release,FS_perp,FR,FRh_max,FRh_min\n";
  const ShotSeries::Moment& at = series.phase_two[series.release_row];
  for (const ShotSeries::Moment& row : series.phase_two) {
    release_csv << gnuplot_number(row.t) << "," << gnuplot_number(row.quality / at.quality) << "," << gnuplot_number(row.efficiency / at.efficiency)
                << "," << gnuplot_number(row.range / at.range);
    for (int k = 0; k < force_count; ++k) release_csv << "," << gnuplot_number(row.running_max[k] / series.final_extremes[k]);
    release_csv << "\n";
  }
  files.push_back({"release.csv", release_csv.str()});
  return files;
}

// 1. The engine at four moments, to scale, in one frame that holds all four with a margin. The
// whipper's projectile leaves its arm where the others' lift off their trough.
PictureFile PictureShot::engine_script() const {
  const std::pair<std::size_t, std::string> panels[] = {
      {moments.start, "at rest: θ_i = " + format_significant(engine.theta_i_deg, 3) + "°"},
      {moments.liftoff, (whipper ? "off the arm, t = " : "lift-off, t = ") + format_significant(seconds(moments.liftoff), 3) + " s"},
      {moments.peak_reaction, "largest pivot force, t_m = " + format_significant(seconds(moments.peak_reaction), 3) + " s"},
      {moments.release, "release, t_r = " + format_significant(seconds(moments.release), 3) + " s"}};
  double x_lo = -0.3 * H, x_hi = 0.3 * H, y_lo = 0, y_hi = H;
  for (const auto& [i, title] : panels) {
    const Snapshot& s = trace[i].snapshot;
    for (const Vec2& point : {s.hinge, s.counterweight, s.tip, s.projectile}) {
      const SitePoint p = site_point(point, engine);
      x_lo = std::min(x_lo, p.x), x_hi = std::max(x_hi, p.x), y_lo = std::min(y_lo, p.y), y_hi = std::max(y_hi, p.y);
    }
  }
  const double margin = 0.08 * std::max(x_hi - x_lo, y_hi - y_lo);
  std::ostringstream engine_gp;
  engine_gp << header("set terminal svg size 1100,950 dynamic font 'sans,12'\nset output 'engine.svg'") << "set size ratio -1\nset xrange ["
            << gnuplot_number(x_lo - margin) << ":" << gnuplot_number(x_hi + margin) << "]\nset yrange [" << gnuplot_number(y_lo - margin) << ":"
            << gnuplot_number(y_hi + margin) << "]\nset xlabel 'x toward the target [m]'\nset ylabel 'height above the base [m]'\n"
            << "set multiplot layout 2,2 title \"The " << machine_words(engine.machine) << " to scale: L1 = " << format_significant(engine.L1, 3)
            << " m, L2 = " << format_significant(engine.L2, 3) << " m, L3 = " << format_significant(engine.L3, 3)
            << " m, L4 = " << format_significant(engine.L4, 3) << " m, H = " << format_significant(H, 3) << " m; " << gnuplot_quoted(scene)
            << (engine.machine == MachineKind::hinged
                    ? "\\nθ: beam from the downward vertical, ψ: counterweight arm from the vertical, φ: sling from the horizontal"
                    : "\\nθ: beam from the downward vertical, φ: sling from the horizontal")
            << "\" noenhanced"
            << " margins 0.08,0.97,0.1,0.9 spacing 0.1,0.1\n";
  for (std::size_t k = 0; k < 4; ++k) {
    const TracePoint& p = trace[panels[k].first];
    engine_gp << "unset arrow\nunset label\nunset object\nset title '" << panels[k].second << "' noenhanced\n"
              << engine_commands(engine, p, true, k == 0, k == 2);
    engine_gp << warning_labels(v, true);
    engine_gp << "plot 0 lc rgb '#6b8e23' lw 2 notitle\n";
  }
  engine_gp << "unset multiplot\n";
  return {"engine.gp", engine_gp.str()};
}

// 2. The paths, then the flight to its end; on the right the engine's part enlarged.
PictureFile PictureShot::paths_script() const {
  std::ostringstream paths;
  const SitePoint impact = flight.back();
  const double from_x = settings.range_from_release ? v.x : 0;  // R runs from the pivot, or from the release point (Denny's)
  const double arrow_y = impact.y - 0.02 * v.capacity.R;
  const std::string flight_title = settings.air ? "flight (air)" : "flight (vacuum)";
  const std::string curves =
      "'shot.csv' every ::1 using (strcol(1) ne 'III' ? $17 : NaN):18 with lines lw 2 title 'counterweight', \\\n"
      "     '' every ::1 using (strcol(1) ne 'III' ? $19 : NaN):20 with lines lw 2 title 'beam tip', \\\n"
      "     '' every ::1 using 21:22 with lines lw 2 title 'projectile, phases I-II', \\\n"
      "     'flight.csv' every ::1 using 1:2 with lines lw 2 dt 2 title '" +
      flight_title +
      "', \\\n"
      "     " +
      gnuplot_number(impact.y) + " with lines lc rgb 'gray40' title '" + (settings.range_from_release ? "release height" : "target level") + "'\n";
  paths << header("set terminal svg size 1200,540 dynamic font 'sans,12'\nset output 'paths.svg'")
        << "set xlabel 'x toward the target [m]'\nset ylabel 'height above the base [m]'\nset key below\n"
        << warnings << "set multiplot title \"" << gnuplot_quoted(scene)
        << "\" noenhanced\nset size 0.62,0.95\nset origin 0,0\nset title 'The whole shot' noenhanced\n"
        << "set arrow 1 from " << gnuplot_number(from_x) << "," << gnuplot_number(arrow_y) << " to " << gnuplot_number(impact.x) << ","
        << gnuplot_number(arrow_y) << " heads lc rgb 'black'\n"
        << "set label 1 'R = " << format_significant(v.capacity.R, 4) << " m" << (settings.range_from_release ? " (from the release point)" : "")
        << "' at " << gnuplot_number((from_x + impact.x) / 2) << "," << gnuplot_number(arrow_y) << " offset 0,-1 center\n"
        << "set yrange [" << gnuplot_number(std::min(0.0, impact.y) - 0.06 * v.capacity.R) << ":*]\nplot " << curves
        << "unset arrow 1\nunset label 1\nset size 0.38,0.95\nset origin 0.62,0\nset size ratio -1\nset key off\n"
        << "set title 'Phases I and II, enlarged' noenhanced\nset xrange [" << gnuplot_number(-engine.L1 - engine.L4 - 0.5) << ":"
        << gnuplot_number(std::max(engine.L1 + engine.L4, engine.L2 + engine.L3) + 0.5)
        << "]\nset yrange [-0.5:" << gnuplot_number(H + engine.L1 + engine.L4 + 0.5) << "]\nplot " << curves << "unset multiplot\n";
  return {"paths.gp", paths.str()};
}

// 3. The forces against time, in kN, with multiples of M g on the right; the marks' names
// stand above the frame, in two rows, clear of the curves and of each other.
PictureFile PictureShot::forces_script() const {
  auto marks = [&](std::ostringstream& gp) {
    const std::pair<std::size_t, const char*> at[] = {{moments.liftoff, whipper ? "off the arm" : "lift-off"},
                                                      {moments.first_extreme, "t_1"},
                                                      {moments.peak_reaction, "t_m"},
                                                      {moments.second_extreme, "t_2"},
                                                      {moments.release, "release"}};
    int row = 0;
    for (const auto& [i, name] : at)
      gp << "set arrow from " << gnuplot_number(seconds(i)) << ", graph 0 to " << gnuplot_number(seconds(i))
         << ", graph 1 nohead dt 3 lc rgb 'gray50'\n"
         << "set label '" << name << "' at " << gnuplot_number(seconds(i)) << ", graph " << (row++ % 2 ? "1.08" : "1.03")
         << " center tc rgb 'gray30' noenhanced\n";
  };
  std::ostringstream forces;
  forces << header("set terminal svg size 1100,540 dynamic font 'sans,12'\nset output 'forces.svg'")
         << "set xlabel 'time [s]'\nset ylabel 'force [kN]'\nset y2label \"force as a multiple of M·g (M = "
         << gnuplot_quoted(quantity_text(engine.M, UnitDimension::mass, UnitSystem::si, 3))
         << ", the counterweight)\" noenhanced\nset y2tics\nset link y2 via y/" << gnuplot_number(Mg_kN) << " inverse y*" << gnuplot_number(Mg_kN)
         << "\nset format y2 '%.1f'\nset key below\nset tmargin 6\nset xrange [0:" << gnuplot_number(seconds(moments.release) * 1.02) << "]\n"
         << "set title \"Forces up to the release: t_1 and t_2 the extremes of F_Rh, t_m the largest pivot force\\n"
         << gnuplot_quoted(scene) << "\" noenhanced\n"
         << warnings;
  marks(forces);
  forces << "plot 'shot.csv' every ::1 using (strcol(1) ne 'III' ? $2 : NaN):($9*" << gnuplot_number(mg_kN)
         << ") with lines lw 2 title 'F_S⊥ (sling, across the beam)', \\\n"
         << "     '' every ::1 using (strcol(1) ne 'III' ? $2 : NaN):($27*" << gnuplot_number(mg_kN)
         << ") with lines lw 2 dt 4 title 'sling tension', \\\n"
         << "     '' every ::1 using (strcol(1) ne 'III' ? $2 : NaN):($10*" << gnuplot_number(Mg_kN)
         << ") with lines lw 2 title '|F_R| (pivot)', \\\n"
         << "     '' every ::1 using (strcol(1) ne 'III' ? $2 : NaN):($11*" << gnuplot_number(Mg_kN)
         << ") with lines lw 2 title 'F_Rh (pivot, horizontal)', \\\n"
         << "     '' every ::1 using (strcol(1) ne 'III' ? $2 : NaN):($13*" << gnuplot_number(Mg_kN)
         << ") with lines lw 2 title '|F_H| (hinge)', \\\n"
         << "     '' every ::1 using (strcol(1) eq 'I' ? $2 : NaN):($14*" << gnuplot_number(mg_kN)
         << ") with lines lw 2 title 'N (trough on the projectile)'\n";
  return {"forces.gp", forces.str()};
}

// 4. Where the energy goes: each body's energy over its value at rest, against Delta U; the
// projectile keeps what it took at the release.
PictureFile PictureShot::energy_script() const {
  std::ostringstream energy;
  const Snapshot& at_release = trace[moments.release].snapshot;
  const double drop_kJ = scaled.energy_drop() * energy_kJ;
  const Snapshot& rest = trace.front().snapshot;
  const double cw0 = rest.energies.counterweight * energy_kJ, beam0 = rest.energies.beam * energy_kJ,
               pr0 = rest.energies.projectile_potential * energy_kJ;
  const double taken_kJ = (at_release.energies.projectile_kinetic + at_release.energies.projectile_potential) * energy_kJ - pr0;
  // An engine as built loses energy to friction and drag: the work they took (the series' last
  // five columns, 29 to 33) is drawn, and the total includes it.
  const bool losses = scaled.parts.dissipates();
  const std::string lost_kJ = "(($29+$30+$31+$32+$33)/1000)";
  energy << header("set terminal svg size 1100,540 dynamic font 'sans,12'\nset output 'energy.svg'")
         << "set xlabel 'time [s]'\nset ylabel 'energy gained since rest [kJ]'\nset key below\n"
         << warnings << "set title \"Where the energy goes\\nat the release the projectile holds ε = " << format_significant(100 * v.eps, 3)
         << (losses ? " % of ΔU; the gap, 1 − ε, stays in beam and counterweight or went to friction and drag\\n"
                    : " % of ΔU; the gap, 1 − ε, stays in beam and counterweight\\n")
         << (v.energy.flight_drag > 0
                 ? "after the release the air takes " + format_significant(v.energy.flight_drag / 1000, 3) + " kJ more in flight\\n"
                 : v.energy.flight_drag < 0
                 ? "after the release the wind gives " + format_significant(-v.energy.flight_drag / 1000, 3) + " kJ more in flight\\n"
                 : "")
         << gnuplot_quoted(scene) << "\" noenhanced\n"
         << "set arrow from " << gnuplot_number(seconds(moments.release)) << ", graph 0 to " << gnuplot_number(seconds(moments.release))
         << ", graph 1 nohead dt 3 lc rgb 'gray50'\n"
         << "set arrow from " << gnuplot_number(seconds(moments.release)) << "," << gnuplot_number(taken_kJ) << " to "
         << gnuplot_number(seconds(moments.release)) << "," << gnuplot_number(drop_kJ) << " heads lw 2 lc rgb 'red' front\nset label '1 − ε' at "
         << gnuplot_number(seconds(moments.release)) << "," << gnuplot_number((taken_kJ + drop_kJ) / 2)
         << " offset 0.5,0 tc rgb 'red' noenhanced\nset label 'release' at " << gnuplot_number(seconds(moments.release))
         << ", graph 0.5 rotate by 90 center offset -0.8,0\n"
         << "plot 'shot.csv' every ::1 using 2:($23/1000-(" << gnuplot_number(cw0) << ")) with lines lw 2 title 'counterweight', \\\n"
         << "     '' every ::1 using 2:($24/1000-(" << gnuplot_number(beam0) << ")) with lines lw 2 title 'beam', \\\n"
         << "     '' every ::1 using 2:(strcol(1) ne 'III' ? ($25+$26)/1000-(" << gnuplot_number(pr0) << ") : " << gnuplot_number(taken_kJ)
         << ") with lines lw 2 title 'projectile (after the release: what it took)', \\\n"
         << "     '' every ::1 using (strcol(1) ne 'III' ? $2 : NaN):($25/1000) with lines lw 1 dt 2 title 'of which kinetic', \\\n"
         << (losses ? "     '' every ::1 using 2:" + lost_kJ + " with lines lw 2 lc rgb '#e377c2' title 'taken by friction and drag', \\\n" : "")
         << "     '' every ::1 using 2:(($23+$24)/1000-(" << gnuplot_number(cw0 + beam0) << ")+(strcol(1) ne 'III' ? ($25+$26)/1000-("
         << gnuplot_number(pr0) << ") : " << gnuplot_number(taken_kJ) << ")" << (losses ? "+" + lost_kJ : "")
         << ") with lines lw 2 lc rgb 'black' title '" << (losses ? "total with what the losses took (conserved)" : "total (conserved)") << "', \\\n"
         << "     " << gnuplot_number(drop_kJ) << " with lines dt 2 lc rgb 'gray30' title 'ΔU (eq:DU)'\n";
  return {"energy.gp", energy.str()};
}

// 5. Why the release is where it is.
PictureFile PictureShot::release_script() const {
  const std::string objective = settings.criterion.release == Release::quality ? "Q" : settings.criterion.release == Release::efficiency ? "ε" : "R";
  std::ostringstream release;
  release << header("set terminal svg size 1100,540 dynamic font 'sans,12'\nset output 'release.svg'")
          << "set xlabel 'time [s]'\nset ylabel 'value over its value at the release'\nset key below\nset yrange [0:1.3]\n"
          << warnings << "set label 'release' at " << gnuplot_number(seconds(moments.release)) << ", graph 0.95 offset 0.3,0\n"
          << "set title \"Phase II, and on as if the projectile were kept: "
          << (settings.release_at ? "this shot is released as given" : objective + " peaks at the release")
          << "; the running extremes of eq:F switch on as they grow\\n"
          << gnuplot_quoted(scene) << "; Q, ε and R here at level 0 in vacuum\" noenhanced\n"
          << "set arrow from " << gnuplot_number(seconds(moments.release)) << ", graph 0 to " << gnuplot_number(seconds(moments.release))
          << ", graph 1 nohead dt 3 lc rgb 'gray50'\n"
          << "plot 'release.csv' every ::1 using 1:2 with lines lw 3 lc rgb 'black' title 'Q', \\\n"
          << "     '' every ::1 using 1:3 with lines lw 2 title 'ε', '' every ::1 using 1:4 with lines lw 2 title 'R', \\\n"
          << "     '' every ::1 using 1:5 with lines lw 2 dt 2 title 'max F_S⊥ so far', '' every ::1 using 1:6 with lines lw 2 dt 2 title 'max |F_R| "
             "so far', \\\n"
          << "     '' every ::1 using 1:7 with lines lw 2 dt 2 title 'max F_Rh so far', '' every ::1 using 1:8 with lines lw 2 dt 2 title 'max −F_Rh "
             "so far'\n";
  return {"release.gp", release.str()};
}

// 6. The pin: R and Q of the releases at pin angles 20 deg either side of this shot's (the
// series' pin scan), each over its value here; a builder reads how exactly the pin must be bent.
std::vector<PictureFile> PictureShot::pin_files() const {
  std::vector<PictureFile> files;
  std::ostringstream pin_csv;
  pin_csv << "pin_angle_deg,R_m,Q\n";
  for (const PinShot& shot : series.pins)
    pin_csv << gnuplot_number(shot.pin_angle_deg) << "," << (shot.R ? gnuplot_number(*shot.R) : "NaN") << ","
            << (shot.Q ? gnuplot_number(*shot.Q) : "NaN") << "\n";
  files.push_back({"pin.csv", pin_csv.str()});
  std::ostringstream pin;
  pin << header("set terminal svg size 1100,540 dynamic font 'sans,12'\nset output 'pin.svg'")
      << "set xlabel 'pin angle between the long arm and the sling at the release [deg]'\nset ylabel 'R [m]'\nset y2label 'Q [%]'\n"
      << "set ytics nomirror\nset y2tics\nset key below\n"
      << warnings << "set title \"The pin: a release at each pin angle; this shot's, " << format_significant(v.pin_to_bend_deg, 4)
      << "°, is marked\\n"
      << gnuplot_quoted(scene) << "\" noenhanced\n"
      << "set arrow from " << gnuplot_number(v.pin_to_bend_deg) << ", graph 0 to " << gnuplot_number(v.pin_to_bend_deg)
      << ", graph 1 nohead dt 3 lc rgb 'gray50'\n"
      << "set label 'this shot' at " << gnuplot_number(v.pin_to_bend_deg) << ", graph 0.05 offset 0.3,0\n";
  // Where no other pin releases this engine forward (every one passes in the trough, or throws
  // back), the chart says so: gnuplot refuses a plot of no points.
  const auto released = std::count_if(series.pins.begin(), series.pins.end(), [](const PinShot& s) { return s.R.has_value(); });
  if (released < 2)
    pin << "set label 'no pin angle near this one releases the projectile forward within the beam''s forward swing' at graph 0.5, graph 0.5 center\n"
        << "plot [" << gnuplot_number(v.pin_to_bend_deg - 20) << ":" << gnuplot_number(v.pin_to_bend_deg + 20) << "] [0:1] 2 notitle\n";
  else
    pin << "plot 'pin.csv' every ::1 using 1:2 with linespoints lw 2 pt 7 ps 0.5 title 'R' axes x1y1, \\\n"
        << "     '' every ::1 using 1:($3*100) with linespoints lw 2 pt 7 ps 0.5 title 'Q' axes x1y2\n";
  files.push_back({"pin.gp", pin.str()});
  return files;
}

// 7. The animation: one frame every second sample of the engine, played at 4 % of real speed
// or slower, the stone flying on after the release; then the whole flight to its end, zoomed
// out, at about real speed.
PictureFile PictureShot::animation_script() const {
  const SitePoint impact = flight.back();
  const std::size_t stride = 2;
  const double frame_s = stride * (trace.size() > 1 ? seconds(1) - seconds(0) : 0.01);
  const int delay = 8;  // [1/100 s] per frame
  const double slowed = delay / 100.0 / frame_s;
  const double t_release = seconds(moments.release);
  std::ostringstream anim;
  anim << "# Made by trebuchet-verify shot --plot; run with gnuplot in this folder.\n"
       << "set encoding utf8\nset datafile separator ','\nset terminal gif animate delay " << delay
       << " size 800,600 font 'sans,11'\nset output 'shot.gif'\nset size ratio -1\n"
       << "set xrange [" << gnuplot_number(-engine.L1 - engine.L4 - 1) << ":"
       << gnuplot_number(std::max(engine.L1 + engine.L4, engine.L2 + engine.L3) + 1) << "]\n"
       << "set yrange [" << gnuplot_number(std::min(-0.5, H - engine.L2 - engine.L3 - 0.5)) << ":" << gnuplot_number(H + engine.L1 + engine.L4 + 0.5)
       << "]\nset xlabel 'x toward the target [m]'\nset ylabel 'height [m]'\nset bmargin 5\n";
  auto stone = [&](SitePoint at, double size) {
    anim << "set object circle at " << gnuplot_number(at.x) << "," << gnuplot_number(at.y) << " size " << gnuplot_number(size)
         << " fc rgb '#d62728' fs solid front\n";
  };
  for (std::size_t i = 0; i < trace.size(); i += stride) {
    const bool on = trace[i].phase != Phase::released;
    anim << "unset arrow\nunset label\nunset object\n" << engine_commands(engine, trace[i], on, false, false) << warning_labels(v, true);
    if (!on) stone(series.stone_at(seconds(i) - t_release), 0.03 * H);
    anim << "set title 't = " << format_significant(seconds(i), 3) << " s  ("
         << (on ? std::string("phase ") + phase_numeral(trace[i].phase) : std::string("released")) << ", slowed " << format_significant(slowed, 2)
         << " times)' noenhanced\nplot 0 lc rgb '#6b8e23' lw 2 notitle\n";
  }
  const double flight_lo = std::min(-engine.L1 - engine.L4, impact.x) - 2, flight_hi = std::max(impact.x, engine.L1) + 2;
  double top = H + engine.L1;
  for (const SitePoint& p : flight) top = std::max(top, p.y);
  anim << "unset arrow\nunset label\nunset object\nset xrange [" << gnuplot_number(flight_lo) << ":" << gnuplot_number(flight_hi) << "]\nset yrange ["
       << gnuplot_number(std::min(0.0, impact.y) - 2) << ":" << gnuplot_number(top + 2) << "]\nset size noratio\n";
  const int flight_frames = 60;
  const double flight_step = series.flight_time / flight_frames;
  for (int k = 0; k <= flight_frames; ++k) {
    const double after = k * flight_step;
    anim << "unset object\nunset label\n" << warning_labels(v, true);
    stone(series.stone_at(after), 0.008 * (flight_hi - flight_lo));
    anim << "set title 'the flight: " << format_significant(after, 3) << " s after the release (" << (settings.air ? "air" : "vacuum") << ", "
         << format_significant(delay / 100.0 / flight_step, 2) << " × real speed)' noenhanced\n"
         << "plot 'flight.csv' every ::1 using 1:2 with lines lc rgb '#bbbbbb' dt 2 notitle, 0 lc rgb '#6b8e23' lw 2 notitle, "
         << gnuplot_number(impact.y) << " lc rgb 'gray40' notitle\n";
  }
  return {"animation.gp", anim.str()};
}

// 7. The page: the browser page's viewer (web/viewer.js) with this shot inside, and the
// pictures above for print.
PictureFile PictureShot::page_html(const nlohmann::ordered_json& report, UnitSystem units) const {
  nlohmann::ordered_json shot = report;
  shot["series"] = shot_series_json(series, engine);
  std::string data = shot.dump();
  for (std::size_t at = data.find("</"); at != std::string::npos; at = data.find("</", at + 3)) data.replace(at, 2, "<\\/");  // JSON's own escape
  std::ostringstream html;
  auto escaped = [](const std::string& text) {
    std::string out;
    for (char c : text) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
    return out;
  };
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
       << "<title>trebuchet shot</title>\n<style>\n"
       << viewer_style() << "main { display: block; }\n</style></head><body>\n"
       << "<header><h1>One shot of a swinging-counterweight trebuchet</h1><p class=\"tagline\">Made by <code>trebuchet-verify shot --plot</code>: "
          "the model of "
       << "Horsdal, appendix A. " << escaped(describe_assumptions(engine, settings))
       << ".</p></header>\n<main><section id=\"shot\"><div id=\"viewer\"></div>\n"
       << "<h2>Pictures for print</h2><ul>\n";
  const std::pair<const char*, const char*> pictures[] = {
      {"engine.svg", "the engine to scale at rest, at lift-off, at the largest pivot force and at the release, with θ, ψ and φ"},
      {"shot.gif", "the shot slowed down, then the whole flight"},
      {"paths.svg", "the paths and the flight"},
      {"forces.svg", "the forces up to the release"},
      {"energy.svg", "where the energy goes"},
      {"release.svg", "why the release is where it is"},
      {"pin.svg", "R and Q against the pin angle"}};
  for (const auto& [file, what] : pictures) html << "<li><a href=\"" << file << "\">" << file << "</a>: " << what << "</li>\n";
  html << "</ul><p>The data: <a href=\"shot.csv\">shot.csv</a> (every sample), <a href=\"release.csv\">release.csv</a>, <a "
          "href=\"flight.csv\">flight.csv</a>. "
          "docs/pictures.md explains each picture.</p></section></main>\n"
       << "<script type=\"application/json\" id=\"shot-data\">" << data << "</script>\n<script>\n"
       << viewer_script() << "\n</script>\n"
       << "<script>TrebuchetViewer.render(document.getElementById('viewer'), JSON.parse(document.getElementById('shot-data').textContent), {units: '"
       << (units == UnitSystem::imperial ? "imperial" : "si") << "'});</script>\n</body></html>\n";
  return {"index.html", html.str()};
}

}  // namespace

std::vector<std::string> picture_scripts() { return {"engine.gp", "paths.gp", "forces.gp", "energy.gp", "release.gp", "pin.gp", "animation.gp"}; }

std::vector<PictureFile> shot_pictures(const Engine& engine, const ShotSettings& settings, const Verification& verification,
                                       const nlohmann::ordered_json& report, UnitSystem units) {
  const PictureShot shot(engine, settings, verification);
  std::vector<PictureFile> files = shot.data_files();
  for (const auto script : {&PictureShot::engine_script, &PictureShot::paths_script, &PictureShot::forces_script, &PictureShot::energy_script,
                            &PictureShot::release_script})
    files.push_back((shot.*script)());
  for (PictureFile& file : shot.pin_files()) files.push_back(std::move(file));
  files.push_back(shot.animation_script());
  files.push_back(shot.page_html(report, units));
  return files;
}

std::vector<PictureFile> histogram_pictures(const MonteCarloSummary& summary, const std::string& title) {
  std::ostringstream data;
  data << "# R [m], T [kJ] of each sample that worked\n";
  for (const auto& v : summary.values) data << format_significant(v[0], 8) << " " << format_significant(v[1] / 1e3, 8) << "\n";
  std::ostringstream gp;
  const int bins = 40;
  auto panel = [&](int column, const char* label, double scale, std::size_t index) {
    const auto& p = summary.percentiles[index];
    const double lo = p[0] / scale, hi = p[2] / scale, median = p[1] / scale;
    // Bins over the central 90 % widened by half on each side; the rest is drawn at the edges.
    const double from = lo - (hi - lo) / 2, to = hi + (hi - lo) / 2, width = std::max((to - from) / bins, 1e-12);
    gp << "set xlabel '" << label << "'\nset xrange [" << from << ":" << to << "]\n"
       << "set arrow 1 from " << lo << ", graph 0 to " << lo << ", graph 1 nohead dt 2 lc rgb '#555555'\n"
       << "set arrow 2 from " << median << ", graph 0 to " << median << ", graph 1 nohead lw 2 lc rgb '#b22222'\n"
       << "set arrow 3 from " << hi << ", graph 0 to " << hi << ", graph 1 nohead dt 2 lc rgb '#555555'\n"
       << "set label 1 '5 %' at " << lo << ", graph 1.03 center\nset label 2 '50 %' at " << median << ", graph 1.03 center\n"
       << "set label 3 '95 %' at " << hi << ", graph 1.03 center\n"
       << "bin(x) = " << from << " + " << width << " * (floor((x - " << from << ") / " << width << ") + 0.5)\n"
       << "clamp(x) = x < " << from << " ? " << from + width / 2 << " : (x > " << to << " ? " << to - width / 2 << " : x)\n"
       << "plot 'histogram.dat' using (bin(clamp($" << column << "))):(1) smooth frequency with boxes fs solid 0.5 lc rgb '#4682b4' notitle\n";
  };
  gp << "set terminal svg size 1100,450 dynamic font 'sans,12'\nset output 'histogram.svg'\n"
     << "set multiplot layout 1,2 title \"" << title << "\\n"
     << summary.values.size() << " of " << summary.samples << " samples worked; dashed: 5 and 95 %, red: the median\"\n"
     << "set ylabel 'samples'\nset yrange [0:*]\nset tmargin 5\nset boxwidth 1 relative\nset grid ytics\n";
  panel(1, "range R [m]", 1, 0);
  panel(2, "energy at the target T [kJ]", 1e3, 1);
  gp << "unset multiplot\n";
  return {{"histogram.dat", data.str()}, {"histogram.gp", gp.str()}};
}

}  // namespace trebuchet
