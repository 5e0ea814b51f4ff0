// trebuchet::api, the JSON requests of the browser page (and the Python module): each gives what
// the library gives through its typed calls, refuses by name, and a Monte Carlo run split into
// parts is the whole run.
#include <catch2/catch.hpp>

#include "trebuchet/app/api/api.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/input/settings.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/scaling_table.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;
using json = nlohmann::json;

namespace {

// The answer of a request that must be refused: its error, or a failed test.
Error refusal(nlohmann::ordered_json (*request)(const json&), const json& r) {
  try {
    request(r);
  } catch (const Error& e) {
    return e;
  }
  FAIL("not refused: " << r.dump());
  return Error(ErrorKind::usage, "");
}

}  // namespace

TEST_CASE("api::design is the calculator's design, its numbers unchanged", "[api]") {
  DesignRequest typed;
  typed.first = {Quantity::R, 150};
  typed.second = {Quantity::m, 50};
  typed.F = 2.0 / 3;
  const OptimalEngine expected = design_optimal_engine(builtin_scaling_table(), typed);
  // The same request in the page's words: values with units, F as a fraction.
  const auto answer = api::design({{"R", "150m"}, {"m", "50kg"}, {"F", "2/3"}});
  // The same code path on the same numbers: equal to the last bit.
  CHECK(answer["L1"].get<double>() == expected.engine.L1);
  CHECK(answer["M"].get<double>() == expected.engine.M);
  CHECK(answer["T"].get<double>() == expected.capacity.T);
}

// Another machine's optimum from its own table, as trebuchet-calc --machine; F is that table's
// (the counterweight at the short arm's end) and refused, as the calculator refuses --F; the
// whipper has no table and is refused with the calculator's reason.
TEST_CASE("api::design of another machine is the calculator's design from that machine's table", "[api]") {
  for (MachineKind machine : {MachineKind::fixed, MachineKind::floating_arm}) {
    DesignRequest typed;
    typed.first = {Quantity::R, 300};
    typed.second = {Quantity::m, 50};
    const OptimalEngine expected = design_optimal_engine(builtin_scaling_table(machine), typed);
    const auto answer = api::design({{"R", "300m"}, {"m", "50kg"}, {"machine", machine_name(machine)}});
    CHECK(answer["L1"].get<double>() == expected.engine.L1);
    CHECK(answer["M"].get<double>() == expected.engine.M);
    CHECK(answer["machine"] == machine_name(machine));
    CHECK_THAT(refusal(api::design, {{"R", "300m"}, {"m", "50kg"}, {"F", "2/3"}, {"machine", machine_name(machine)}}).what(),
               Catch::Contains("leave out F"));
  }
  CHECK_THAT(refusal(api::design, {{"R", "300m"}, {"m", "50kg"}, {"machine", "whipper"}}).what(), Catch::Contains("shot here, not designed"));
}

TEST_CASE("api::shot is verify_engine under the request's settings, which its answer states", "[api]") {
  const auto design = api::design({{"R", "150m"}, {"m", "50kg"}});
  const json request = {{"design", design}, {"air", {{"wind", "5m/s"}}}, {"release", "range"}, {"target_level", "-10m"}};
  const auto answer = api::shot(request);
  ShotSettings settings;
  Air air;
  air.wind = 5;
  settings.air = air;
  settings.criterion.release = Release::range;
  settings.target_level = -10;
  const Verification v = verify_engine(read_engine(design, "design").engine, settings);
  CHECK(answer["R"].get<double>() == v.capacity.R);
  CHECK(answer["eps"].get<double>() == v.eps);
  CHECK(answer["assumptions"]["air"]["wind"].get<double>() == 5);
  CHECK(answer["assumptions"]["release"] == "range");
  // The answer's settings go back in as they came out, and give the same shot.
  json again = answer["assumptions"];
  for (const char* only_reported : {"g", "theta_i_deg", "F"}) again.erase(only_reported);
  again["air"].erase("projectile_diameter");
  again["design"] = design;
  CHECK(api::shot(again)["R"].get<double>() == answer["R"].get<double>());
}

