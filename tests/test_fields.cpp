// The table of inputs (fields.hpp): one row per value, names that cannot be confused, ranges the
// core holds, and the refusal of a near miss with the name meant.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>

#include "trebuchet/error.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/records/shot_record.hpp"

using namespace trebuchet;

namespace {

// Alcala la Vieja's Ca engine (docs/guide.md), as a design's values.
DesignValues ca_engine() {
  DesignValues v;
  v.L1 = 4.13, v.L2 = 0.88, v.L3 = 1.5043, v.L4 = 3.55, v.M = 3110, v.m = 50,
  v.mb = 174;  // L3 for F = 2/3, given: a probed L1 or L2 must not first leave no room for the arm
  return v;
}

// Whether an error speaks of the field, by its key or an alias ({{name}}).
bool names_field(const Error& error, const InputField& field) {
  for (const std::string& name : error.names())
    if (find_field(name) == &field) return true;
  return false;
}

}  // namespace

TEST_CASE("every member of DesignValues has one row, and no two rows share a name", "[fields]") {
  std::set<std::string> names, flags;
  for (const InputField& field : input_fields()) {
    INFO(field.key);
    CHECK(&field_of(field.member) == &field);  // the member finds its own row
    CHECK(names.insert(field.key).second);
    for (const char* alias : field.aliases) CHECK(names.insert(alias).second);
    CHECK(flags.insert(field.flag).second);
    CHECK(find_field(field.key) == &field);
    CHECK(*field.help != '\0');
    CHECK(*field.example != '\0');
    CHECK(field.operations != 0);
  }
  // DesignValues holds optionals alone: its size counts its members, each of which has a row.
  CHECK(sizeof(DesignValues) / sizeof(std::optional<double>) == input_fields().size());
}

// The range a row states is the one the core checks: a value beyond either end is refused,
// naming the row's key. Rows of "A to B unit" for the engine, its stand-ins and the material
// (the parts' ranges need their companions, a radius or a box, and are tested in test_real_engine).
TEST_CASE("a value beyond the range a row states is refused, naming the row", "[fields]") {
  int probed = 0;
  for (const InputField& field : input_fields()) {
    if (!(field.operations & op_shot) || field.group == FieldGroup::part || field.group == FieldGroup::capacity) continue;
    std::string range = field.range;
    if (range.rfind("0, or ", 0) == 0) range = range.substr(6);
    double low = 0, high = 0;
    if (std::sscanf(range.c_str(), "%lf to %lf", &low, &high) != 2) continue;
    const bool excluded = range.find("both excluded") != std::string::npos;
    std::vector<double> outside = {low > 0 ? low / 2 : low - 1, high * 2};
    if (excluded) outside.insert(outside.end(), {low, high});
    for (double value : outside) {
      DesignValues v = ca_engine();
      if (field.member == &DesignValues::D) v.mb.reset();  // a diameter alone gives the beam's mass
      v.*field.member = value;
      INFO(field.key << " = " << value << " (range " << field.range << ")");
      try {
        engine_record(v, "design");
        FAIL("accepted");
      } catch (const Error& e) {
        INFO(e.what());
        const std::string said = e.what();
        const auto names_it = [&](const char* name) { return said.find(std::string("design.") + name + " ") != std::string::npos; };
        const std::vector<const char*> names = names_of(field);
        CHECK((names_field(e, field) || std::any_of(names.begin(), names.end(), names_it)));
      }
      ++probed;
    }
  }
  CHECK(probed >= 30);  // L1 to psi_i_deg, D and the material: at least 15 rows of two ends
}

TEST_CASE("a near miss is named with the key meant, and other keys pass through", "[fields]") {
  const std::vector<std::string> shot = input_names(op_shot);
  CHECK(near_miss("theta_i", shot) == "theta_i_deg");  // the unit left off
  CHECK(near_miss("theta_deg", shot) == "theta_i_deg");  // the alias with a unit
  CHECK(near_miss("L4_ft", shot) == "L4");  // a unit put on, as a CSV column has it
  CHECK(near_miss("M_kg", shot) == "M");
  CHECK(near_miss("thta_i_deg", shot) == "theta_i_deg");  // two edits of a long name
  CHECK(near_miss("l1", shot) == "L1");  // a name of two letters: its case alone
  CHECK(near_miss("L_4", shot) == "L4");  // a hand's variants: underscores, hyphens, blanks, case
  CHECK(near_miss("g ", shot) == "g");
  CHECK(near_miss("m_b", shot) == "mb");
  CHECK(near_miss("L4m", shot) == "L4");  // a unit put on without an underscore
  CHECK(near_miss("theta_degrees", shot) == "theta_i_deg");
  CHECK(near_miss("g_m_s2", shot) == "g");  // a CSV column's name, in JSON
  CHECK(near_miss("rope_diam", shot).empty());  // an abbreviation: passed through, named
  CHECK(near_miss("site", shot).empty());
  CHECK(near_miss("comment", shot).empty());
  CHECK(near_miss("Lb", shot).empty());  // complete's, not a shot's: a shot's output key, read back silently

  nlohmann::json design = {{"L1", 4.13}, {"L2", 0.88}, {"F", "2/3"}, {"L4", 3.55}, {"M", 3110}, {"m", 50}, {"mb", 174}};
  design["l4"] = 0.86;  // the programs' own outputs, near L4 and L but known: read back silently
  design["L"] = 1.3;
  design["site"] = "Ca";  // the caller's: passed through
  nlohmann::json passed;
  read_design_values(design, "design", &passed);
  CHECK(passed == nlohmann::json{{"site", "Ca"}});
  design["theta_i"] = 45;
  try {
    read_design_values(design, "design", &passed);
    FAIL("accepted theta_i");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::usage);
    CHECK(std::string(e.what()) == "design: unknown key \"theta_i\"; did you mean \"theta_i_deg\"?");
  }
}

// A design carries its wood's strength (inputs.def's modulus_of_rupture): read from JSON and from
// a CSV column in MPa, it reaches the beam's check. The stresses do not depend on it, so the
// margin, the modulus of rupture over the larger stress (material.hpp), halves exactly with it.
TEST_CASE("a design carries its wood's modulus of rupture to the beam's margin", "[fields]") {
  nlohmann::json design = {{"L1", 4.13}, {"L2", 0.88}, {"F", "2/3"}, {"L4", 3.55}, {"M", 3110}, {"m", 50}, {"mb", 174}, {"D", 0.25}};
  design.erase("mb");
  const Engine strong = read_engine(design, "design").engine;
  design["modulus_of_rupture"] = "60MPa";
  const Engine weak = read_engine(design, "design").engine;
  CHECK(strong.material.modulus_of_rupture == 120e6);  // Material's default, section 4
  CHECK(weak.material.modulus_of_rupture == 60e6);
  const double margin_strong = verify_engine(strong, ShotSettings{}).beam->margin, margin_weak = verify_engine(weak, ShotSettings{}).beam->margin;
  INFO("margins " << margin_strong << " and " << margin_weak);
  CHECK(margin_weak / margin_strong == Approx(0.5).epsilon(1e-14));  // a ratio of two products of the same stresses: round-off only
  std::istringstream csv("L1_m,L2_m,F,L4_m,M_kg,m_kg,D_m,modulus_of_rupture_MPa\n4.13,0.88,2/3,3.55,3110,50,0.25,60\n");
  const DesignRows rows = read_design_rows(csv, "test");
  REQUIRE(rows.rows.size() == 1);
  CHECK(read_engine(rows.rows[0].design, "line 2").engine.material.modulus_of_rupture == 60e6);
}
