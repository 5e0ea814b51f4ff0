// One shot of an engine, ab initio: phases I and II of appendix A integrated with GSL odeiv2,
// lift-off located where the trough's normal force vanishes, and the release at the maximum
// of the quality function over phase II (section 5). Everything here is scaled (dynamics.hpp).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "trebuchet/design.hpp"
#include "trebuchet/dynamics.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/integrator.hpp"
#include "trebuchet/machine.hpp"
#include "trebuchet/quality.hpp"

namespace trebuchet {

/// The projectile's state and the engine's figures at one moment of phase II, scaled.
struct ReleasePoint {
  double t = 0;  ///< scaled time
  State state;
  Vec2 position, velocity;  ///< projectile, relative to the pivot
  double height = 0;  ///< above the engine's base (l cos th_i + y), in L2
  double range = 0;  ///< rho: pivot to impact at level 0, in L2; <= 0: not forward
  double energy_at_target = 0;  ///< tau_e = T/(M g L2), eq:Aux, level 0
  double efficiency = 0;  ///< eps = T/Delta U, eq:Aux
  /// Running extremes of the forces of eq:F over [0, t], in Mg, peaks between step ends
  /// included (found on the continuous solution).
  ForceExtremes extremes;
  double force_factor = 0;  ///< F of eq:F
  double quality = 0;  ///< Q of eq:Q or eq:Q_n, at level 0
  double objective = 0;  ///< what the release maximises: Q, eps or the range
  double velocity_angle = 0;  ///< of the projectile above the horizontal toward the target [rad], in (-pi, pi]
  double pin_angle = 0;  ///< from the long arm (pivot to tip) to the sling (tip to projectile) [rad], in (-pi, pi]
};

/// The projectile's velocity angle above the horizontal toward the target (-x) [rad], in (-pi, pi].
double velocity_angle(const Snapshot& snapshot);

/// The pin angle [rad], in (-pi, pi]: from the long arm (pivot to tip) to the sling (tip to
/// projectile), positive while the sling trails the arm; the geometric angle between them
/// while positive (it starts obtuse, eq:InitialConditions, and closes through the throw).
double pin_angle(const Snapshot& snapshot);

/// The figures of a release at scaled time t from state s (with its snapshot), given the running
/// extremes of eq:F before t; the objective follows the criterion. Q (or Q_n), the range and the
/// objective stay 0 where the projectile would not fly forward from above the base.
ReleasePoint release_point(const ScaledDesign& design, const ReleaseCriterion& criterion, double t, const State& s, const Snapshot& snapshot,
                           ForceExtremes extremes_before);

/// What a builder sizes the parts for, scaled: the sling's tension (ropes), the force at the
/// counterweight's hinge (its pin), the axle's load (the force the frame carries: at the pivot,
/// and the floating arm's guide's beside its rail's), all in M g, and
/// the bending moment in the beam at the pivot, in M g L2 (the beam, eq:Strain).
enum LoadIndex { sling_tension_load, hinge_load, pivot_load, beam_moment_load };
inline constexpr int load_count = 4;
std::array<double, load_count> load_values(const Snapshot& snapshot);  ///< each as a magnitude, the tension as it is

/// The largest value of one load over phases I and II up to the release, found on the
/// continuous solution, and its scaled time.
struct LoadPeak {
  double value = 0, t = 0;
};

/// A further release of a shot read off its trajectory (docs/verifier.md, "One trajectory, every
/// release"): a release changes nothing before it, so phase II, stepped on as far as the release
/// needs, is the same that a shot given that release steps. The release and the work of the
/// losses up to it, bit for bit as that shot finds them.
struct OtherRelease {
  ReleasePoint release;
  Losses work{};
};

/// The further releases a shot reads off its trajectory, chosen once its own is found (`own`):
/// e.g. the pins a degree or two either side of the optimum's.
using OtherReleases = std::function<std::vector<GivenRelease>(const ReleasePoint& own)>;

/// Where phase III (after the release) could not be followed further: its scaled time, and why.
struct PhaseIiiCut {
  double t = 0;
  std::string why;
};

struct ShotResult {
  double t_liftoff = 0;  ///< scaled; the whipper's: when the projectile leaves the arm
  std::optional<double> t_counterweight_free;  ///< the whipper's: when its counterweight leaves the arm, scaled
  ReleasePoint release;
  double energy_drift = 0;  ///< max |E(t) + W(t) - E(0)| / Delta U over phases I and II, W the work of the losses
  long steps = 0;  ///< accepted steps, both phases
  std::array<LoadPeak, load_count> loads;  ///< by LoadIndex; all 0 unless asked for (simulate_shot)
  /// The work each loss took from the bodies up to the release, scaled (M g L2); all 0 for the
  /// ideal engine. With them, the energy of the bodies at the release and Delta U balance.
  Losses work{};
  /// The release sits at the instant this running extreme of eq:F starts to grow (a kink of
  /// the objective); none when it sits at a smooth maximum.
  std::optional<ForceIndex> release_at_growth_of;
  /// Where the sling goes slack and stays slack up to the range's peak (scaled time): the release is
  /// then the best before it (shot.cpp, slack_up_to_peak).
  std::optional<double> release_before_slack;
  // Where the model stops holding before the release, the scaled time it starts; none when it holds.
  std::optional<double> slack_sling;  ///< the sling would push the projectile (tension < 0)
  std::optional<double> counterweight_below_base;  ///< the counterweight passes below the engine's base
  /// the whipper's arm would pull the counterweight it holds (pytrebuchet's rule lets it go later)
  std::optional<double> counterweight_pulled;
  /// A rope of mass stops being a straight rope (shot.cpp, rope_holds): it would go slack at the
  /// tip or bend at an end by more than 10 deg to carry the rod model's shear.
  std::optional<double> rope_bent;
  std::optional<double> tip_below_base;  ///< the beam's tip passes below the engine's base
  /// The lowest height of the counterweight's centre above the engine's base, scaled: over the
  /// shot up to the release and after it for as long again (phase III, or until friction holds
  /// the machine at rest); found with the builder's loads (simulate_shot's find_loads).
  std::optional<double> lowest_counterweight;
  /// Where phase III stopped short of as long again, and why (simulate_shot): the lowest point
  /// above is then the lowest up to there.
  std::optional<PhaseIiiCut> phase_iii_cut;
  /// The further releases asked for (simulate_shot's `others`), in their order: none where a shot
  /// given that release would refuse it (in the trough, never, not forward) or fail.
  std::vector<std::optional<OtherRelease>> others;
};

/// One moment of the motion for a time series (--series), scaled.
struct TracePoint {
  Phase phase;
  double t;
  State state;
  Snapshot snapshot;
  Losses work{};  ///< of each loss since the start, scaled (M g L2)
};

/// Integrates the shot and finds the release. Throws Error(numerical) with a named reason:
/// the beam cannot turn, no lift-off, sling vertical in the trough, no forward release,
/// integrator failure or step budget, or energy drift above the limit.
/// With `trace`, the motion up to the release, the release itself, and phase III (beam and
/// counterweight alone) for as long again, are appended to it: at the integrator's step ends,
/// or with trace_dt > 0 (scaled) at every multiple of trace_dt on the continuous solution.
/// `unreleased` gets phase II past the release, had the projectile not been let go, as far as
/// the release search looked (the objective down to half its best), sampled alike.
/// With `find_loads`, the builder's loads (ShotResult::loads) and the counterweight's lowest
/// point (ShotResult::lowest_counterweight, which follows phase III) are found: what searches
/// that only rank engines save. With `others`, the further releases it asks for once the shot's
/// own is found are read off the same trajectory (ShotResult::others); the shot's own figures do
/// not change. With `span` to_release, the trace ends on the release (phase III, which the
/// pictures show, is neither integrated for it nor traced).
enum class TraceSpan { with_phase_iii, to_release };
ShotResult simulate_shot(const ScaledDesign& design, const ReleaseCriterion& criterion, const IntegratorSettings& settings,
                         std::vector<TracePoint>* trace = nullptr, double trace_dt = 0, std::vector<TracePoint>* unreleased = nullptr,
                         bool find_loads = false, const OtherReleases& others = {}, TraceSpan span = TraceSpan::with_phase_iii);

/// The same for any machine (machine.hpp): the paper's engine is simulate_shot(Dynamics(design), ...)
/// once the design has room for its counterweight arm and a beam that can turn, which the
/// overload above checks first.
ShotResult simulate_shot(const Machine& machine, const ReleaseCriterion& criterion, const IntegratorSettings& settings,
                         std::vector<TracePoint>* trace = nullptr, double trace_dt = 0, std::vector<TracePoint>* unreleased = nullptr,
                         bool find_loads = false, const OtherReleases& others = {}, TraceSpan span = TraceSpan::with_phase_iii);

/// One shot of simulate_given_shots: what it found, or why it failed.
struct GivenShot {
  std::optional<ShotResult> shot;
  std::optional<Error> error;
};

/// The shots of `machine` given each of `releases` in turn: each what simulate_shot given that
/// release (criterion.given) with `find_loads` finds, bit for bit, or the Error it throws. Phases
/// I and II are stepped once for all of them, as far as the latest release needs (a release
/// changes nothing before it: docs/verifier.md, "One trajectory, every release"); each follows
/// its own phase III. criterion.given is not read.
std::vector<GivenShot> simulate_given_shots(const Machine& machine, const ReleaseCriterion& criterion, const IntegratorSettings& settings,
                                            const std::vector<GivenRelease>& releases, bool find_loads);

}  // namespace trebuchet
