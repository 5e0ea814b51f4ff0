// The what-if sweep (app/run/what_if.hpp, trebuchet-verify sweep, api::sweep): its values, its
// refusals, and that each point is the shot of its engine alone, bit for bit.
#include <catch2/catch.hpp>

#include <cmath>

#include "trebuchet/app/api/api.hpp"
#include "trebuchet/app/run/what_if.hpp"
#include "trebuchet/sweep.hpp"

using namespace trebuchet;
using json = nlohmann::json;

namespace {

// The engine of the paper's tab:SketchBook-I row that docs/verifier.md shoots (R 451 m).
json sample_engine() { return {{"L1", "6.13m"}, {"L2", "1.08m"}, {"F", 1}, {"L4", "5.8m"}, {"M", "14.3t"}, {"m", "100kg"}, {"mb", "660kg"}}; }

}  // namespace

TEST_CASE("a sweep's values run evenly from one end to the other, both exact", "[what_if]") {
  const std::vector<double> v = what_if_values(2, 5, 40);
  REQUIRE(v.size() == 40);
  CHECK(v.front() == 2);
  CHECK(v.back() == 5);
  // Evenly spaced: every step is (5 - 2)/39 to the rounding of the doubles (a few ulps of 5).
  for (std::size_t i = 1; i < v.size(); ++i) CHECK(std::abs(v[i] - v[i - 1] - 3.0 / 39) < 1e-14);
  CHECK_THROWS_AS(what_if_values(2, 5, 1), Error);
  CHECK_THROWS_AS(what_if_values(2, 5, max_what_if_points + 1), Error);
  CHECK_THROWS_AS(what_if_values(5, 2, 10), Error);
  CHECK_THROWS_AS(what_if_values(2, INFINITY, 10), Error);
}

TEST_CASE("the value a sweep varies is an engine's, with its range, or refused with the fix", "[what_if]") {
  const WhatIf w = parse_what_if("L4=2m..500cm", 40, "--vary");
  CHECK(std::string(w.field->key) == "L4");
  CHECK(w.from == 2);
  CHECK(w.to == 5);
  CHECK(std::string(parse_what_if("--M=10t..20t", 5, "--vary").field->key) == "M");  // its flag
  CHECK(std::string(parse_what_if("pin_angle=30..50", 5, "--vary").field->key) == "pin_angle_deg");  // an alias
  const auto message = [](const char* text) {
    try {
      parse_what_if(text, 21, "--vary");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("not refused");
  };
  CHECK_THAT(message("R=100m..200m"), Catch::Contains("no value of an engine to vary") && Catch::Contains("L4"));  // a capacity is no engine's value
  CHECK_THAT(message("wood_density=500..900"), Catch::Contains("no value of an engine to vary"));  // the material is held
  CHECK_THAT(message("L4=2m"), Catch::Contains("gives no range"));
  CHECK_THAT(message("L4"), Catch::Contains("gives no range"));
  CHECK_THAT(message("L4=5m..2m"), Catch::Contains("low..high"));
  CHECK_THAT(message("L4=2kg..5kg"), Catch::Contains("kg"));
}

TEST_CASE("each point of a sweep is the shot of its engine alone, bit for bit", "[what_if]") {
  // The sweep's claim (issue 37): a point is a full shot at the chosen release, not an
  // interpolation or a cheaper shot. So the whole record, every number in it, must equal the
  // answer of api::shot for the engine with the point's value, as its shortest round-trip text.
  const struct {
    const char* vary;
    const char* key;
    double from, to;  // SI
  } sweeps[] = {{"L4=2m..8m", "L4", 2, 8},
                {"M=8t..20t", "M", 8000, 20000},
                {"pin_angle=20..60", "pin_angle_deg", 20, 60},
                {"trough_friction=0..0.4", "trough_friction", 0, 0.4}};
  for (const auto& sweep : sweeps) {
    const std::vector<double> values = what_if_values(sweep.from, sweep.to, 7);
    for (const bool air : {false, true}) {
      const json answer = api::sweep({{"design", sample_engine()}, {"vary", sweep.vary}, {"points", 7}, {"air", air}, {"release", "range"}});
      CHECK(answer["vary"] == sweep.key);
      REQUIRE(answer["points"].size() == values.size());
      for (std::size_t i = 0; i < values.size(); ++i) {
        const json& point = answer["points"][i];
        INFO(sweep.vary << " at " << values[i] << (air ? " in air" : " in vacuum"));
        REQUIRE_FALSE(point.contains("error"));
        json design = sample_engine();
        design[sweep.key] = values[i];
        const json single = api::shot({{"design", design}, {"air", air}, {"release", "range"}});
        CHECK(point.dump() == single.dump());
      }
    }
  }
}

TEST_CASE("a sweep of a release reads its points off one trajectory, each the shot given it alone, refusals too", "[what_if]") {
  // A release changes nothing before it, so the points of a sweep of pin_angle, release_angle or
  // release_time share phases I and II (check_released_designs). Each point must still be the
  // shot of the engine given that release alone, bit for bit, and a point that shot refuses (in
  // the trough, never reached, thrown backward, an energy drift past the limit further on) must
  // keep that shot's message, word for word. The sweeps run past both ends of the window.
  const json whipper = {{"machine", "whipper"}, {"L1", "4m"}, {"L2", "2m"},   {"L3", "4m"}, {"L4", "4m"},
                        {"M", "100kg"},         {"m", "3kg"}, {"mb", "10kg"}, {"H", "5m"}};
  const struct {
    json design;
    const char* vary;
    const char* key;
    double from, to;  // SI: deg or s
    json options;  // the request's settings
  } sweeps[] = {
      {sample_engine(), "release_time=0.2s..3s", "release_time", 0.2, 3, json::object()},
      {sample_engine(), "release_angle=-170..179", "release_angle_deg", -170, 179, {{"air", true}}},
      {sample_engine(), "pin_angle=-170..179", "pin_angle_deg", -170, 179, {{"release", "range"}}},
      // rk2 at 5e-8 drifts past 1e-8 of Delta U partway: four points shoot, the next fails on the
      // drift up to its own release, not on the drift of the trajectory stepped further for later ones.
      {sample_engine(), "release_time=0.5s..1.6s", "release_time", 0.5, 1.6, {{"stepper", "rk2"}, {"rtol", 5e-8}, {"atol", 5e-8}}},
      {whipper, "release_angle=-170..179", "release_angle_deg", -170, 179, json::object()},
      {whipper, "pin_angle=-170..179", "pin_angle_deg", -170, 179, json::object()},
  };
  for (const auto& sweep : sweeps) {
    json request = sweep.options;
    request["design"] = sweep.design, request["vary"] = sweep.vary, request["points"] = 15;
    const json answer = api::sweep(request);
    const std::vector<double> values = what_if_values(sweep.from, sweep.to, 15);
    int shot = 0, refused = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      INFO(sweep.vary << " " << sweep.options.dump() << " at " << values[i]);
      json single = sweep.options;
      single["design"] = sweep.design;
      single["design"][sweep.key] = values[i];
      const json& point = answer["points"][i];
      json alone;
      try {
        alone = api::shot(single);
        ++shot;
      } catch (const Error& e) {
        alone = {{"error", api::error_json(e)["error"]}, {sweep.key, values[i]}};
        ++refused;
      }
      CHECK(point.dump() == alone.dump());
    }
    std::printf("%s %s: %d points shot, %d refused, as alone\n", sweep.vary, sweep.options.dump().c_str(), shot, refused);
    CHECK(shot > 0);
  }
}

