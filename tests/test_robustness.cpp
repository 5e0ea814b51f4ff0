// Randomised robustness (issue 4): wide boxes of random engines and requests, and malformed
// text, through the library as the programs call it. Every outcome must be a result with
// finite numbers or an Error of a named class: no crash, no NaN, no other exception.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "heavy.hpp"

#include "engines.hpp"
#include "exit_codes.hpp"
#include "trebuchet/calculator.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/app/input/request.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/design_record.hpp"
#include "trebuchet/app/records/search_records.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/input/units.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;

namespace {

double log_uniform(std::mt19937_64& random, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(random));
}

void print_counts(const char* what, const std::map<std::string, int>& counts) {
  std::printf("%s:\n", what);
  for (const auto& [reason, count] : counts) std::printf("  %6d  %s\n", count, reason.c_str());
}

// The message up to its first ':' or ';', to group failures by reason; bad input by kind.
std::string reason_of(const Error& e) {
  if (e.kind() != ErrorKind::numerical) return "bad input, exit code " + std::to_string(exit_code(Program::verify, e.kind()));
  const std::string message = e.what();
  return message.substr(0, message.find_first_of(":;"));
}

}  // namespace

TEST_CASE("10 000 random engines: a finite result or a named error each", "[robustness][heavy]") {
  std::mt19937_64 random(4);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::map<std::string, int> outcomes;
  int shot = 0;
  for (int k = 0; k < 10000; ++k) {
    Engine e;
    e.theta_i_deg = 5 + 80 * uniform(random);
    e.L1 = log_uniform(random, 0.3, 40);
    e.L2 = e.L1 / log_uniform(random, 1.1, 80);
    e.L3 = counterweight_arm(e.L1, e.L2, e.theta_i_deg, 0.3 + uniform(random));
    e.L4 = e.L1 * log_uniform(random, 0.03, 5);
    e.M = log_uniform(random, 10, 1e6);
    e.m = e.M * log_uniform(random, 1e-5, 1);
    e.mb = e.M * log_uniform(random, 1e-5, 2);
    if (!heavy_case_runs(k)) continue;  // drawn all the same, so that each pass meets the same engines
    ++shot;
    INFO("engine " << k << ": L1 " << e.L1 << " L2 " << e.L2 << " L3 " << e.L3 << " L4 " << e.L4 << " M " << e.M << " m " << e.m << " mb " << e.mb
                   << " theta " << e.theta_i_deg);
    try {
      check_engine(e);
      const Verification v = verify_engine(e, ShotSettings{});
      verification_json(v, check_capacity(v, {100, 1e4}, 0.02));  // throws if any number is not finite
      ++outcomes["result"];
    } catch (const Error& error) {
      CHECK((error.kind() == ErrorKind::numerical || error.kind() == ErrorKind::bad_number));
      ++outcomes[reason_of(error)];
    }
  }
  print_counts("10 000 random engines", outcomes);
  CHECK(outcomes["result"] > shot / 4);  // a quarter or more make a shot (47 % of the 10 000 do): the set is not all refusals
}

TEST_CASE("random calculator requests: a design with finite numbers or a named error each", "[robustness]") {
  std::mt19937_64 random(5);
  std::uniform_int_distribution<std::size_t> pick(0, all_quantities.size() - 1);
  std::map<std::string, int> outcomes;
  for (int k = 0; k < 20000; ++k) {
    DesignRequest request;
    const Quantity a = all_quantities[pick(random)], b = all_quantities[pick(random)];
    request.first = {a, log_uniform(random, 1e-3, 1e7)};
    request.second = {b, log_uniform(random, 1e-3, 1e7)};
    request.theta_i_deg = std::uniform_int_distribution<int>(0, 2)(random) == 0 ? 40 : 30;
    request.F = std::uniform_int_distribution<int>(0, 1)(random) ? 1.0 : 2.0 / 3;
    request.extrapolate = std::uniform_int_distribution<int>(0, 3)(random) == 0;
    try {
      const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), request);
      design_json(design);  // throws if any number is not finite
      ++outcomes["design"];
    } catch (const Error& error) {
      ++outcomes["error, exit code " + std::to_string(exit_code(Program::calc, error.kind()))];
    }
  }
  print_counts("20 000 random requests", outcomes);
  CHECK(outcomes["design"] > 100);
}

// Malformed text as users type it: every string is a value or an Error naming it.
TEST_CASE("malformed values and designs are named errors", "[robustness]") {
  std::mt19937_64 random(6);
  const std::string alphabet = "0123456789.eE+-/ kgmtJKMGPa%x,;\"nainf";
  std::uniform_int_distribution<std::size_t> letter(0, alphabet.size() - 1), length(0, 12);
  int errors = 0, values = 0;
  for (int k = 0; k < 20000; ++k) {
    std::string text;
    for (std::size_t n = length(random); n > 0; --n) text += alphabet[letter(random)];
    for (UnitDimension dimension : {UnitDimension::length, UnitDimension::mass, UnitDimension::energy, UnitDimension::angle}) {
      try {
        const double value = parse_value(text, dimension, "x");
        CHECK(std::isfinite(value));
        ++values;
      } catch (const Error& error) {
        CHECK((error.kind() == ErrorKind::bad_number || error.kind() == ErrorKind::unknown_unit));
        ++errors;
      }
    }
    // The same text as a JSON design value, in place of L4.
    nlohmann::ordered_json design;
    write_engine(design, testing::alcala_ca());
    design["L4"] = text;
    try {
      const EngineRecord in = read_engine(design, "design");
      CHECK(std::isfinite(in.engine.L4));
    } catch (const Error& error) {
      CHECK(std::string(error.what()).find("L4") != std::string::npos);
    }
  }
  std::printf("malformed text: %d values, %d named errors\n", values, errors);
  CHECK(errors > values);
}
