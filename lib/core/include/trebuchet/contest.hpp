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
};

/// One engine of a contest, with what each limit measures on it (in the limits' units) and
/// whether it meets them all.
struct ContestEngine {
  Engine engine;
  Verification verification;
  std::array<double, contest_limit_count> measured{};
  double clearance = 0;  ///< the smaller of Verification::Clearance's two [m]
  /// For each limit that binds (contest_binds), the objective (R [m] or eps) that relaxing it by
  /// 10 % gains, the others held: what that limit costs. None for the others, and for the
  /// engines of a Pareto front.
  std::array<std::optional<double>, contest_limit_count> gain_if_relaxed{};
  double objective = 0;  ///< R [m] or eps
  bool feasible = false;
  int shots = 0;  ///< of the search that found it
};

/// The measures of the limits on `engine` under `settings`: the bounding box of the pivot, the
/// beam, the counterweight (its box, upright, where its sides are given), the sling and the
/// projectile from rest through the release (the
/// base at the bottom, sampled every 0.02 (L2/g)^(1/2) and at the release), its counterweight
/// mass, its peak axle load, and the projectile's peak acceleration up to the release.
std::array<double, contest_limit_count> contest_measures(const Engine& engine, const ShotSettings& settings, Verification* verification = nullptr);

/// The best engine: Nelder-Mead in the logs of L1/L2, L4/L1, m/M, L2 (and L3/L2 for the hinged
/// machine; the others hold their counterweight at the short arm's end), the limits as exact
/// penalties, M at its limit where that binds, then the size pushed to the largest that meets
/// the limits (bisection to 1e-10), so that a limit that binds is met with equality. Throws
/// No engine returned strikes the ground: each meets the request's clearance. Throws
/// Error(bad_number) for a request no engine could meet (no projectile, no beam), Error(out_of_range)
/// when no engine meets the limits, naming the fewest limits that cannot be met together.
ContestEngine contest_optimum(const ContestRequest& request);

/// Whether `limit` binds on `engine`: given, and met to within 1e-4 of it (the search meets an
/// active limit to that, docs/machines.md).
bool contest_binds(const ContestEngine& engine, const ContestRequest& request, ContestLimit limit);

/// The fewest limits of the request that no engine the search finds meets together; empty when
/// it meets them all.
std::vector<ContestLimit> conflicting_limits(const ContestRequest& request);

/// The Pareto front of the objective against the peak axle load: `points` optima, the axle's
/// limit from a fifth of the unlimited optimum's load up to that load, each under the request's
/// other limits; those that meet their limits, by rising axle load.
std::vector<ContestEngine> pareto_front(const ContestRequest& request, int points);

}  // namespace trebuchet
