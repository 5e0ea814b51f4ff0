// The ab-initio figures of an engine in SI units: a shot (shot.hpp) of its scaled design,
// turned back into metres, joules and newtons with L2, M and the engine's g (section 3).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/air.hpp"
#include "trebuchet/angles.hpp"
#include "trebuchet/capacity.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/shot.hpp"

namespace trebuchet {

/// A release the user sets (quality.hpp, GivenRelease), as given: the time after the start [s],
/// or the velocity or pin angle [deg].
struct SetRelease {
  ReleaseBy by = ReleaseBy::time;
  double value = 0;  ///< [s] or [deg]
};

/// Where a sling's loop leaves a release pin bent to `bent` [rad] with friction mu: a loop slips
/// once the sling's pull leaves the pin's friction cone, atan(mu) past where it would leave a
/// frictionless pin; the pin angle closes through the throw, so the release comes at bent -
/// atan(mu) (docs/verifier.md, "The release pin's friction").
inline double release_pin_angle(double bent, double mu) { return bent - std::atan(mu); }
/// Its inverse: the pin to bend [deg] for a release at pin angle `released_deg` [deg].
inline double pin_to_bend_deg(double released_deg, double mu) { return released_deg + degrees(std::atan(mu)); }

struct ShotSettings {
  double target_level = 0;  ///< target height relative to the engine's base [m], e.g. -54
  ReleaseCriterion criterion{};  ///< the optimum's criterion; its given release and target level follow from the fields here (release_criterion)
  std::optional<SetRelease> release_at;  ///< none: the release is the criterion's optimum
  IntegratorSettings integrator{};
  std::optional<Air> air;  ///< none: vacuum (the paper's, and the default)
  /// Denny's range (section 6.3): from the release point to where the flight dips below the
  /// release height, instead of from the pivot to the target level.
  bool range_from_release = false;
  /// Find the builder's loads (Verification::loads and the beam's peak stress); searches that
  /// only rank engines leave them out, and report them for the engine they find.
  bool loads = true;
  /// With air: the air acts before the release too, on the projectile in the trough and in the
  /// sling, and on the sling's rope when the engine gives its diameter (EngineParts). Off by
  /// default, as in the paper and in tab:Denny, where drag acts only in flight.
  bool drag_in_sling = false;
};

/// The scaled design a shot of `engine` under `settings` integrates: scaled_design(engine) with
/// the air before the release when the settings ask for it (BuiltParts::drag, rope_drag).
ScaledDesign shot_design(const Engine& engine, const ShotSettings& settings);

/// Refuses settings no shot can run under: check_integrator, check_air, a target level
/// beyond 1e6 m either way ({{target_level}}), a release time outside 1e-9 to 1e6 s
/// ({{release_time}}) and a release angle outside -180 to 180 deg ({{release_angle}}, {{pin_angle}}). Searches that try many shots call it first, so
/// that bad settings are reported as such, not as engines that failed.
void check_shot_settings(const ShotSettings& settings);

/// What trebuchet-verify reports, in SI units (angles in degrees).
struct Verification {
  Capacity capacity;  ///< range and energy (eq:T) at the end of the flight, under the settings' air and range definition
  double R_vacuum = 0;  ///< the paper's range: in vacuum, from the pivot to the target level [m]
  double T_vacuum = 0;  ///< the paper's energy at the target level, in vacuum (eq:T) [J]
  double eps = 0;  ///< efficiency T/Delta U at level 0, eq:Aux
  double Q = 0;  ///< quality at the release, eq:Q or eq:Q_n (with the n of the settings)
  double force_factor = 0;  ///< F of eq:F, scaled
  double v = 0;  ///< release speed [m/s]
  double h = 0;  ///< release height above the base [m]
  double x = 0;  ///< release position from the pivot toward the target, as on the site (report.hpp): < 0 behind the pivot [m]
  double A_deg = 0;  ///< initial climb: the velocity angle at the release [deg]
  double pin_angle_deg = 0;  ///< the pin angle at the release, from the long arm to the sling (shot.hpp) [deg]
  /// The pin angle to bend the release pin to for this release: pin_angle_deg plus atan of the
  /// engine's pin friction (release_pin_angle) [deg].
  double pin_to_bend_deg = 0;
  /// Siano's range efficiency (docs/verifier.md, "Range efficiency"): the range in vacuum from the
  /// pivot to the base's level (R_vacuum at target level 0) over the black
  /// box's range 2 Delta U/(m g), all of Delta U (eq:DU, the beam's rise taken off) thrown at 45
  /// deg from the ground in vacuum; and over 2 M h/m, h the counterweight's fall alone. Scaled.
  double range_efficiency = 0, range_efficiency_counterweight = 0;
  double theta_release_deg = 0;  ///< beam angle at release from the downward vertical [deg]; 180 is upright (section 6.2: below it, lower branch)
  double t_release = 0;  ///< [s]
  double t_liftoff = 0;  ///< [s]; the whipper's: its projectile leaves the arm
  std::optional<double> t_counterweight_free;  ///< the whipper's: its counterweight leaves the arm [s]
  double FS_perp_mg = 0;  ///< largest perpendicular sling force on the beam / (m g), scaled
  double FR_Mg = 0;  ///< largest |pivot reaction| / (M g), scaled
  double dFRh_Mg = 0;  ///< largest minus smallest horizontal pivot reaction / (M g), scaled
  double FS_perp = 0, FR = 0, dFRh = 0;  ///< the same three forces [N]
  double energy_drift = 0;  ///< max |E(t) - E(0)| / Delta U over phases I and II, scaled
  /// The largest loads a builder sizes parts for (shot.hpp: LoadIndex), over phases I and II up
  /// to the release, with their times: the sling's tension, the force on the counterweight's
  /// hinge pin and on the axle at the pivot [N], the bending moment in the beam at the pivot [N m].
  struct Load {
    double value = 0;  ///< [N] or [N m]
    double t = 0;  ///< [s]
  };
  std::array<Load, load_count> loads;
  /// The beam's bending and stress (material.hpp), with D as given or, failing that, from mb by
  /// eq:BeamMass; none for a beam of no mass.
  std::optional<BeamStrength> beam;
  /// Where Delta U (eq:DU) went by the release [J]: the projectile's energy at the base's level
  /// (eq:T, eps Delta U), what the beam and the counterweight still hold above their rest (upright
  /// beam, counterweight hanging below the hinge), and the work each loss took (LossIndex). These
  /// sum to Delta U within the energy drift. After the release, what the air took in flight.
  struct EnergyBudget {
    double delta_U = 0, projectile = 0, engine = 0;
    double sling = 0;  ///< what a sling of mass took: its energy at the release less at the start [J]
    Losses losses{};
    double flight_drag = 0;  ///< the projectile's energy at release over the flight's end level, less that at the end; 0 in vacuum
  };
  EnergyBudget energy;
  /// The counterweight's clearance above the ground [m], of its lowest point (the bottom of its
  /// box, where the box's height is given): the lowest that the machine's geometry lets it reach,
  /// hanging straight down below the short arm pointing down (H - L2 - L3 - half the box, for
  /// every machine), and the lowest it reaches in the shot, up to the release and after it for
  /// as long again (none for a shot without the builder's loads). The tip rests on the ground by
  /// construction and is left out. Below 0 (past round-off) the engine cannot be built as
  /// given: a warning says so.
  struct Clearance {
    double geometric = 0;
    std::optional<double> in_shot;
    bool buildable() const;
  };
  Clearance clearance;
  /// Where the model stops holding before the release (a slack sling, the counterweight or the
  /// beam's tip below the base), each with its time: the figures are then not physical; and a
  /// counterweight that would strike the ground (clearance): the engine cannot be built as given.
  std::vector<std::string> warnings;
  /// Whether one of them is the counterweight passing below the base before the release: an
  /// engine that strikes the ground, as a clearance below 0 (then also warned) says.
  bool counterweight_below_base = false;
  /// Whether one of them is the sling going slack before the release.
  bool sling_slack = false;
  /// What makes a figure less certain without making it unphysical: Cd(Re) used beyond the
  /// Reynolds numbers it was fitted to; phase III followed only part of the way (ShotResult::phase_iii_cut).
  std::vector<std::string> notes;
};

/// The SI figures of a shot of `engine` (of scaled design shot_design(engine, ...)), its flight in
/// vacuum or through `air`, to the target level or (range_from_release) back to the release
/// height. Throws Error(usage) when the target level lies above the apex of the flight.
Verification verification_of(const Engine& engine, const ShotResult& shot, double target_level, const std::optional<Air>& air = std::nullopt,
                             bool range_from_release = false);

/// The release criterion of a shot of `engine` under `settings`: under Release::range it
/// maximises the range as the settings define it, in their air, from where they measure and to
/// their target level; with release_at it releases there instead (scaled).
ReleaseCriterion release_criterion(const Engine& engine, const ShotSettings& settings);

/// The most points a series sampled every trace_dt_s may hold (about 100 MB of CSV).
inline constexpr double max_series_points = 1e6;

/// The settings as they hold for `engine`: its projectile's diameter, where given, sets the
/// projectile's density in air (m over the ball's volume), so that its drag is the ball's.
/// Throws Error(usage) where the density is given too. In vacuum a diameter is the whipper's
/// alone (its ball rests on its arm by it); another machine's shot notes it unused (Verification::notes).
ShotSettings settings_for(const Engine& engine, const ShotSettings& settings);

/// The shot of `engine` released at a pin bent to a given angle: its range (as the settings
/// measure it) and Q, or none where that release cannot be made (in the trough, never reached,
/// backward, or with a flight that does not come down to the target level).
struct PinShot {
  double pin_angle_deg = 0;  ///< the pin to bend [deg]
  std::optional<double> R, Q;  ///< [m], scaled
  std::string refused;  ///< why a shot given this pin has no R and Q, in words; empty when it has them
};

/// How the range and Q change as the pin is bent (the best pin's tolerance, the chart of --plot):
/// the releases at pins bent to pins_deg(own) [deg], own the pin to bend for the shot's own
/// release, read off that shot's trajectory (simulate_shot's OtherReleases). Each is what a shot
/// of `engine` under settings_for(engine, settings) given that pin angle ({{pin_angle}}) finds,
/// bit for bit; a pin such a shot refuses (beyond -180 to 180 deg too) has none. One scan serves
/// one shot: releases() for the shot to ask, then read() of what it found.
class PinScan {
 public:
  using Pins = std::function<std::vector<double>(double own_deg)>;
  PinScan(const Engine& engine, const ShotSettings& settings, Pins pins_deg);
  /// The releases to ask the shot for; this scan must outlive the shot.
  OtherReleases releases();
  /// Reads the pin shots off a shot that asked for releases().
  void read(const ShotResult& shot);
  const std::vector<PinShot>& shots() const { return shots_; }