TEST_CASE("a sweep over the pin angle never beats the optimum, and brackets it", "[what_if]") {
  // An independent fact of the release search: the range-optimal release maximises R over every
  // release, so no pin angle of the sweep may reach farther than the shot at the optimum, and the
  // best point lies next to the optimum's pin angle. The 1e-12 is the optimum's own convergence
  // (a parabola's vertex in solve_1d, far below the digits a range is quoted to).
  const json best = api::shot({{"design", sample_engine()}, {"release", "range"}});
  const double optimum_R = best["R"], optimum_pin = best["pin_angle_at_release_deg"];
  const json answer = api::sweep({{"design", sample_engine()}, {"vary", "pin_angle=20..60"}, {"points", 41}, {"release", "range"}});
  double best_R = 0, best_pin = 0;
  for (const json& point : answer["points"]) {
    REQUIRE_FALSE(point.contains("error"));
    CHECK(point["R"].get<double>() <= optimum_R * (1 + 1e-12));
    if (point["R"].get<double>() > best_R) best_R = point["R"], best_pin = point["pin_angle_at_release_deg"];
  }
  std::printf("pin-angle sweep: best point %.10g m at %.4g deg, the optimum %.10g m at %.4g deg\n", best_R, best_pin, optimum_R, optimum_pin);
  CHECK(std::abs(best_pin - optimum_pin) <= 0.5 + 1e-9);  // the grid's step is 1 deg: the nearest point lies within half of it
}

TEST_CASE("a sweep keeps the points that fail in their place", "[what_if]") {
  // M = 1 t cannot lift this beam (mu_b (l - 1)/2 > 1, eq:DU): that point fails, the others shoot.
  const json answer = api::sweep({{"design", sample_engine()}, {"vary", "M=1t..20t"}, {"points", 3}});
  REQUIRE(answer["points"].size() == 3);
  CHECK(answer["points"][0]["M"] == 1000.0);
  CHECK_THAT(answer["points"][0]["error"].get<std::string>(), Catch::Contains("cannot turn"));
  CHECK(answer["points"][1].contains("R"));
  CHECK(answer["points"][2].contains("R"));
  CHECK_THROWS_AS(api::sweep({{"design", sample_engine()}, {"vary", "M=1t..20t"}, {"points", 1}}), Error);
  CHECK_THROWS_AS(api::sweep({{"design", sample_engine()}, {"vary", "M=1t..20t"}, {"points", 2.5}}), Error);
  CHECK_THROWS_AS(api::sweep({{"design", sample_engine()}}), Error);
}