TEST_CASE("api::shot's series runs from rest through the release to the flight's end", "[api]") {
  const auto answer = api::shot({{"design", api::design({{"R", "150m"}, {"m", "50kg"}})}, {"series", true}});
  const auto& series = answer["series"];
  const auto& frames = series["frames"];
  const std::size_t release = series["moments"]["release"];
  CHECK(frames["phase"][0] == "I");
  CHECK(frames["phase"][release] == "II");
  CHECK(frames["phase"][release + 1] == "III");
  // The release frame is the shot's release: the same time to 1e-9 s (the trace's release is the
  // refined one), and the flight ends R from the pivot at the target level 0.
  CHECK(frames["t"][release].get<double>() == Approx(answer["t_release"].get<double>()).margin(1e-9));
  CHECK(series["flight"]["x"].back().get<double>() == Approx(answer["R"].get<double>()).epsilon(1e-6));
  CHECK(series["flight"]["y"].back().get<double>() == Approx(0).margin(1e-6));
}

TEST_CASE("api requests are refused by name, with the fix", "[api]") {
  CHECK_THAT(refusal(api::design, {{"R", "150m"}}).what(), Catch::Contains("give exactly two"));
  CHECK_THAT(refusal(api::design, {{"R", "150m"}, {"m", "50kg"}, {"colour", "red"}}).what(), Catch::Contains("'colour' is no key"));
  const Error negative = refusal(api::design, {{"R", -150}, {"m", "50kg"}});
  CHECK(negative.kind() == ErrorKind::bad_number);
  CHECK(api::error_json(negative)["names"].dump() == R"(["R"])");
  CHECK_THAT(refusal(api::shot, {{"design", {{"L1", "4m"}}}}).what(), Catch::Contains("design: key \"L2\" is missing"));
  CHECK_THAT(refusal(api::shot, {{"design", api::design({{"R", "150m"}, {"m", "50kg"}})}, {"air", "thick"}}).what(), Catch::Contains("is no air"));
  json uncertain = api::design({{"R", "150m"}, {"m", "50kg"}});
  uncertain["M"] = "2t..3t";
  CHECK_THAT(refusal(api::monte_carlo, {{"design", uncertain}, {"samples", 1e300}}).what(), Catch::Contains("whole number"));
  // An attested key near an input's name is refused with it; another key passes through, named.
  CHECK_THAT(refusal(api::complete, {{"attested", {{"Lb", "9.5m"}, {"M", "3t"}, {"m", "50kg"}, {"L_b", 1}}}}).what(),
             Catch::Contains("attested: unknown key \"L_b\"; did you mean \"Lb\"?"));
  CHECK(api::complete({{"attested", {{"Lb", "9.5m"}, {"M", "3t"}, {"m", "50kg"}, {"source", "Villard"}}}})["passed"].dump() ==
        R"({"source":"Villard"})");
}

TEST_CASE("api::monte_carlo split into parts is the whole run", "[api]") {
  const json request = {{"attested", {{"Lb", "9.5m"}, {"M", "2.5t..3.5t"}, {"m", "50kg"}}}, {"samples", 6}, {"seed", 3}};
  const auto whole = api::monte_carlo(request);
  json outcomes = json::array();
  for (int first : {0, 2, 5}) {  // parts of 2, 3 and 1 samples, as Web Workers take them
    json part = request;
    part["first"] = first;
    part["count"] = first == 0 ? 2 : first == 2 ? 3 : 1;
    const auto answer = api::monte_carlo(part);
    for (const auto& o : answer["outcomes"]) outcomes.push_back(json::parse(o.dump()));
  }
  json together = request;
  together["outcomes"] = outcomes;
  CHECK(api::monte_carlo(together).dump() == whole.dump());
  CHECK(whole["worked"] == 6);
  // The drawn inputs travel with the parts: each sample's M is within its range, beside its R.
  const auto& draws = whole["draws"];
  REQUIRE(draws["M"].size() == 6);
  for (std::size_t i = 0; i < 6; ++i) {
    CHECK(draws["M"][i].get<double>() >= 2500);
    CHECK(draws["M"][i].get<double>() <= 3500);
    CHECK(draws["R"][i].get<double>() > 0);
  }
}

// Issue 65: a request's settings are laid over the design's as the programs' flags are
// (lay_over_run), and each one that replaces the design's own is noted in the request's keys.
TEST_CASE("api::monte_carlo notes a request's setting that replaces the design's own", "[api]") {
  const json design = {{"L1", "4.13m"}, {"L2", "0.88m"},   {"F", "2/3"},  {"L4", "3.55m"}, {"m", "50kg"},
                       {"mb", "174kg"}, {"M", "3t..3.2t"}, {"air", true}, {"wind", "2m/s"}};
  const auto answer = api::monte_carlo({{"design", design}, {"wind", "0m/s"}, {"samples", 5}});
  REQUIRE(answer.contains("notes"));
  CHECK(answer["notes"].get<std::vector<std::string>>() == std::vector<std::string>{"wind 0 m/s replaces design.wind = 2 m/s"});
  // A spread given over the design's one value replaces it, drawn, and is noted with its spread.
  const auto spread = api::monte_carlo({{"design", design}, {"wind", "-1m/s..1m/s"}, {"samples", 5}});
  CHECK(spread["notes"].get<std::vector<std::string>>() == std::vector<std::string>{"wind -1m/s..1m/s replaces design.wind = 2 m/s"});
  CHECK(spread["draws"].contains("wind"));
}

