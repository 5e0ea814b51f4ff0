// Calibration over unknowns (issue 48, calibration_run.hpp): a friction known by construction is
// found again as the median of the draws, each unknown moves the fit the way the physics says,
// and a range that reaches what no engine has is refused before the run.
#include <catch2/catch.hpp>
#include <cstdio>

#include "engines.hpp"
#include "trebuchet/app/run/calibration_run.hpp"
#include "trebuchet/error.hpp"

using namespace trebuchet;
using namespace trebuchet::testing;

namespace {

// The laboratory engine's values as a file gives them, its pins 2 cm and 1 cm.
DesignValues laboratory_values() {
  DesignValues v;
  v.L1 = 0.975, v.L2 = 0.25, v.L3 = 0.515, v.L4 = 0.87, v.theta_i_deg = 31.513, v.M = 53.9, v.m = 0.717, v.mb = 4.86;
  v.beam_cm = 0.465, v.beam_inertia = 1.85, v.axle_radius = 0.02, v.hinge_radius = 0.01;
  return v;
}

SpreadInput unknown(const char* name, std::optional<double> DesignValues::*member, UnitDimension dimension, double low, double high) {
  return {{name, dimension, {Spread::Kind::uniform, low, high}}, member, nullptr};
}

}  // namespace

TEST_CASE("calibration over unknowns finds a known friction, and a thicker pin asks less", "[real][calibrate]") {
  // The engine with mu = 0.3 at both pins throws R; drawn over an axle of 1.8 to 2.2 cm, the
  // fits spread around 0.3: the axle's friction torque goes as mu r, so a draw at r asks about
  // 0.3 (2 cm/r) at the axle, and less than that in all (the hinge's share is not drawn): the
  // median within 5 % of 0.3, the fit falling with r (rank correlation near -1: nothing else
  // varies; the measured range has no uncertainty here).
  Engine engine = laboratory_engine();
  engine.parts.axle = {0.3, 0.02}, engine.parts.hinge = {0.3, 0.01};
  const double R = verify_engine(engine, ShotSettings{}).capacity.R;
  CalibrationRunInputs in;
  in.request.values = laboratory_values();
  in.request.spreads = {unknown("--axle-radius", &DesignValues::axle_radius, UnitDimension::length, 0.018, 0.022)};
  in.measured = {R, 0};
  in.samples = 40;
  const CalibrationRun run = calibrate_over_unknowns(in);
  std::printf("known friction 0.3: fitted percentiles %.4g %.4g %.4g %.4g %.4g, rank correlation with the axle %.3f\n", run.percentiles[0],
              run.percentiles[1], run.percentiles[2], run.percentiles[3], run.percentiles[4], run.moves[0].rho);
  CHECK(run.summary.values.size() == 40u);
  CHECK(std::abs(run.percentiles[2] / 0.3 - 1) < 0.05);
  CHECK(run.percentiles[0] < 0.3);
  CHECK(run.percentiles[4] > 0.3);
  CHECK(run.moves[0].rho < -0.95);
  CHECK(run.moves[0].resolved());  // 40 samples: z's 95 % half-width 0.33 leaves -0.95 far from 0
  CHECK(run.share.fraction == 1);  // every fit inside the handbooks' 0.1 to 0.5
  const std::string table = calibration_run_table(run);
  CHECK(table.find("Plausible:") != std::string::npos);
}

TEST_CASE("calibration over unknowns says when no plausible friction explains the range", "[real][calibrate]") {
  // A range far shorter than any pin friction up to 2 gives (half the frictionless one):
  // every draw fails as "friction alone does not explain it", and the sentence says not plausible.
  CalibrationRunInputs in;
  in.request.values = laboratory_values();
  in.request.spreads = {unknown("--pin-angle", &DesignValues::pin_angle_deg, UnitDimension::angle, 30, 40)};
  in.measured = {20, 1};
  in.samples = 10;
  const CalibrationRun run = calibrate_over_unknowns(in);
  CHECK(run.summary.values.empty());
  CHECK(run.share.fraction == 0);
  REQUIRE(run.summary.failures.size() == 1);
  CHECK(run.summary.failures.front().reason.rfind("friction alone does not explain it", 0) == 0);
  CHECK(calibration_run_table(run).find("Not plausible:") != std::string::npos);
}

TEST_CASE("a range of unknowns that reaches what no engine has is refused before the run", "[real][calibrate]") {
  const auto refusal = [](SpreadInput spread, bool hinge_pin = true) {
    CalibrationRunInputs in;
    in.request.values = laboratory_values();
    if (!hinge_pin) in.request.values.hinge_radius.reset();  // one pin's radius is enough for a fit; none is not
    in.request.spreads = {spread};
    in.measured = {34.4, 1.5};
    try {
      calibrate_over_unknowns(in);
    } catch (const Error& e) {
      CHECK(e.kind() == ErrorKind::bad_number);
      return e.message([](std::string_view key) { return std::string(key); });
    }
    return std::string("accepted");
  };
  CHECK(refusal(unknown("--axle-radius", &DesignValues::axle_radius, UnitDimension::length, 0, 0.01), false)
            .find("--axle-radius uniform 0..0.01 m reaches 0") == 0);
  CHECK(refusal(unknown("--pouch-mass", &DesignValues::pouch_mass, UnitDimension::mass, -0.1, 0.1)).find("pouch_mass") != std::string::npos);
  SpreadInput normal = unknown("--hinge-radius", &DesignValues::hinge_radius, UnitDimension::length, 0, 0);
  normal.input.spread = {Spread::Kind::normal, 0.01, 0.003};
  CHECK(refusal(normal).find("4 sigma out") != std::string::npos);
}
