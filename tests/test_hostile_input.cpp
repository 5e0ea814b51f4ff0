// The root fixes of issue 21, one class each, at the functions every program shares: text that
// is not UTF-8, nesting, values that overflow, ranges where one value is taken, sizes beyond
// the ordinary, tolerances, and outputs written whole. The expected values are facts of the
// encodings and of the documented windows (docs/stability.md), not outputs of the code.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <unistd.h>

#include "engines.hpp"
#include "trebuchet/air.hpp"
#include "trebuchet/engine.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/integrator.hpp"
#include "trebuchet/verification.hpp"
#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/input/text_input.hpp"
#include "trebuchet/app/input/units.hpp"

using namespace trebuchet;
namespace fs = std::filesystem;

namespace {
ErrorKind error_kind_of(const std::function<void()>& work) {
  try {
    work();
  } catch (const Error& e) {
    return e.kind();
  }
  FAIL("no error");
  return ErrorKind::usage;
}
}  // namespace

TEST_CASE("UTF-8 is told from other bytes as RFC 3629 defines it", "[hostile]") {
  CHECK(is_utf8("Sa\xC3\xB4ne"));  // ô, two bytes
  CHECK(is_utf8("\xE2\x82\xAC"));  // €, three bytes
  CHECK(is_utf8("\xF0\x9F\x8F\xB0"));  // U+1F3F0 (a castle), four bytes
  CHECK_FALSE(is_utf8("Sa\xF4ne"));  // Latin-1 ô: a lead byte without its continuation
  CHECK_FALSE(is_utf8("\xC0\xAF"));  // an overlong '/'
  CHECK_FALSE(is_utf8("\xED\xA0\x80"));  // a UTF-16 surrogate, U+D800
  CHECK_FALSE(is_utf8("\xF4\x90\x80\x80"));  // beyond U+10FFFF
  CHECK_FALSE(is_utf8("ab\xC3"));  // cut short
}

TEST_CASE("text that is not UTF-8 is read as Windows-1252", "[hostile]") {
  CHECK(as_utf8("Sa\xF4ne") == "Sa\xC3\xB4ne");  // 0xF4 is ô in Latin-1 and Windows-1252
  CHECK(as_utf8("\x80 5") == "\xE2\x82\xAC 5");  // 0x80 is € in Windows-1252
  CHECK(as_utf8("\x93x\x94") == "\xE2\x80\x9Cx\xE2\x80\x9D");  // curly quotes
  CHECK(as_utf8("a\x81") == "a\xEF\xBF\xBD");  // one of the five bytes Windows-1252 leaves unused: U+FFFD
  CHECK(as_utf8("Sa\xC3\xB4ne") == "Sa\xC3\xB4ne");  // UTF-8 stays as it is
  // Through the CSV reader, as a spreadsheet on Windows saves it.
  std::istringstream input("site,R\nSa\xF4ne,150\n");
  CsvReader reader(input, "test");
  CsvRow row;
  REQUIRE(reader.next(row));
  CHECK(row.cells.front() == "Sa\xC3\xB4ne");
}

TEST_CASE("nesting is counted outside strings and refused past 32 levels before parsing", "[hostile]") {
  CHECK(json_depth("{\"L1\": [1, [2]]}") == 3);
  CHECK(json_depth("{\"L1\": \"[[[[\"}") == 1);  // brackets in a string are text
  CHECK(json_depth("{\"a\\\"[[\": 1}") == 1);  // an escaped quote does not end the string
  CHECK(json_depth(std::string(100000, '[')) == max_json_depth + 1);  // counting stops once past the bound
  const std::string deep = std::string(33, '[') + std::string(33, ']');
  CHECK(error_kind_of([&] { parse_json(deep, "test", "a design"); }) == ErrorKind::usage);
  CHECK_NOTHROW(parse_json(std::string(32, '[') + std::string(32, ']'), "test", "a design"));
}

