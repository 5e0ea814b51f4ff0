// trebuchet-verify complete: an engine from what a source attests (issue 14). Attested values
// are kept to 1e-9, the free ones are the best choice, and conflicts are named.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <iostream>

#include "trebuchet/completion.hpp"
#include "trebuchet/error.hpp"

using namespace trebuchet;

namespace {
void kept(double value, double attested, const char* name) {
  INFO(name << ": " << value << " against the attested " << attested);
  CHECK(std::abs(value / attested - 1) <= 1e-9);
}
}  // namespace

TEST_CASE("complete keeps every attested value and verifies the engine", "[complete]") {
  SECTION("a beam length, the counterweight and the stones (the Catalan engines)") {
    CompletionRequest r;
    r.attested.Lb = 9.5, r.attested.M = 3000, r.attested.m = 50;
    const Completion c = complete_engine(r);
    kept(c.engine.L1 + c.engine.L2, 9.5, "Lb");
    kept(c.engine.M, 3000, "M");
    kept(c.engine.m, 50, "m");
    CHECK(c.chosen == std::vector<std::string>{"L1", "L2", "L4"});
    CHECK(c.verification.energy_drift < 1e-9);
    CHECK(c.verification.Q > 0);
  }
  SECTION("a beam length and ratio, the angle and the stones (Villard's sketch)") {
    CompletionRequest r;
    r.attested.Lb = 10, r.attested.l = 4.5, r.attested.theta_i_deg = 25, r.attested.m = 100;
    const Completion c = complete_engine(r);
    kept(c.engine.L1 / c.engine.L2, 4.5, "l");
    kept(c.engine.L1 + c.engine.L2, 10, "Lb");
    kept(c.engine.theta_i_deg, 25, "theta_i");
    kept(c.engine.m, 100, "m");
  }
  SECTION("the pivot height with the long arm fixes theta_i") {
    CompletionRequest r;
    r.attested.H = 6.15, r.attested.L1 = 8.6974, r.attested.L2 = 3.3026, r.attested.M = 10000, r.attested.m = 100, r.attested.mb = 2000,
    r.attested.F = 0.93;
    r.settings.criterion.release = Release::range;
    const Completion c = complete_engine(r);
    // Denny's engine: H = 6.15 m with L1 = 8.6974 m is theta_i = 45 deg to the printed digits.
    CHECK(std::abs(c.engine.theta_i_deg - 45) < 0.01);
    kept(pivot_height(c.engine), 6.15, "H");
    kept(c.engine.mb, 2000, "mb");
    CHECK(c.chosen == std::vector<std::string>{"L4"});
  }
  SECTION("the counterweight's drop fixes L2 (issue 64: a pumpkin team's ten-foot drop)") {
    // With a massless beam Delta U is the counterweight's fall alone (eq:DU): M g drop.
    CompletionRequest r;
    r.attested.drop = 3.048, r.attested.M = 998, r.attested.m = 4.1, r.attested.mb = 0;
    const Completion c = complete_engine(r);
    kept(potential_energy_drop(c.engine) / (998 * c.engine.material.g), 3.048, "drop");
    kept(c.engine.L2, 3.048 / (1 + std::cos(M_PI / 6)), "L2");
    CHECK(c.attested == std::vector<std::string>{"M", "m", "mb", "drop"});
    CHECK(c.chosen == std::vector<std::string>{"L1", "L4"});
    // With the beam's length and an angle: L1 = Lb - L2.
    r.attested.Lb = 12, r.attested.theta_i_deg = 40;
    const Completion with_beam = complete_engine(r);
    kept(potential_energy_drop(with_beam.engine) / (998 * c.engine.material.g), 3.048, "drop");
    kept(with_beam.engine.L1 + with_beam.engine.L2, 12, "Lb");
    CHECK(with_beam.chosen == std::vector<std::string>{"L4"});
  }
  SECTION("a beam mass and diameter fix the beam's length (eq:BeamMass)") {
    CompletionRequest r;  // 470 kg of wood of 700 kg/m3, 0.3 m across: Lb = 470/(700 pi/4 0.3^2) = 9.4986 m
    r.attested.mb = 470, r.attested.D = 0.3, r.attested.M = 3000, r.attested.m = 50;
    const Completion c = complete_engine(r);
    kept(c.engine.L1 + c.engine.L2, 470 / (700 * M_PI / 4 * 0.09), "Lb");
    kept(c.engine.mb, 470, "mb");
    kept(c.engine.D, 0.3, "D");
    CHECK(std::find(c.implied.begin(), c.implied.end(), "Lb (from mb and D, eq:BeamMass)") != c.implied.end());
  }
}

