// CSV as spreadsheets write it (docs/csv.md): each form a spreadsheet writes reads to the same
// cells, and each ambiguity is refused with a message rather than read one way.
#include <catch2/catch.hpp>
#include <sstream>

#include "trebuchet/app/input/csv.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/app/input/units.hpp"

using namespace trebuchet;

namespace {
std::vector<std::vector<std::string>> read_all(const std::string& text) {
  std::istringstream input(text);
  CsvReader reader(input, "test");
  std::vector<std::vector<std::string>> rows = {reader.header()};
  CsvRow row;
  while (reader.next(row)) rows.push_back(row.cells);
  return rows;
}
}  // namespace

TEST_CASE("a BOM, CRLF, semicolons, tabs and quotes read to the same cells as plain CSV", "[csv]") {
  const std::vector<std::vector<std::string>> plain = {{"site", "R", "m"}, {"Saone, castle", "150 m", "50"}, {"say \"hi\"", "2", "3"}};
  CHECK(read_all("site,R,m\n\"Saone, castle\",150 m,50\n\"say \"\"hi\"\"\",2,3\n") == plain);
  CHECK(read_all("\xEF\xBB\xBFsite;R;m\r\nSaone, castle;150 m;50\r\n\"say \"\"hi\"\"\";2;3\r\n") == plain);
  CHECK(read_all("# a comment\n\nsite\tR\tm\nSaone, castle\t150 m\t50\n\n\"say \"\"hi\"\"\"\t2\t3") == plain);
}

TEST_CASE("a malformed row is an error naming its line, and the reader reads on", "[csv]") {
  std::istringstream input("R,m\n150,50\n\"150,50\n150,50,7\n200,60\n");
  CsvReader reader(input, "sites.csv");
  CsvRow row;
  REQUIRE(reader.next(row));
  CHECK_THROWS_WITH(reader.next(row), Catch::Contains("sites.csv line 3: a quote is not closed"));
  CHECK(row.line == 3);
  CHECK_THROWS_WITH(reader.next(row), Catch::Contains("line 4: expected 2 cells as in the header, found 3"));
  REQUIRE(reader.next(row));
  CHECK(row.cells == std::vector<std::string>{"200", "60"});
  CHECK(!reader.next(row));
  std::istringstream empty("# nothing\n\n");
  CHECK_THROWS_WITH(CsvReader(empty, "sites.csv"), Catch::Contains("sites.csv is empty"));
}

TEST_CASE("a column's unit is in its name, and the longest key wins", "[csv]") {
  const std::vector<std::string_view> keys = {"m", "mb", "M", "R", "wood_density", "g"};
  CHECK(split_column_name("R_m", keys)->unit == "m");
  CHECK(split_column_name("mb_kg", keys)->key == "mb");
  CHECK(split_column_name("M_t", keys)->unit == "t");
  CHECK(split_column_name("wood_density_kg_m3", keys)->unit == "kg/m3");
  CHECK(split_column_name("g_m_s2", keys)->unit == "m/s2");
  CHECK(split_column_name("m", keys)->unit.empty());
  CHECK(!split_column_name("site", keys));
  CHECK(!split_column_name("Rx", keys));
}

TEST_CASE("decimal commas are read, thousands separators refused", "[csv]") {
  CHECK(cell_value("150,5 m", "", "R") == "150.5 m");
  CHECK(cell_value("0,500", "t", "M") == "0.500t");
  CHECK(cell_value("1,5", "kg", "m") == "1.5kg");
  CHECK(cell_value("3", "t", "M") == "3t");
  CHECK(cell_value("3 kg", "t", "M") == "3 kg");  // the cell's own unit wins over the column's
  CHECK(parse_value(cell_value("150,5 m", "", "R"), UnitDimension::length, "R") == 150.5);
  CHECK_THROWS_WITH(cell_value("1,500", "", "R"), Catch::Contains("could be a decimal comma or a thousands separator"));
  CHECK_THROWS_WITH(cell_value("1,500.5", "", "R"), Catch::Contains("mixes ',' and '.'"));
  CHECK_THROWS_WITH(cell_value("1,500,000", "", "R"), Catch::Contains("two commas"));
}

TEST_CASE("numbers are written with the digits asked for, and 17 round-trip", "[csv]") {
  CHECK(csv_number(40454.745502907805, default_csv_digits) == "40454.7");
  CHECK(std::stod(csv_number(0.1 + 0.2, 17)) == 0.1 + 0.2);
  CHECK(csv_cell("a,b") == "\"a,b\"");
  CHECK(csv_cell("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(csv_cell("plain") == "plain");
  CHECK(parse_digits("17", "--digits") == 17);
  CHECK_THROWS_WITH(parse_digits("0", "--digits"), Catch::Contains("give 1 to 17"));
  CHECK_THROWS_WITH(parse_digits("6x", "--digits"), Catch::Contains("give 1 to 17"));
}