TEST_CASE("a unit at one end of a range or spread is the unit of both", "[hostile]") {
  const auto range = parse_spread("3..4t", UnitDimension::mass, "--M");
  REQUIRE(range);
  CHECK(range->a == 3000);
  CHECK(range->b == 4000);
  const auto low = parse_spread("3t..4", UnitDimension::mass, "--M");
  REQUIRE(low);
  CHECK(low->b == 4000);
  const auto spread = parse_spread("5±20cm", UnitDimension::length, "--L4");
  REQUIRE(spread);
  CHECK(spread->a == Approx(0.05).epsilon(1e-15));
  CHECK(spread->b == Approx(0.2).epsilon(1e-15));
  const auto fraction = parse_spread("1/2..2/3", UnitDimension::dimensionless, "--F");
  REQUIRE(fraction);
  CHECK(fraction->b == Approx(2.0 / 3).epsilon(1e-15));
  CHECK(error_kind_of([] { parse_spread("4m..5kg", UnitDimension::length, "--L4"); }) == ErrorKind::unknown_unit);
}

TEST_CASE("a value is one value: a range, a spread or an overflow in SI units is refused", "[hostile]") {
  CHECK_THROWS_WITH(parse_value("100..200m", UnitDimension::length, "R"), Catch::Contains("is a range or a spread, and R takes one value"));
  CHECK_THROWS_WITH(parse_value("150m±10m", UnitDimension::length, "R"), Catch::Contains("is a range or a spread"));
  CHECK_THROWS_WITH(parse_value("1e308t", UnitDimension::mass, "--M"), Catch::Contains("beyond the range of numbers in SI units"));
  CHECK(error_kind_of([] { parse_value("1e-322mm", UnitDimension::length, "--L1"); }) == ErrorKind::bad_number);  // 1e-325 m rounds to 0
}

TEST_CASE("engines, materials, air and tolerances of ordinary size, and not beyond", "[hostile]") {
  const Engine alcala = testing::alcala_ca();
  CHECK_NOTHROW(check_engine(alcala));
  // Messages name the inputs bare here (what()); the programs write their own words for them.
  // Each bound of docs/stability.md, just inside and just beyond.
  auto with = [&](auto change) {
    Engine e = alcala;
    change(e);
    return e;
  };
  CHECK_NOTHROW(check_engine(with([](Engine& e) { e.material.g = 1e6; })));
  CHECK_THROWS_WITH(check_engine(with([](Engine& e) { e.material.g = 1.01e6; })), Catch::Contains("g = 1.01e+06 m/s2 is not of ordinary size"));
  CHECK_THROWS_WITH(check_engine(with([](Engine& e) { e.L2 = 1e-310; })), Catch::Contains("L2 = "));
  CHECK_NOTHROW(check_engine(with([](Engine& e) { e.M = 1e12, e.m = 1e6, e.mb = 1e6; })));
  CHECK_THROWS_WITH(check_engine(with([](Engine& e) { e.M = 2e12; })), Catch::Contains("M = "));
  // Proportions: L1/L2 at 10^6 passes, beyond it is refused, naming both.
  CHECK_NOTHROW(check_engine(with([](Engine& e) { e.L2 = e.L1 / 0.99e6, e.L3 = e.L2; })));  // within 10^6 (L3 follows L2 here)
  CHECK_THROWS_WITH(check_engine(with([](Engine& e) { e.L2 = e.L1 / 1.1e6; })), Catch::Contains("L1 = ") && Catch::Contains("L2 = "));
  CHECK_THROWS_WITH(check_engine(with([](Engine& e) { e.m = e.M * 1e-7; })), Catch::Contains("differ by more than a factor 10^6"));
  CHECK_THROWS_WITH(check_material(Material{1.0 / 300, 12e9, 1e-300, 9.81}), Catch::Contains("wood_density = "));
  Air air;
  CHECK_NOTHROW(check_air(air));
  air.wind = -1000;
  CHECK_NOTHROW(check_air(air));
  air.wind = -1001;
  CHECK_THROWS_WITH(check_air(air), Catch::Contains("wind = "));
  air = Air{};
  air.projectile_density = 1e-308;
  CHECK_THROWS_WITH(check_air(air), Catch::Contains("projectile = "));
  IntegratorSettings settings;
  settings.rtol = 1e-15;
  CHECK_NOTHROW(check_integrator(settings));
  settings.rtol = 1e-300;
  CHECK_THROWS_WITH(check_integrator(settings), Catch::Contains("rtol = "));
  // A search checks its settings first, so they are named as bad input, not as "no engine works".
  ShotSettings bad;
  bad.integrator.atol = 1e-300;
  CHECK(error_kind_of([&] { verify_engine(alcala, bad); }) == ErrorKind::bad_number);
}