TEST_CASE("api::monte_carlo with a claim: its odds agree with the samples' own ranges", "[api]") {
  const json request = {{"attested", {{"Lb", "9.5m"}, {"M", "2t..4t"}, {"m", "50kg"}}}, {"samples", 40}, {"claim", "170m"}, {"release", "range"}};
  const auto answer = api::monte_carlo(request);
  int reached = 0;
  for (const auto& R : answer["draws"]["R"]) reached += R.get<double>() >= 170;
  CHECK(answer["claim"]["reached"] == reached);
  CHECK(answer["claim"]["probability"].get<double>() == Approx(reached / 40.0).epsilon(1e-15));
  CHECK(reached > 0);
  CHECK(reached < 40);  // the range of M straddles the claim
  // M is the only input drawn: it leads the ranking, and a heavier counterweight throws farther.
  CHECK(answer["sensitivity"]["ranking"][0]["input"] == "M");
  CHECK(answer["sensitivity"]["ranking"][0]["spearman_R"].get<double>() > 0.9);
}

// Issue 64: a pumpkin team's claim of 1895 ft from a ten-foot drop of 998 kg, a 4.1 kg pumpkin
// 0.2 m across, its beam's mass unknown. The verdict turns on the drag coefficient, left at its
// default: a smooth sphere past its drag crisis reaches the claim, a rough ball does not.
TEST_CASE("api::monte_carlo with a claim says what decides it and reads back as its run", "[api]") {
  const json request = {{"attested", {{"drop", "10ft"}, {"M", "998kg"}, {"m", "4.1kg"}, {"mb", "30kg..100kg"}, {"projectile_diameter", "0.2m"}}},
                        {"air", true},
                        {"release", "range"},
                        {"claim", "1895ft"},
                        {"samples", 8}};
  const auto answer = api::monte_carlo(request);
  const auto& decided = answer["claim"]["decided_by"];
  INFO(decided.dump());
  // No engine of this energy throws beyond Siano's black box, 2 Delta U/(m g), even in vacuum.
  CHECK(decided["farthest"].get<double>() < decided["energy_bound"].get<double>());
  CHECK(decided["energy_bound"].get<double>() > 577.6);
  // The density follows from the diameter, so only Cd and the wind are left at their defaults.
  REQUIRE(decided["defaults"].size() == 2);
  const auto& cd = decided["defaults"][0];
  CHECK(cd["input"] == "cd");
  CHECK(cd["R_low"].get<double>() >= 577.6);  // Cd(Re) falls to about 0.1 past the drag crisis
  CHECK(cd["R_high"].get<double>() < 577.6);  // Cd 0.5
  CHECK(cd["decides"] == true);
  const auto& wind = decided["defaults"][1];
  CHECK(wind["input"] == "wind");
  CHECK(wind["R_low"].get<double>() < wind["R_high"].get<double>());  // against the shot, then with it
  CHECK(wind["decides"] == false);
  // The report read back is the same run, the values left at their defaults too.
  CHECK(api::monte_carlo({{"attested", answer}})["claim"].dump() == answer["claim"].dump());
}

TEST_CASE("api::complete applies the request's modulus of rupture, as the program's --rupture", "[api]") {
  const json attested = {{"Lb", "9.5m"}, {"M", "3t"}, {"m", "50kg"}};
  const auto standard = api::complete({{"attested", attested}});
  const auto weaker = api::complete({{"attested", attested}, {"modulus_of_rupture", "60MPa"}});
  // The same engine and stresses; the margin is the modulus over the larger stress, so half the
  // modulus (120 MPa by default, section 4) halves it.
  CHECK(weaker["rupture_margin"].get<double>() == Approx(standard["rupture_margin"].get<double>() / 2).epsilon(1e-12));
  CHECK_THAT(refusal(api::complete, {{"attested", attested}, {"modulus_of_rupture", -1}}).what(), Catch::Contains("must be positive"));
}

