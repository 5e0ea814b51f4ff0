#include "trebuchet/verification.hpp"

#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/angles.hpp"

namespace trebuchet {

namespace {

// The release's velocity and place in SI, in the frame of the shot (the target toward -x), and
// the height of the release above the target level [m/s, m].
struct ReleaseInSi {
  double vx, vy, behind, drop;
};

// The flight through air, or back to the release height for Denny's range (measured from the
// release point, x behind the pivot, rather than the pivot): its range and the energy at its end.
void add_flight(Verification& out, const Engine& engine, const ReleaseInSi& at, double target_level, const std::optional<Air>& air,
                bool range_from_release) {
  const double g = engine.material.g, vx = at.vx, vy = at.vy, behind = at.behind, drop = at.drop;
  const double end_drop = range_from_release ? 0 : drop;
  double range = 0;
  Vec2 end_velocity{vx, vy};
  if (air) {
    const auto end = fly({behind, 0}, {vx, vy}, end_drop, drag_of(*air, engine.m), g);
    if (!end)
      throw Error(end_drop < 0 ? ErrorKind::usage : ErrorKind::numerical,
                  "the flight through " + describe_air(*air, engine.m) + " did not come down to its end" +
                      (end_drop < 0 ? ": the target level " + format_significant(target_level, 4) +
                               " m lies above the apex of the flight in air (drag lowers it); give a lower target level"
                                    : "; give the air, the wind and the projectile's density values of ordinary size"));
    range = end->range, end_velocity = end->velocity;
    if (!air->drag_coefficient) {
      // The fastest the flight meets the air is at one of its ends (drag slows the stone
      // toward its terminal speed, and gravity speeds it toward the same).
      const Drag drag = drag_of(*air, engine.m);
      const double fastest = std::max(std::hypot(vx + air->wind, vy), std::hypot(end_velocity.x + air->wind, end_velocity.y));
      const double reynolds = drag.reynolds_per_speed * fastest;
      if (reynolds > max_fitted_reynolds)
        out.notes.push_back("the flight reaches Re = " + format_significant(reynolds, 2) +
                            ", beyond the 1e6 to which Morrison's Cd(Re) was fitted: "
                            "the range in air is an extrapolation there (a fixed drag coefficient is another choice)");
    }
  } else {
    range = vacuum_range({behind, 0}, {vx, vy}, 0, g);
    end_velocity.y = -vy;
  }
  out.capacity.R = range_from_release ? range + behind : range;
  // A headwind can blow the projectile back behind the engine: no range to report.
  if (air && !(out.capacity.R > 0))
    throw Error(ErrorKind::out_of_range,
                "the flight through " + describe_air(*air, engine.m) + " ends " + format_significant(-out.capacity.R, 4) + " m behind the " +
                    (range_from_release ? "release point" : "pivot") +
                    ": the air blows the projectile back; give a weaker headwind ({{wind}}) or less drag");
  out.capacity.T = engine.m * (end_velocity.x * end_velocity.x + end_velocity.y * end_velocity.y) / 2;
  if (air) out.energy.flight_drag = engine.m * (out.v * out.v / 2 + g * end_drop) - out.capacity.T;
}

// The energy budget at the release, in M g L2, then in J, and Siano's range efficiencies, of the
// range to the base's level R_base [m].
void add_energy_budget(Verification& out, const Engine& engine, const ShotResult& shot, double R_base) {
  const ReleasePoint& r = shot.release;
  const double L2 = engine.L2, Mg = engine.M * engine.material.g;
  const ScaledDesign design = scaled_design(engine);
  const Snapshot at_release = machine_of(design)->snapshot(Phase::lifted, r.state);
  const double at_rest = design.mu_b * design.beam_cm() - 1 - design.L();  // upright beam, hanging counterweight, from the pivot's level
  const double energy_unit = Mg * L2;
  out.energy.delta_U = design.energy_drop() * energy_unit;
  out.energy.projectile = r.energy_at_target * energy_unit;
  out.energy.engine = (at_release.energies.beam + at_release.energies.counterweight - at_rest) * energy_unit;
  // The sling's, from its start along the base: what it took by the release.
  const double sling_at_start = -(design.parts.sling.rope + design.parts.sling.pouch) * design.pivot_height();
  out.energy.sling = (at_release.energies.sling - sling_at_start) * energy_unit;
  for (int k = 0; k < loss_count; ++k) out.energy.losses[k] = shot.work[k] * energy_unit;
  // Siano's black box throws all of Delta U at 45 deg from the ground: 2 Delta U/(m g) = 2 Delta U L2/mu [m].
  out.range_efficiency = R_base / (2 * design.energy_drop() * L2 / design.mu);
  out.range_efficiency_counterweight = R_base / (2 * design.counterweight_fall() * L2 / design.mu);
}

// The builder's loads in SI, and the beam's strength where it has a diameter.
void add_loads_and_beam(Verification& out, const Engine& engine, const ShotResult& shot, double time_unit) {
  const double L2 = engine.L2, Mg = engine.M * engine.material.g;
  const double load_unit[load_count] = {Mg, Mg, Mg, Mg * L2};  // LoadIndex, scaled in M g and M g L2
  for (int k = 0; k < load_count; ++k) out.loads[k] = {shot.loads[k].value * load_unit[k], shot.loads[k].t * time_unit};
  const double D = engine.D > 0 ? engine.D : engine.mb > 0 ? beam_diameter(engine.mb, beam_length(engine), engine.material) : 0;
  if (const ScaledDesign d = scaled_design(engine); D > 0 && d.short_section())
    out.beam = beam_strength(D, L2, engine.M, out.loads[beam_moment_load].value, engine.material, d.counterweight_lever());
  if (engine.D > 0 && engine.mb > 0 && !engine.parts.D_tip) {
    // The beam's mass moves the engine, its diameter carries the stress: a pair that disagrees
    // with the wood (eq:BeamMass) by more than 10 % is said to, with the density it implies.
    const double implied_density = engine.mb / beam_mass(engine.D, beam_length(engine), engine.material) * engine.material.wood_density;
    if (std::abs(implied_density / engine.material.wood_density - 1) > 0.1)
      out.notes.push_back("D = " + format_significant(engine.D, 3) + " m and mb = " + format_significant(engine.mb, 4) + " kg make a wood of " +
                          format_significant(implied_density, 3) + " kg/m3 (eq:BeamMass), not " +
                          format_significant(engine.material.wood_density, 3) + ": the motion uses mb, the stress D");
  }
}

// Where the model stops holding before the release, the counterweight's clearance above the
// ground (hanging, and lowest in the shot), and the notes of what the shot left unused or unfollowed.
void add_warnings_and_clearance(Verification& out, const Engine& engine, const ShotResult& shot, const std::optional<Air>& air, double time_unit) {
  const double L2 = engine.L2;
  // In vacuum only the whipper's ball has a use for its size (where it rests on the arm).
  if (engine.projectile_diameter && !air && engine.machine != MachineKind::whipper)
    out.notes.push_back("the projectile's diameter, " + format_significant(*engine.projectile_diameter, 4) +
                        " m, sets its drag in air alone: this shot is in vacuum, where it is not used (fly through air to use it)");
  auto warn = [&](const std::optional<double>& t, const std::string& what) {
    if (t)
      out.warnings.push_back(what + " at t = " + format_significant(*t * time_unit, 4) + " s, before the release at " +
                             format_significant(out.t_release, 4) + " s: the model no longer holds there, and the figures are not physical");
  };
  warn(shot.slack_sling, "the sling goes slack (it would push the projectile)");
  out.sling_slack = shot.slack_sling.has_value();
  warn(shot.counterweight_below_base, "the counterweight passes below the engine's base");
  out.counterweight_below_base = shot.counterweight_below_base.has_value();
  warn(shot.counterweight_pulled,
       "the whipper's arm would pull the counterweight it holds (the push between them changes sign before pytrebuchet's rule lets it go)");
  warn(shot.tip_below_base, "the beam's tip passes below the engine's base");
  warn(shot.rope_bent, "the sling's rope of mass stops being a straight rope (it would go slack at the tip, or bend at an end by more than 10 deg)");
  // A clearance within round-off of 0 (1e-9 L2, as the shot's conditions) is 0: an F = 1
  // counterweight hanging straight down touches the ground.
  const auto clear = [&](double height) { return std::abs(height) < 1e-9 * L2 ? 0.0 : height; };
  const double half_box = engine.parts.box_height.value_or(0) / 2;
  const std::string bottom = engine.parts.box_height ? "the bottom of the counterweight's box" : "the counterweight's centre";
  out.clearance.geometric = clear(pivot_height(engine) - engine.L2 - engine.L3 - half_box);
  if (shot.lowest_counterweight) out.clearance.in_shot = clear(*shot.lowest_counterweight * L2 - half_box);
  if (shot.release_before_slack)
    out.notes.push_back("the sling goes slack at t = " + format_significant(*shot.release_before_slack * time_unit, 4) +
                        " s and stays slack up to the range's peak: released at the best before it (the range would grow later only on a sling that "
                        "pushes the ball)");
  if (shot.phase_iii_cut)
    out.notes.push_back("after the release the counterweight was followed only to t = " + format_significant(shot.phase_iii_cut->t * time_unit, 4) +
                        " s of " + format_significant(2 * out.t_release, 4) + " s (" + shot.phase_iii_cut->why +
                        "): its clearance in the shot is the lowest up to then");
  // Short enough for a picture's foot (pictures.cpp): the docs say how H follows from L1 and theta_i.
  const std::string fix = std::string(": not buildable as given; ") +
      (engine.machine == MachineKind::whipper ? "raise its frame (H)" : "raise the pivot") + " or shorten L2 + L3" +
      (engine.parts.box_height ? " or the box" : "");
  if (!(out.clearance.geometric >= 0))
    out.warnings.push_back("hanging straight down, " + bottom + " reaches " + format_significant(-out.clearance.geometric, 4) +
                           " m below the ground (H - L2 - L3" + (engine.parts.box_height ? " - half the box's height" : "") + ")" + fix);
  else if (out.clearance.in_shot && !(*out.clearance.in_shot >= 0))
    out.warnings.push_back("in the shot " + bottom + " swings " + format_significant(-*out.clearance.in_shot, 4) + " m below the ground" + fix);
}

}  // namespace

Verification verification_of(const Engine& engine, const ShotResult& shot, double target_level, const std::optional<Air>& air,
                             bool range_from_release) {
  const ReleasePoint& r = shot.release;
  const double L2 = engine.L2, g = engine.material.g;
  const double speed_unit = std::sqrt(g * L2), time_unit = std::sqrt(L2 / g);  // section 3
  Verification out;
  const double vx = r.velocity.x * speed_unit, vy = r.velocity.y * speed_unit;
  out.v = std::hypot(vx, vy);
  out.h = r.height * L2;
  const double behind = r.position.x * L2;  // in the frame of the shot, where the target lies toward -x [m]
  out.x = -behind;
  out.A_deg = degrees(std::atan2(vy, -vx));
  out.theta_release_deg = degrees(r.state.theta);
  out.pin_angle_deg = degrees(r.pin_angle);
  out.pin_to_bend_deg = pin_to_bend_deg(out.pin_angle_deg, engine.parts.pin_friction);
  const double drop = out.h - target_level;  // release to target level [m]
  const double apex = out.h + (vy > 0 ? vy * vy / (2 * g) : 0);  // highest point of the flight above the base [m]
  if (!(target_level <= apex))
    throw Error(ErrorKind::usage,
                "the target level " + format_significant(target_level, 4) + " m lies above the apex of the flight, " + format_significant(apex, 4) +
                    " m above the engine's base; give a target level below it");
  out.R_vacuum = vacuum_range({behind, 0}, {vx, vy}, drop, g);
  out.capacity.R = out.R_vacuum;
  // The black box throws from the ground to the ground: the range efficiency's range is to the base's level.
  const double R_base = target_level == 0 ? out.R_vacuum : vacuum_range({behind, 0}, {vx, vy}, out.h, g);
  // eq:T at the target level: the height above it is drop/L2, scaled; M g L2 turns tau_e into joules.
  out.capacity.T = energy_at_target(engine.m / engine.M, r.velocity, drop / L2) * engine.M * g * L2;
  out.T_vacuum = out.capacity.T;
  out.capacity.target_level = range_from_release ? out.h : target_level;
  if (air || range_from_release) add_flight(out, engine, {vx, vy, behind, drop}, target_level, air, range_from_release);
  out.eps = r.efficiency;
  out.Q = r.quality;
  out.force_factor = r.force_factor;
  out.t_release = r.t * time_unit;
  out.t_liftoff = shot.t_liftoff * time_unit;
  if (shot.t_counterweight_free) out.t_counterweight_free = *shot.t_counterweight_free * time_unit;
  out.FS_perp_mg = r.extremes.max[sling_perpendicular] / (engine.m / engine.M);
  out.FR_Mg = r.extremes.max[pivot_reaction];
  out.dFRh_Mg = r.extremes.max[pivot_horizontal] + r.extremes.max[pivot_horizontal_negated];
  out.energy_drift = shot.energy_drift;
  const double Mg = engine.M * g;
  add_energy_budget(out, engine, shot, R_base);
  out.FS_perp = out.FS_perp_mg * engine.m * g, out.FR = out.FR_Mg * Mg, out.dFRh = out.dFRh_Mg * Mg;
  add_loads_and_beam(out, engine, shot, time_unit);
  add_warnings_and_clearance(out, engine, shot, air, time_unit);
  return out;
}

bool Verification::Clearance::buildable() const { return geometric >= 0 && (!in_shot || *in_shot >= 0); }

void check_shot_settings(const ShotSettings& settings) {
  check_integrator(settings.integrator);
  if (settings.air) check_air(*settings.air);
  check_ordinary(settings.target_level, -1e6, 1e6, "target_level", "m", "target level above the engine's base (below it when negative)");
  // eq:Q_n asks n >= 0. Beyond max_quality_exponent, eps^n of an engine's eps (0.5 to 0.98)
  // falls below 1e-6 or flattens Q_n to round-off, and no release or design is preferred.
  check_ordinary(settings.criterion.n, 0, max_quality_exponent, "n", "", "exponent of eps in eq:Q_n");
  if (const auto& at = settings.release_at) {
    if (at->by == ReleaseBy::time)
      check_ordinary(at->value, 1e-9, 1e6, "release_time", "s", "release time after the start");
    else
      check_ordinary(
          at->value, -180, 180, at->by == ReleaseBy::pin_angle ? "pin_angle" : "release_angle", "deg",
          at->by == ReleaseBy::pin_angle ? "pin angle between the long arm and the sling" : "projectile's velocity angle above the horizontal");
  }
}

ReleaseCriterion release_criterion(const Engine& engine, const ShotSettings& settings) {
  ReleaseCriterion criterion = settings.criterion;
  if (settings.air) criterion.drag = scaled(drag_of(*settings.air, engine.m), engine.L2, engine.material.g);
  criterion.range_from_release = settings.range_from_release;
  criterion.target_level = settings.target_level / engine.L2;
  criterion.length_unit = engine.L2;
  if (const auto& at = settings.release_at) {
    const double time_unit = std::sqrt(engine.L2 / engine.material.g);  // section 3 [s]
    const double value = at->by == ReleaseBy::time ? at->value / time_unit
        : at->by == ReleaseBy::pin_angle           ? release_pin_angle(radians(at->value), engine.parts.pin_friction)
                                                   : radians(at->value);
    // A pin's messages name it as bent: the release's angle moved back by the friction's delay.
    criterion.given = GivenRelease{at->by, value, time_unit, at->by == ReleaseBy::pin_angle ? radians(at->value) - value : 0};
  }
  return criterion;
}

ScaledDesign shot_design(const Engine& engine, const ShotSettings& settings) {
  ScaledDesign design = scaled_design(engine);
  // The whipper's ball, not given, is a sphere of the air's projectile density, as its drag's.
  if (engine.machine == MachineKind::whipper && !engine.projectile_diameter && settings.air)
    design.projectile_radius = sphere_diameter(engine.m, settings.air->projectile_density) / 2 / engine.L2;
  if (settings.air && settings.drag_in_sling) {
    design.parts.drag = scaled(drag_of(*settings.air, engine.m), engine.L2, engine.material.g);
    // rho Cd d/2 per length and speed squared [N s^2/m^3], in M g per L2 and (g L2) (section 3)
    design.parts.rope_drag = settings.air->density * engine.parts.rope_cd * engine.parts.rope_diameter / 2 * engine.L2 * engine.L2 / engine.M;
  }
  return design;
}

ShotSettings settings_for(const Engine& engine, const ShotSettings& settings) {
  ShotSettings out = settings;
  const std::optional<double>& d = engine.projectile_diameter;
  if (!d || !out.air) return out;
  if (out.air->projectile_density != Air{}.projectile_density)
    throw Error(ErrorKind::usage, "{{projectile}} and {{projectile_diameter}} both size the projectile (with its mass m); give one of them");
  out.air->projectile_density = sphere_density(engine.m, *d);
  return out;
}

namespace {

// What verify_engine checks before its shot, in this order, and the settings and criterion it
// shoots by.
struct ShotPlan {
  ShotSettings settings;
  ReleaseCriterion criterion;
};
ShotPlan plan_shot(const Engine& engine, const ShotSettings& given) {
  check_engine(engine);  // as given, its material too: a caller may have changed either since it was read
  check_shot_settings(given);
  const ShotSettings settings = settings_for(engine, given);
  if (engine.parts.rope_diameter > 0 && !(settings.air && settings.drag_in_sling))
    throw Error(ErrorKind::usage,
                "{{rope_diameter}} gives the drag on the sling's rope, which acts only when the air acts before the release; "
                "add {{drag_in_sling}} (with {{air}}), or leave the rope's diameter out");
  return {settings, release_criterion(engine, settings)};
}

}  // namespace

Verification verify_engine(const Engine& engine, const ShotSettings& given, std::vector<TracePoint>* trace, double trace_dt_s, PinScan* pins) {
  const auto [settings, criterion] = plan_shot(engine, given);
  const double time_unit = std::sqrt(engine.L2 / engine.material.g);  // section 3 [s]
  if (trace && trace_dt_s > 0) {
    // The series runs to twice the release (shot.hpp); its size is known before it is written.
    const double duration_s = 2 * simulate_shot(shot_design(engine, settings), criterion, settings.integrator).release.t * time_unit;
    if (!(duration_s / trace_dt_s <= max_series_points))
      throw Error(ErrorKind::bad_number,
                  "{{series_dt}} = " + format_significant(trace_dt_s, 6) + " s would cut the " + format_significant(duration_s, 4) +
                      " s of the series into more than " + std::to_string(static_cast<long>(max_series_points)) + " points; give at least " +
                      format_significant(duration_s / max_series_points, 2) + " s");
  }
  const ShotResult shot = simulate_shot(shot_design(engine, settings), criterion, settings.integrator, trace, trace_dt_s / time_unit, nullptr,
                                        settings.loads, pins ? pins->releases() : OtherReleases{});
  if (pins) pins->read(shot);
  return verification_of(engine, shot, settings.target_level, settings.air, settings.range_from_release);
}

std::vector<VerifiedRelease> verify_releases(const Engine& engine, const ShotSettings& settings, const std::vector<SetRelease>& releases) {
  std::vector<VerifiedRelease> out(releases.size());
  std::optional<ShotPlan> plan;  // the first release's; the others differ from it in their release alone
  std::vector<GivenRelease> asked;
  std::vector<std::size_t> place;  // each asked release's place in `releases`
  for (std::size_t i = 0; i < releases.size(); ++i) {
    ShotSettings at = settings;
    at.release_at = releases[i];
    try {
      const ShotPlan planned = plan_shot(engine, at);
      asked.push_back(*planned.criterion.given);
      place.push_back(i);
      if (!plan) plan = planned;
    } catch (const Error& e) {
      out[i].error = e;
    }
  }
  if (!plan) return out;
  const ShotSettings& settings_at = plan->settings;
  std::vector<GivenShot> shots;
  try {
    const ScaledDesign design = shot_design(engine, settings_at);
    shots = simulate_given_shots(*machine_of(design), plan->criterion, settings_at.integrator, asked, settings_at.loads);
  } catch (const Error& e) {
    for (std::size_t i : place) out[i].error = e;
    return out;
  }
  for (std::size_t k = 0; k < shots.size(); ++k) {
    VerifiedRelease& one = out[place[k]];
    one.error = shots[k].error;
    if (shots[k].shot) try {
        one.verification = verification_of(engine, *shots[k].shot, settings_at.target_level, settings_at.air, settings_at.range_from_release);
      } catch (const Error& e) {
        one.error = e;
      }
  }
  return out;
}

PinScan::PinScan(const Engine& engine, const ShotSettings& settings, Pins pins_deg)
    : engine_(engine), settings_(settings), pins_deg_(std::move(pins_deg)) {}

OtherReleases PinScan::releases() {
  return [this](const ReleasePoint& own) {
    asked_ = pins_deg_(pin_to_bend_deg(degrees(own.pin_angle), engine_.parts.pin_friction));
    // Each pin as a shot given it releases there (release_criterion), in the settings as they hold for the engine.
    // Those it refuses as given (check_shot_settings: beyond -180 to 180 deg) are not asked.
    ShotSettings at = settings_for(engine_, settings_);
    std::vector<GivenRelease> releases;
    released_.clear();
    unasked_.clear();
    for (double pin : asked_) {
      at.release_at = SetRelease{ReleaseBy::pin_angle, pin};
      released_.emplace_back();
      unasked_.emplace_back();
      try {
        check_shot_settings(at);
      } catch (const Error& e) {
        unasked_.back() = e.what();
        continue;
      }
      released_.back() = releases.size();
      releases.push_back(*release_criterion(engine_, at).given);
    }
    return releases;
  };
}

void PinScan::read(const ShotResult& shot) {
  const ShotSettings settings = settings_for(engine_, settings_);
  shots_.clear();
  for (std::size_t i = 0; i < asked_.size(); ++i) {
    PinShot pin{asked_[i], std::nullopt, std::nullopt, unasked_[i]};
    if (const auto& other = released_[i] ? shot.others.at(*released_[i]) : std::nullopt) {
      ShotResult released;
      released.t_liftoff = shot.t_liftoff, released.release = other->release, released.work = other->work;
      try {
        const Verification v = verification_of(engine_, released, settings.target_level, settings.air, settings.range_from_release);
        pin.R = v.capacity.R, pin.Q = v.Q;
      } catch (const Error& e) {
        pin.refused = e.what();  // a flight that does not come down to the target level, as a shot given this pin refuses it
      }
    } else if (released_[i]) {
      pin.refused = "no release there: the sling passes this pin in the trough, before lift-off, or not at all before the swing ends";
    }
    shots_.push_back(pin);
  }
}

std::optional<std::string> pin_release_note(const Verification& v, const PinShot& pin) {
  // The shot given its own pin repeats the release to the roots' 1e-9 (tests/test_release.cpp).
  if (pin.R && std::abs(*pin.R - v.capacity.R) <= 1e-6 * std::abs(v.capacity.R)) return std::nullopt;
  return "no pin makes this release: a pin bent to " + format_significant(pin.pin_angle_deg, 4) + " deg " +
      (pin.R ? "lets go elsewhere in the swing (R = " + format_significant(*pin.R, 4) + " m there)" : std::string("is refused")) +
      "; release it at a given time instead, or choose another engine";
}

CapacityCheck check_capacity(const Verification& v, const Capacity& predicted, double tolerance, bool as_measured) {
  // From a part in 10^12 (round-off of the shot) to a factor of 10^3.
  check_ordinary(tolerance, 1e-12, 1e3, "tol", "", "relative tolerance on the predicted R and T");
  CapacityCheck c;
  c.predicted = predicted, c.tolerance = tolerance;
  c.as_measured = as_measured;
  c.deviation_R = (as_measured ? v.capacity.R : v.R_vacuum) / predicted.R - 1;
  c.deviation_T = (as_measured ? v.capacity.T : v.T_vacuum) / predicted.T - 1;
  c.pass = std::abs(c.deviation_R) <= tolerance && std::abs(c.deviation_T) <= tolerance;
  return c;
}

}  // namespace trebuchet