TEST_CASE("a series sampled too finely is refused before it is drawn, one too coarsely gives its ends", "[hostile]") {
  const Engine alcala = testing::alcala_ca();
  std::vector<TracePoint> trace;
  CHECK_THROWS_WITH(verify_engine(alcala, ShotSettings{}, &trace, 1e-12), Catch::Contains("more than 1000000 points"));
  CHECK(trace.empty());
  // A step longer than the shot (about 2 s to twice the release): the multiples of it within
  // the shot are 0 alone, so the series is t = 0 and the end of each phase, I, II (the
  // release) and III (twice the release).
  verify_engine(alcala, ShotSettings{}, &trace, 1e3);
  REQUIRE(trace.size() == 4);
  CHECK(trace.front().t == 0);
  CHECK(trace.back().t == Approx(2 * trace[2].t).epsilon(1e-12));
  trace.clear();
  verify_engine(alcala, ShotSettings{}, &trace, 1e308);  // ends, where it ran without end before
  CHECK(trace.size() <= 4);
}

TEST_CASE("an output is written whole or not at all, and never over an input", "[hostile]") {
  const fs::path folder = fs::temp_directory_path() / ("trebuchet-hostile-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string file = (folder / "out.csv").string();
  {
    PendingOutput output(file, "series");
    std::ofstream(output.temporary()) << "half";
    // destroyed without commit: a failure
  }
  CHECK_FALSE(fs::exists(file));
  CHECK(fs::is_empty(folder));
  write_output_file(file, "whole\n", "series");
  auto first_line = [](const fs::path& path) {
    std::ifstream in(path);
    std::string text;
    std::getline(in, text);
    return text;
  };
  CHECK(first_line(file) == "whole");
  CHECK_THROWS_WITH(refuse_output_over_input(file, "series", {file}), Catch::Contains("would overwrite the input"));
  CHECK_NOTHROW(refuse_output_over_input((folder / "other.csv").string(), "series", {file, "-"}));
  // Through a link: the file it points at is written, the link stays a link.
  const fs::path link = folder / "link.csv";
  fs::create_symlink(file, link);
  write_output_file(link.string(), "through\n", "series");
  CHECK(fs::is_symlink(link));
  CHECK(first_line(file) == "through");
  CHECK_THROWS_WITH(refuse_output_over_input(link.string(), "series", {file}), Catch::Contains("would overwrite the input"));
  // A device is written into, never replaced by a file.
  write_output_file("/dev/null", "gone\n", "series");
  CHECK(fs::is_character_file("/dev/null"));
  // A picture folder: its files may not replace an input inside it; nothing moves then.
  const fs::path pictures = folder / "pictures";
  fs::create_directories(pictures);
  std::ofstream(pictures / "shot.csv") << "input\n";
  {
    PendingOutput output(pictures.string(), "plot", true, {(pictures / "shot.csv").string()});
    std::ofstream(fs::path(output.temporary()) / "a.svg") << "a";
    std::ofstream(fs::path(output.temporary()) / "shot.csv") << "series";
    CHECK_THROWS_WITH(output.commit(), Catch::Contains("would overwrite the input"));
  }
  CHECK(first_line(pictures / "shot.csv") == "input");
  CHECK_FALSE(fs::exists(pictures / "a.svg"));
  // Without that input, the files move in and the folder's other files stay.
  {
    PendingOutput output(pictures.string(), "plot", true);
    std::ofstream(fs::path(output.temporary()) / "a.svg") << "a";
    output.commit();
  }
  CHECK(fs::exists(pictures / "a.svg"));
  CHECK(fs::exists(pictures / "shot.csv"));
  for (const auto& entry : fs::directory_iterator(folder)) CHECK(entry.path().filename().string().find(".part-") == std::string::npos);
  fs::remove_all(folder);
}
