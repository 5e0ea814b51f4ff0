// The best engine under a contest's limits (issue 36, docs/machines.md): for a given projectile,
// machine and beam, the lengths and the counterweight that throw farthest (or most efficiently)
// within a bounding box, a largest counterweight, a largest peak load on the axle and a largest
// peak acceleration of the projectile; the Pareto front of range against the axle's load; and,
// when no engine meets the limits, the fewest of them that cannot be met together.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "trebuchet/engine.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// The limits a contest sets, each optional.
enum ContestLimit { width_limit, height_limit, mass_limit, axle_limit, acceleration_limit };
inline constexpr int contest_limit_count = 5;
/// width and height of the bounding box [m], counterweight mass [kg], peak axle load [N], peak
/// acceleration of the projectile [m/s2].
using ContestLimits = std::array<std::optional<double>, contest_limit_count>;

/// "max_width", ...: each limit's key, as messages ({{max_width}}, error.hpp), JSON and the
/// programs' flags (--max-width) name it.
const char* contest_limit_key(ContestLimit limit);

struct ContestRequest {
  MachineKind machine = MachineKind::hinged;
  double projectile_mass = 0;  ///< m [kg], as the contest gives it
  double beam_mass_per_length = 0;  ///< the beam's mass per metre [kg/m]: mb = this times L1 + L2
  double theta_i_deg = standard_theta_i_deg;  ///< held [deg]
  Material material{};
  ShotSettings settings{};  ///< the release (its criterion's optimum, or a given one), air, target level
  bool efficiency = false;  ///< maximise eps instead of the range
  ContestLimits limits{};
  /// The counterweight's box, width and height [m], both or neither: its inertia (but the
  /// floating arm's) and the height its bottom hangs below its centre.
  std::optional<double> box_width, box_height;
  /// The least clearance of the counterweight (its box's bottom) above the ground [m], in the
  /// machine's geometry and in the shot (Verification::Clearance): 0 unless a margin is asked for.
  double min_clearance = 0;
  /// The builder's parts of the sling and its pin (EngineParts), on every engine tried: the
  /// rope's and the pouch's mass [kg], and mu of the loop on the release pin (scaled), which
  /// gives the pin to bend with the engine.
  double rope_mass = 0, pouch_mass = 0, pin_friction = 0;
  /// The ball's diameter [m], where given: with its mass, its density in air (Engine::projectile_diameter).
  std::optional<double> projectile_diameter;
  /// Whether to find what relaxing each limit given gains: a search each, most of a contest's
  /// cost. Without, the engine of the contest's own searches (which a gain's search may better),
  /// its gains and binds left empty.
  bool gains = true;
};

/// A limit the engine stands at: within this fraction of it (the clearance: of the engine's
/// height above its least).
inline constexpr double at_limit_tolerance = 1e-3;
/// A limit binds where relaxing it by 10 % gains more than this fraction of the objective: above
/// the resolution of the search, which meets a limit to about 1e-6 of it.
inline constexpr double binding_gain = 1e-5;
/// Within this fraction of the best, a local search reached the best (ContestEngine::start_objectives).
inline constexpr double reached_best = 1e-4;
/// How many of the first `count` local searches' ends reached `best` (to reached_best of it).
inline int searches_at_best(const std::vector<std::optional<double>>& ends, double best, std::size_t count) {
  int at_best = 0;
  for (std::size_t k = 0; k < count && k < ends.size(); ++k) at_best += ends[k] && *ends[k] >= best * (1 - reached_best);
  return at_best;
}
/// The search's starts: the paper's proportions and the best of a Sobol sample of this many points.
inline constexpr int contest_sample_size = 64;
/// The local searches of a contest: from the paper's proportions and the best five of the sample.
inline constexpr int contest_local_searches = 6;
/// Then hops from the best (monotone basin hopping): up to this far in each log of the point,
inline constexpr double contest_hop = 0.1;
/// until this many hops in a row gain nothing,
inline constexpr int contest_fruitless_hops = 6;
/// or this many in all.
inline constexpr int contest_most_hops = 40;

/// One engine of a contest, with what each limit measures on it (in the limits' units) and
/// whether it meets them all.
struct ContestEngine {
  Engine engine;
  Verification verification;
  std::array<double, contest_limit_count> measured{};
  double clearance = 0;  ///< the smaller of Verification::Clearance's two [m]
  /// The limits the engine stands at (at_limit_tolerance), and those that bind: relaxing them by
  /// 10 % gains (binding_gain), whether the engine stands at them or not. None for the engines of a
  /// Pareto front.
  std::array<bool, contest_limit_count> at_limit{}, binds{};
  /// For each limit given, the objective (R [m] or eps) that the contest gains
  /// with it 10 % looser, the others held: what that limit costs (0 where it does not bind).
  std::array<std::optional<double>, contest_limit_count> gain_if_relaxed{};
  /// The same for the least clearance the request asks for: whether the counterweight stands at
  /// it (or at the ground), and what asking 10 % less gains (none at the ground, 0 asked for).
  bool clearance_at_limit = false;
  std::optional<double> gain_if_clearance_relaxed;
  double objective = 0;  ///< R [m] or eps
  /// What each local search of the contest reached, in the order run (none: no engine that meets
  /// the limits): how sure the search is of its best.
  std::vector<std::optional<double>> start_objectives;
  /// How many local searches the contest ran from its starts (at most contest_local_searches:
  /// fewer where the sample has fewer distinct points), first in start_objectives; its hops from
  /// its best (where fewer than two of them reached it), and how many of those found a better
  /// engine, which follow them there.
  int local_searches = 0, hops = 0, hops_gained = 0;
  int shots = 0;  ///< of the search that found it
  /// Whether a pin bent to the verification's pin_to_bend_deg makes its release (where not, a note
  /// says why: pin_release_note); the Pareto front's engines are not asked.
  bool pin_releases = true;
};

