// The one engine schema (schema.hpp): every writer's engine reads back as the same engine,
// material included, so that the programs, the sweep parts and the tables can be chained.
#include <catch2/catch.hpp>

#include "engines.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/records/shot_record.hpp"

using namespace trebuchet;

// Numbers are written to round-trip (nlohmann's shortest form), L3 is written and read as
// itself: the engine comes back bit for bit.
TEST_CASE("an engine written and read back is the same engine, material included", "[schema]") {
  Engine e = testing::denny_standard();
  e.D = 0.41;
  e.material = {1.0 / 200, 10e9, 600, 1.62};
  nlohmann::ordered_json json;
  write_engine(json, e);
  const Engine back = read_engine(nlohmann::json::parse(json.dump()), "design").engine;
  CHECK(back.L1 == e.L1);
  CHECK(back.L2 == e.L2);
  CHECK(back.L3 == e.L3);
  CHECK(back.L4 == e.L4);
  CHECK(back.D == e.D);
  CHECK(back.M == e.M);
  CHECK(back.m == e.m);
  CHECK(back.mb == e.mb);
  CHECK(back.theta_i_deg == e.theta_i_deg);
  CHECK(back.material.beta2 == e.material.beta2);
  CHECK(back.material.youngs_modulus == e.material.youngs_modulus);
  CHECK(back.material.wood_density == e.material.wood_density);
  CHECK(back.material.g == e.material.g);
}

// The calculator's design carries its material: beta2 = 1/200 written by design_json is read
// back by the verifier's reader (issue 10: it was refitted at 1/300 before).
TEST_CASE("the calculator's design reads back with its beta2", "[schema]") {
  DesignRequest request;
  request.first = {Quantity::R, 300};
  request.second = {Quantity::T, 60e3};
  request.material.beta2 = 1.0 / 200;
  const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), request);
  const EngineRecord record = read_engine(nlohmann::json::parse(design_json(design).dump()), "design");
  CHECK(record.engine.material.beta2 == 1.0 / 200);
  CHECK(record.engine.L1 == design.engine.L1);
  REQUIRE(record.capacity);
  CHECK(record.capacity->R == design.capacity.R);
  CHECK(record.capacity->T == design.capacity.T);
}

TEST_CASE("a design with a non-positive material is a named error", "[schema]") {
  nlohmann::ordered_json json;
  write_engine(json, testing::alcala_ca());
  json["beta2"] = 0;
  CHECK_THROWS_WITH(read_engine(json, "design"), "design.beta2 = 0: the allowed bending must be positive");
}
