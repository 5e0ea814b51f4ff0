#include "trebuchet/app/output/shot_series.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "trebuchet/air.hpp"
#include "trebuchet/angles.hpp"
#include "trebuchet/error.hpp"

namespace trebuchet {
namespace {

Moments moments_of(const std::vector<TracePoint>& trace) {
  Moments m;
  double largest = -1, most = -1e300, least = 1e300;
  std::size_t most_at = 0, least_at = 0;
  for (std::size_t i = 0; i < trace.size() && trace[i].phase != Phase::released; ++i) {
    const Snapshot& s = trace[i].snapshot;
    if (trace[i].phase == Phase::trough) m.liftoff = i;  // the whipper's projectile leaves the arm there
    m.release = i;
    const double reaction = force_values(s)[pivot_reaction];
    if (reaction > largest) largest = reaction, m.peak_reaction = i;
    const double horizontal = force_values(s)[pivot_horizontal];  // the frame's (the floating arm's at its guide)
    if (horizontal > most) most = horizontal, most_at = i;
    if (horizontal < least) least = horizontal, least_at = i;
  }
  m.first_extreme = std::min(most_at, least_at), m.second_extreme = std::max(most_at, least_at);
  return m;
}

}  // namespace

ShotSeries shot_series(const Engine& engine, const ShotSettings& settings, const Verification& verification) {
  ShotSeries series;
  const ShotSettings as_shot = settings_for(engine, settings);  // as verify_engine shoots it (a ball of given size in air)
  const ScaledDesign d = shot_design(engine, as_shot);
  const double g = engine.material.g;
  const double time_unit = std::sqrt(engine.L2 / g);  // section 3 [s]
  series.time_unit = time_unit;
  const Verification& v = series.verification = verification;
  std::vector<TracePoint>& trace = series.trace;
  std::vector<TracePoint> unreleased;
  // The chart of the pin: the releases at pins bent 20 deg either side of its own, every 2 deg, read off this shot.
  PinScan pins(engine, settings, [](double own_deg) {
    std::vector<double> out;
    for (int k = -10; k <= 10; ++k) out.push_back(own_deg + 2 * k);
    return out;
  });
  pins.read(simulate_shot(d, release_criterion(engine, as_shot), settings.integrator, &trace, v.t_release / time_unit / 200, &unreleased, false,
                          pins.releases()));
  series.pins = pins.shots();
  const Moments m = moments_of(trace);
  series.liftoff = m.liftoff, series.peak_reaction = m.peak_reaction, series.first_extreme = m.first_extreme,
  series.second_extreme = m.second_extreme, series.release = m.release;

  // The flight the shot computed, from the release to its end (the target level, or back at the
  // release height for Denny's range), in vacuum or through the settings' air.
  const double A = radians(v.A_deg);
  const Drag drag = as_shot.air ? drag_of(*as_shot.air, engine.m) : Drag{};
  const double flight_drop = settings.range_from_release ? 0 : v.h - settings.target_level;
  std::vector<Vec2> path;  // in the frame of the shot (target toward -x), height from the release [m]
  const auto end = fly({-v.x, 0}, {-v.v * std::cos(A), v.v * std::sin(A)}, flight_drop, drag, g, &path, 201);
  if (!end)
    throw Error(ErrorKind::numerical,
                "the flight drawn did not come down where the shot's did (an internal error; please report it with the command)");
  for (const Vec2& p : path) series.flight.push_back({-p.x, v.h + p.y});
  series.flight_time = end->time;

  // Q(t), eps(t), R(t) over phase II, and the running extremes of eq:F.
  ForceExtremes running;
  for (std::size_t i = 0; i <= m.release; ++i) running.add(force_values(trace[i].snapshot));
  series.final_extremes = running.max;
  running = ForceExtremes{};
  std::vector<TracePoint> phase_two(trace.begin(), trace.begin() + m.release + 1);
  phase_two.insert(phase_two.end(), unreleased.begin(), unreleased.end());
  // Each moment as a release (shot.hpp), so that Q is the Q_n the shot maximised and R the
  // range at level 0.
  for (std::size_t i = 0; i < phase_two.size(); ++i) {
    const TracePoint& p = phase_two[i];
    const ForceExtremes before = running;
    running.add(force_values(p.snapshot));
    if (p.phase != Phase::lifted) continue;
    const ReleasePoint r = release_point(d, settings.criterion, p.t, p.state, p.snapshot, before);
    if (!(r.range > 0)) continue;
    if (i == m.release) series.release_row = series.phase_two.size();
    series.phase_two.push_back({p.t * time_unit, r.quality, r.efficiency, r.range, running.max});
  }
  return series;
}

SitePoint ShotSeries::stone_at(double after) const {
  const double k = std::clamp(after / flight_time, 0.0, 1.0) * static_cast<double>(flight.size() - 1);
  const std::size_t i = std::min(static_cast<std::size_t>(k), flight.size() - 2);
  const double f = k - static_cast<double>(i);
  return SitePoint{flight[i].x + f * (flight[i + 1].x - flight[i].x), flight[i].y + f * (flight[i + 1].y - flight[i].y)};
}

namespace {

using json = nlohmann::ordered_json;

// The motion as columns of SI values, a row per sample; after the release the sling and
// projectile are gone: their values are null.
json frames_json(const ShotSeries& series, const Engine& engine) {
  const double Mg = engine.M * engine.material.g;  // [N]: the scaled forces' unit
  const double energy_unit = Mg * engine.L2;  // [J], and the beam moment's [N m]
  json frames = json::object();
  const char* columns[] = {"t",
                           "theta_deg",
                           "psi_deg",
                           "phi_deg",
                           "pivot_x",
                           "hinge_x",
                           "hinge_y",
                           "counterweight_x",
                           "counterweight_y",
                           "tip_x",
                           "tip_y",
                           "projectile_x",
                           "projectile_y",
                           "FS_perp",
                           "sling_tension",
                           "FR",
                           "FRh",
                           "FRv",
                           "FH",
                           "normal",
                           "beam_moment",
                           "E_counterweight",
                           "E_beam",
                           "E_projectile_kinetic",
                           "E_projectile_potential",
                           "W_lost"};
  for (const char* column : columns) frames[column] = json::array();
  frames["phase"] = json::array();
  for (const TracePoint& p : series.trace) {
    const Snapshot& s = p.snapshot;
    const bool gone = p.phase == Phase::released;
    const SitePoint pivot = site_point(s.pivot, engine), hinge = site_point(s.hinge, engine), cw = site_point(s.counterweight, engine),
                    tip = site_point(s.tip, engine), pr = site_point(s.projectile, engine);
    double lost = 0;  // the work of friction and drag so far
    for (double w : p.work) lost += w;
    const std::optional<double> values[] = {p.t * series.time_unit,
                                            degrees(p.state.theta),
                                            degrees(p.state.psi),
                                            gone ? std::nullopt : std::optional(degrees(p.state.phi)),
                                            pivot.x,
                                            hinge.x,
                                            hinge.y,
                                            cw.x,
                                            cw.y,
                                            tip.x,
                                            tip.y,
                                            gone ? std::nullopt : std::optional(pr.x),
                                            gone ? std::nullopt : std::optional(pr.y),
                                            s.sling_perpendicular * Mg,
                                            gone ? std::nullopt : std::optional(s.sling_tension * Mg),
                                            force_values(s)[pivot_reaction] * Mg,
                                            force_values(s)[pivot_horizontal] * Mg,
                                            s.pivot_reaction.y * Mg,
                                            std::hypot(s.hinge_force.x, s.hinge_force.y) * Mg,
                                            s.normal_force * Mg,
                                            s.beam_moment * energy_unit,
                                            s.energies.counterweight * energy_unit,
                                            s.energies.beam * energy_unit,
                                            s.energies.projectile_kinetic * energy_unit,
                                            s.energies.projectile_potential * energy_unit,
                                            lost * energy_unit};
    for (std::size_t k = 0; k < std::size(columns); ++k) frames[columns[k]].push_back(values[k] ? json(*values[k]) : json(nullptr));
    frames["phase"].push_back(phase_numeral(p.phase));
  }
  return frames;
}

// Phase II as releases, each over its value at the release (as release.svg draws them).
json phase_two_json(const ShotSeries& series) {
  const ShotSeries::Moment& at = series.phase_two[series.release_row];
  json phase_two = json::object();
  for (const char* column : {"t", "Q", "eps", "R", "FS_perp", "FR", "FRh_max", "FRh_min"}) phase_two[column] = json::array();
  for (const ShotSeries::Moment& row : series.phase_two) {
    phase_two["t"].push_back(row.t);
    phase_two["Q"].push_back(row.quality / at.quality);
    phase_two["eps"].push_back(row.efficiency / at.efficiency);
    phase_two["R"].push_back(row.range / at.range);
    const char* extremes[] = {"FS_perp", "FR", "FRh_max", "FRh_min"};
    for (int k = 0; k < force_count; ++k) phase_two[extremes[k]].push_back(row.running_max[k] / series.final_extremes[k]);
  }
  return phase_two;
}

// R [m] and Q against the pin angle [deg]; null where a pin gives no release, with why each pin
// without them is refused (null where it has them).
json pins_json(const ShotSeries& series) {
  json pins = {{"pin_angle_deg", json::array()}, {"R", json::array()}, {"Q", json::array()}, {"refused", json::array()}};
  for (const PinShot& shot : series.pins) {
    pins["pin_angle_deg"].push_back(shot.pin_angle_deg);
    pins["R"].push_back(shot.R ? json(*shot.R) : json(nullptr));
    pins["Q"].push_back(shot.Q ? json(*shot.Q) : json(nullptr));
    pins["refused"].push_back(shot.refused.empty() ? json(nullptr) : json(shot.refused));
  }
  return pins;
}

}  // namespace

nlohmann::ordered_json shot_series_json(const ShotSeries& series, const Engine& engine) {
  json flight = {{"x", json::array()}, {"y", json::array()}, {"time", series.flight_time}};
  for (const SitePoint& p : series.flight) flight["x"].push_back(p.x), flight["y"].push_back(p.y);
  return {{"pivot_height", pivot_height(engine)},
          {"energy_drop", potential_energy_drop(engine)},
          {"moments",
           {{"liftoff", series.liftoff},
            {"t1", series.first_extreme},
            {"tm", series.peak_reaction},
            {"t2", series.second_extreme},
            {"release", series.release}}},
          {"frames", frames_json(series, engine)},
          {"flight", flight},
          {"phase_two", phase_two_json(series)},
          {"release_row", series.release_row},
          {"pins", pins_json(series)}};
}

}  // namespace trebuchet
