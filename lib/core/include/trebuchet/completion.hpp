// An engine completed from what a source attests (trebuchet-verify complete): the attested
// quantities are kept exactly, the others are chosen to maximise Q (section 5) or the range,
// and the beam follows from the allowed bending and the wood (eq:bend_L2, eq:BeamMass) unless
// its mass or diameter is attested. θi and F take the paper's standard, 30 deg and 2/3, unless
// attested or implied (θi by H and L1).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/verification.hpp"

namespace trebuchet {

/// What a source gives, in SI units; any subset.
struct Attested {
  std::optional<double> Lb, L1, L2, H, L4;  ///< beam length, beam sections, pivot height, sling [m]
  std::optional<double> M, m, mb;  ///< counterweight, projectile, beam [kg]
  std::optional<double> D;  ///< beam diameter [m]
  std::optional<double> l;  ///< beam ratio L1/L2, scaled
  std::optional<double> theta_i_deg;  ///< [deg]
  std::optional<double> F;  ///< arm fraction (L2 + L3)/H, scaled
  /// The counterweight's drop: the fall of its centre from rest to its lowest point, the short
  /// arm straight down, L2 (1 + cos theta_i) (eq:DU) [m]. Sources give it, not L2.
  std::optional<double> drop;
};

struct CompletionRequest {
  Attested attested;
  Material material{};  ///< beta2 and the wood: the beam's D and mb when they are not attested
  ShotSettings settings{};  ///< the release criterion (Q, or the range), air, target level, integrator
  /// The engine's parts as built that do not depend on the values searched: the pins' friction,
  /// the counterweight's own inertia, the rope. A beam as built is refused: complete builds a
  /// uniform beam from the attested values (a beam as built is checked by a shot).
  EngineParts parts{};
  /// The projectile's diameter [m], where known: with m its density in air (Engine::projectile_diameter).
  std::optional<double> projectile_diameter;
};

struct Completion {
  Engine engine;  ///< with every attested value as given
  Verification verification;  ///< its shot under the request's settings
  std::vector<std::string> attested;  ///< the quantities given, e.g. "Lb", "M", "m"
  std::vector<std::string> implied;  ///< those that follow from them, e.g. "L2" from Lb and L1
  std::vector<std::string> chosen;  ///< those the search chose
  int simulations = 0;
  /// The calculator's optimum for the engine's own capacity in vacuum at the base's level, to
  /// show how far the chosen values sit from an optimal engine; or why there is none.
  std::optional<OptimalEngine> calculator;
  std::string calculator_note;  ///< why there is none, naming settings as "{{name}}" (error.hpp)
};

/// Completes the engine. Throws Error(usage) for a subset that conflicts (naming the
/// quantities and their values) or that leaves the objective unbounded: no attested length or
/// neither M nor m (Q grows as the engine shrinks or the counterweight grows), or the range
/// with a free M or m. Error(bad_number) for a value out of its range, and Error(out_of_range) when no
/// choice of the free quantities gives a working engine.
Completion complete_engine(const CompletionRequest& request);

}  // namespace trebuchet