 private:
  const Engine& engine_;
  const ShotSettings& settings_;
  Pins pins_deg_;
  std::vector<double> asked_;  ///< the pins asked for [deg]
  std::vector<std::optional<std::size_t>> released_;  ///< each pin's place among the shot's further releases; none: refused as given
  std::vector<std::string> unasked_;  ///< why a pin refused as given was not asked; empty for the others
  std::vector<PinShot> shots_;
};

/// Simulates one shot of `engine` under settings_for(engine, settings), under its own g. Throws Error(numerical) as simulate_shot
/// does. With `trace`, the motion is appended to it (scaled, see simulate_shot): at the step
/// ends, or every trace_dt_s seconds; a trace_dt_s that gives more than max_series_points is
/// refused (Error(bad_number), {{series_dt}}) before the series is drawn. With `pins`, its pin
/// shots are read off the same shot (PinScan::shots).
Verification verify_engine(const Engine& engine, const ShotSettings& settings, std::vector<TracePoint>* trace = nullptr, double trace_dt_s = 0,
                           PinScan* pins = nullptr);

/// One shot of verify_releases: what verify_engine returns for it, or the Error it throws.
struct VerifiedRelease {
  std::optional<Verification> verification;
  std::optional<Error> error;
};

/// verify_engine of `engine` under `settings` given each of `releases` in turn (its release_at,
/// settings.release_at not read), bit for bit, the shots read off one trajectory
/// (simulate_given_shots): a sweep of a release at the cost of one phase II.
std::vector<VerifiedRelease> verify_releases(const Engine& engine, const ShotSettings& settings, const std::vector<SetRelease>& releases);

/// Where a pin bent to the shot's own pin to bend does not make its release: a note that no pin
/// makes it. `pin` is the shot given that pin (read off the trajectory, PinScan, or shot alone):
/// refused, or of another range (beyond 1e-6 of it), as where the pin angle passes the pin
/// earlier in the swing. None where the pin makes it.
std::optional<std::string> pin_release_note(const Verification& v, const PinShot& pin);

/// The pin angles either side of an optimum's whose range loss a shot reports [deg].
inline constexpr double pin_tolerance_offsets[] = {-2, -1, 1, 2};
/// The friction of a greased and of a dry release pin the pin report bends for when none is given:
/// the ends of the handbooks' 0.1 to 0.5 for a rope or iron loop on an iron or wooden pin.
inline constexpr double greased_pin_friction = 0.1, dry_pin_friction = 0.5;

/// A predicted capacity (from the calculator, in vacuum as the paper's) against the shot's own
/// in vacuum (R_vacuum, T_vacuum), whatever air the shot flew through; or, as_measured, a
/// requested one (fit's) against the shot as it measures them (its air, level and range).
struct CapacityCheck {
  Capacity predicted;  ///< [m], [J]
  double deviation_R = 0;  ///< simulated/predicted - 1
  double deviation_T = 0;
  double tolerance = 0;  ///< relative
  bool pass = false;  ///< both deviations within the tolerance
  bool as_measured = false;  ///< against the shot's capacity as measured, not the vacuum one
};

CapacityCheck check_capacity(const Verification& v, const Capacity& predicted, double tolerance, bool as_measured = false);

}  // namespace trebuchet