/// The measures of the limits on `engine` under `settings`: the bounding box of the pivot, the
/// beam, the counterweight (its box, upright, where its sides are given), the sling and the
/// projectile from rest through the release (the
/// base at the bottom, sampled every 0.02 (L2/g)^(1/2) and at the release), its counterweight
/// mass, its peak axle load, and the projectile's peak acceleration up to the release (sampled
/// alike, and no less than the sling's refined peak pull allows).
/// With `least_sling_pull`, the sling's least pull on the projectile up to the release, sampled
/// alike, in the projectile's weights (< 0: the sling goes slack).
std::array<double, contest_limit_count> contest_measures(const Engine& engine, const ShotSettings& settings, Verification* verification = nullptr,
                                                         double* least_sling_pull = nullptr);

/// The best engine (docs/machines.md): coarse local searches by COBYLA (NLopt) in the logs of
/// L1/L2, L4/L1, m/M, L2 (and L3/L2 for the hinged machine; the others hold their counterweight
/// at the short arm's end), each limit a constraint and M bounded by its limit, from the paper's
/// proportions and the best five of 64 points of a Sobol sequence; those within 1 % of the best
/// refined; where fewer than two reached the best, hops from it (contest_hop); the best engine
/// that meets the limits over them all. Every candidate is shot once. An engine whose sling goes
/// slack before the release is none, but the searches see how far it goes slack, as a limit.
/// Then, with request.gains, for each limit given, a search with that limit 10 %
/// looser, from the contest's own ends and from starts of its own (hopping as the contest's own
/// does): what it gains, and whether it binds. No engine returned strikes the ground: each meets the request's clearance. Throws
/// Error(bad_number) for a request no engine could meet (no projectile, no beam), Error(out_of_range)
/// when no engine meets the limits, naming the fewest limits that cannot be met together.
ContestEngine contest_optimum(const ContestRequest& request);

/// The machines a contest designs by search; the whipper is not (docs/machines.md).
inline constexpr MachineKind searched_machines[] = {MachineKind::hinged, MachineKind::fixed, MachineKind::floating_arm};

/// One machine's best engine within a contest's limits, or why that machine has none.
struct MachineBest {
  MachineKind machine;
  std::optional<ContestEngine> best;  ///< none when the machine is refused
  std::optional<Error> refusal;  ///< contest_optimum's refusal of this machine
};

/// Each of searched_machines' best (contest_optimum) for `request` with its machine replaced,
/// side by side: one machine's refusal does not stop the others.
std::vector<MachineBest> contest_each_machine(ContestRequest request);

/// The limits an engine is held to outside a contest (compare under a contest's limits): the
/// five, each optional, and the least clearance of the counterweight above the ground [m].
struct LimitsToMeet {
  ContestLimits limits{};
  double min_clearance = 0;
  bool any() const;  ///< whether any is given
};

/// Refuses (Error(bad_number), naming the flag) a limit that is not positive and finite, and a
/// clearance outside 0 to 1e6 m: contest's and compare's one rule.
void check_limits_to_meet(const LimitsToMeet& to_meet);

/// One limit an engine breaks: its key ("max_axle_load", ..., "min_clearance"), what the engine
/// measures and the limit, in the limit's units (contest_measures; the clearance [m]).
struct BrokenLimit {
  const char* key;
  double measured, limit;
};

/// The limits of `to_meet` that `engine` breaks under `settings`, from one shot
/// (contest_measures; the clearance: the smaller of Verification::Clearance's two).
std::vector<BrokenLimit> broken_limits(const Engine& engine, const ShotSettings& settings, const LimitsToMeet& to_meet);

/// The fewest limits of the request that no engine the search finds meets together; empty when
/// it meets them all.
std::vector<ContestLimit> conflicting_limits(const ContestRequest& request);

/// The Pareto front of the objective against the peak axle load: `points` optima, the axle's
/// limit from a fifth of the unlimited optimum's load up to that load, each under the request's
/// other limits; those that meet their limits, by rising axle load.
std::vector<ContestEngine> pareto_front(const ContestRequest& request, int points);

/// The contest's best and its Pareto front of `points` optima (none for 0), from one set of
/// shots: the front is searched first, so that the best adopts an engine the front's searches
/// shot that meets every limit and throws farther (as it adopts a gain's, contest_optimum), and
/// the front holds the best at its load. Refuses `points` outside 2 to 200 as pareto_front does.
struct ContestResult {
  ContestEngine best;
  std::vector<ContestEngine> front;
};
ContestResult contest_with_front(const ContestRequest& request, int points);

}  // namespace trebuchet