TEST_CASE("api::shot takes an engine as built and the air before the release", "[api]") {
  // The parts go in as the design's keys and come back in the engine; the air before the release
  // is a key of "air", as the answer's assumptions state it.
  const json design = {{"L1", "4.13m"}, {"L2", "0.88m"},          {"F", "2/3"},           {"L4", "3.55m"},         {"M", "3.11t"}, {"m", "50kg"},
                       {"mb", "174kg"}, {"axle_friction", 0.107}, {"axle_radius", "5cm"}, {"rope_diameter", "2cm"}};
  const auto answer = api::shot({{"design", design}, {"air", {{"drag_in_sling", true}}}});
  Engine engine;
  engine.L1 = 4.13, engine.L2 = 0.88, engine.L4 = 3.55, engine.M = 3110, engine.m = 50, engine.mb = 174;
  engine.L3 = counterweight_arm(engine.L1, engine.L2, 30, 2.0 / 3);
  engine.parts.axle = {0.107, 0.05};
  engine.parts.rope_diameter = 0.02;
  ShotSettings settings;
  settings.air = Air{};
  settings.drag_in_sling = true;
  const Verification v = verify_engine(engine, settings);
  // The same engine by another road: L3 from F rounds once, 1e-12 covers it.
  CHECK(answer["R"].get<double>() == Approx(v.capacity.R).epsilon(1e-12));
  CHECK(answer["energy"]["losses"]["axle"].get<double>() == Approx(v.energy.losses[axle_loss]).epsilon(1e-9));
  CHECK(answer["energy"]["losses"]["rope_drag"].get<double>() > 0);
  CHECK(answer["engine"]["axle_friction"].get<double>() == 0.107);
  CHECK(answer["assumptions"]["air"]["drag_in_sling"].get<bool>());
  const Error wrong = refusal(&api::shot, {{"design", design}, {"air", {{"drag_in_sling", "yes"}}}});
  CHECK(std::string(wrong.what()).find("air.drag_in_sling") != std::string::npos);
}

TEST_CASE("every key of every request has its row, and a setting has one name at every door", "[api][settings]") {
  using Request = nlohmann::ordered_json (*)(const json&);
  const std::pair<const char*, Request> requests[] = {{"design", api::design},     {"shot", api::shot},         {"sweep", api::sweep},
                                                      {"optimize", api::optimize}, {"complete", api::complete}, {"monte_carlo", api::monte_carlo},
                                                      {"value", api::value}};
  for (const auto& [name, request] : requests) {
    // A key no request takes is refused with the keys this one takes: each is an input's or a setting's.
    const std::string message = refusal(request, {{"zz_no_such_key", 1}}).what();
    const std::string listed = message.substr(message.find("; use ") + 6);
    INFO(name << ": " << message);
    REQUIRE(message.find("; use ") != std::string::npos);
    std::size_t keys = 0;
    for (std::size_t start = 0; start < listed.size(); ++keys) {
      const std::size_t end = std::min(listed.find(", ", start), listed.size());
      const std::string key = listed.substr(start, end - start);
      INFO("its key " << key);
      CHECK((find_field(key) != nullptr || find_setting(key, ~0u) != nullptr));
      start = end + 2;
    }
    CHECK(keys > 1);
  }
  // The flag's word and the old key give the same shot; the old key is an alias of the row.
  const json design = {{"L1", "6.13m"}, {"L2", "1.52m"}, {"L3", "2m"}, {"L4", "5.1m"}, {"M", "14.3t"}, {"m", "100kg"}, {"mb", "2t"}};
  CHECK(api::shot({{"design", design}, {"quality", "range"}}) == api::shot({{"design", design}, {"release", "range"}}));
  json with_claim = design;
  with_claim["R"] = "300m", with_claim["T"] = "200kJ";
  CHECK(api::shot({{"design", with_claim}, {"tol", 1e-9}}) == api::shot({{"design", with_claim}, {"tolerance", 1e-9}}));
  // Given twice under its two names, or misspelt: refused by name.
  CHECK_THAT(refusal(api::shot, {{"design", design}, {"quality", "range"}, {"release", "Q"}}).what(),
             Catch::Contains("quality and release both give quality; keep one"));
  // Both of the wind's names are named, the air's detail as its path (issue 62).
  nlohmann::json windy = design;
  windy["air"] = {{"wind", "1m/s"}}, windy["wind"] = "2m/s";
  CHECK_THAT(refusal(api::shot, {{"design", windy}}).what(), Catch::Contains("design.air.wind and design.wind both give wind; keep one"));
  CHECK_THAT(refusal(api::shot, {{"design", design}, {"tolerence", 0.1}}).what(), Catch::Contains("did you mean \"tolerance\""));
  // The air's details flat, as the flags give them, or in the air's object: one shot.
  CHECK(api::shot({{"design", design}, {"air", true}, {"wind", "5m/s"}, {"cd", 0.5}}) ==
        api::shot({{"design", design}, {"air", {{"wind", "5m/s"}, {"drag_coefficient", 0.5}}}}));
}