TEST_CASE("the free values are the best: no small change of one raises Q", "[complete]") {
  // The simplex stops at a size of 1e-5 in log coordinates; a 2 % step of any chosen quantity
  // is far beyond that, so it must not raise Q by more than the objective's flatness allows
  // (a 2 % step from a smooth maximum changes Q by O(4e-4) of itself, and only downward).
  CompletionRequest r;
  r.attested.Lb = 9.5, r.attested.M = 3000, r.attested.m = 50;
  const Completion c = complete_engine(r);
  const double best = c.verification.Q;
  for (double factor : {0.98, 1.02}) {
    CompletionRequest moved = r;
    moved.attested.L1 = c.engine.L1 * factor;
    moved.attested.L4 = c.engine.L4;
    CHECK(complete_engine(moved).verification.Q <= best * (1 + 1e-6));
    moved.attested.L1 = c.engine.L1;
    moved.attested.L4 = c.engine.L4 * factor;
    CHECK(complete_engine(moved).verification.Q <= best * (1 + 1e-6));
  }
  std::cout << "Catalan engine (Lb 9.5 m, M 3 t, m 50 kg): l = " << c.engine.L1 / c.engine.L2 << ", L4 = " << c.engine.L4 << " m, Q = " << best
            << ", R = " << c.verification.capacity.R << " m\n";
}

TEST_CASE("conflicting or unbounded subsets are named errors", "[complete]") {
  auto message = [](const Attested& a, Release release = Release::quality) {
    CompletionRequest r;
    r.attested = a;
    r.settings.criterion.release = release;
    try {
      complete_engine(r);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Attested a;
  a.Lb = 10, a.L1 = 8, a.L2 = 2.5, a.M = 3000, a.m = 50;
  CHECK_THAT(message(a), Catch::Contains("L1 = 8 m, but Lb - L2 = 7.5 m"));
  a = Attested{};
  a.Lb = 10, a.L1 = 8, a.D = 0.5, a.mb = 100, a.M = 3000, a.m = 50;
  CHECK_THAT(message(a), Catch::Contains("mb = 100 kg and D = 0.5 m make a beam 0.727565 m long by eq:BeamMass"));
  // Without L1 and L2 the diameter still contradicts the mass, through Lb (issue 38: it was accepted).
  a.L1.reset();
  CHECK_THAT(message(a), Catch::Contains("make a beam 0.727565 m long by eq:BeamMass with wood of 700 kg/m3, but Lb = 10 m"));
  a = Attested{};
  a.Lb = 10, a.m = 50;
  CHECK_THAT(message(a, Release::range), Catch::Contains("give M and m for quality range"));
  a = Attested{};
  a.L1 = 5, a.H = 6, a.M = 3000, a.m = 50;
  CHECK_THAT(message(a), Catch::Contains("the pivot height H = 6 m is not below the long arm's length"));
  a = Attested{};
  a.L2 = 2, a.drop = 3.048, a.M = 3000, a.m = 50;  // 3.048/(1 + cos 30 deg) = 1.63342 m
  CHECK_THAT(message(a), Catch::Contains("drop/(1 + cos theta_i) = 1.63342 m with the standard theta_i = 30 deg, but L2 = 2 m"));
  a = Attested{};
  a.Lb = 1.5, a.drop = 3.048, a.M = 3000, a.m = 50;
  CHECK_THAT(message(a), Catch::Contains("Lb = 1.5 m is not longer than drop/(1 + cos theta_i) = 1.63342 m"));
}