// machine "all" is the programs' --machine all: a refusal every machine gives alike (here a
// clearance no engine in a 3 m box can keep) is raised once, as the request's own, not answered
// three times; pareto, a front of one machine, is refused beside it. Each machine's best side by
// side is tests/python's (contest(machine="all")) and cli.verify.contest_all's, three searches.
TEST_CASE("api::contest with machine all raises a refusal every machine gives alike", "[api][contest]") {
  const nlohmann::json request = {{"m", "0.5kg"},       {"D", "5cm"},       {"machine", "all"},      {"max_width", "3m"},
                                  {"max_height", "3m"}, {"max_M", "300kg"}, {"min_clearance", "1km"}};
  CHECK_THROWS_WITH(api::contest(request), Catch::Contains("no engine found keeps its counterweight min_clearance = 1000 m"));
  CHECK_THROWS_WITH(api::contest({{"m", "0.5kg"}, {"D", "5cm"}, {"machine", "all"}, {"pareto", 5}}),
                    Catch::Contains("\"all\" sets the machines' best side by side"));
}

// "over" is the programs' flags over a file's values (overlay_flags), for the front ends that
// have no flags (Python's keyword arguments): the same shot as the value written in the design,
// a release in one form replacing another, and a key that is no input refused by name. A wrong
// overlay would give another range, bit for bit compared.
TEST_CASE("api: a request's over lays the engine's inputs over its design, as the flags do", "[api]") {
  const json design = {{"L1", "6.13m"}, {"L2", "1.08m"}, {"L3", "1.2m"}, {"L4", "5.8m"}, {"M", "14.3t"}, {"m", "100kg"}, {"mb", "660kg"}};
  json shorter = design;
  shorter["L4"] = "5m";
  CHECK(api::shot({{"design", design}, {"over", {{"L4", "5m"}}}})["R"] == api::shot({{"design", shorter}})["R"]);
  json timed = design;
  timed["release_time"] = "0.9s";
  json pinned = design;
  pinned["pin_angle_deg"] = 40;
  CHECK(api::shot({{"design", timed}, {"over", {{"pin_angle_deg", 40}}}})["R"] == api::shot({{"design", pinned}})["R"]);
  CHECK(api::sweep({{"design", design}, {"over", {{"L4", "5m"}}}, {"vary", "M=14t..15t"}, {"points", 2}}) ==
        api::sweep({{"design", shorter}, {"vary", "M=14t..15t"}, {"points", 2}}));
  CHECK_THAT(refusal(api::shot, {{"design", design}, {"over", {{"tol", 1}}}}).what(), Catch::Contains("over.tol is no input of the engine"));
  CHECK_THAT(refusal(api::shot, {{"design", design}, {"over", "L4=5m"}}).what(), Catch::Contains("over: \"L4=5m\" must be an object"));
}

// complete's "over" takes complete's own inputs (Lb, l, drop), and a range there is completed at
// its middle, as one in the attested values is (Python's complete(attested, Lb=..., M="2.5t..3.5t")).
TEST_CASE("api::complete lays its over on the attested values, complete's own inputs and ranges too", "[api]") {
  const json attested = {{"Lb", "9.5m"}, {"M", "3t"}, {"m", "50kg"}};
  const auto direct = api::complete({{"attested", attested}});
  const auto over_Lb = api::complete({{"attested", {{"Lb", "5m"}, {"M", "3t"}, {"m", "50kg"}}}, {"over", {{"Lb", "9.5m"}}}});
  const auto over_range = api::complete({{"attested", attested}, {"over", {{"M", "2.5t..3.5t"}}}});
  CHECK(over_Lb["R"] == direct["R"]);
  CHECK(over_range["R"] == direct["R"]);  // 2.5 t to 3.5 t completed at its middle, 3 t
  CHECK_THAT(refusal(api::shot,
                     {{"design", {{"L1", "6.13m"}, {"L2", "1.08m"}, {"L3", "1.2m"}, {"L4", "5.8m"}, {"M", "14.3t"}, {"m", "100kg"}, {"mb", "660kg"}}},
                      {"over", {{"M", "13t..15t"}}}})
                 .what(),
             Catch::Contains("over.M: '13t..15t' is a range or a spread"));
}
