#include "trebuchet/app/output/spreadsheet.hpp"

#include <xlsxwriter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/quantity.hpp"
#include "trebuchet/app/input/fields.hpp"
#include "trebuchet/app/output/output_files.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {
namespace {

using V = DesignValues;

// An input's unit as the sheets write it: "m", "kg", "deg", "" for a pure number.
std::string sheet_unit(const InputField& field) {
  if (field.dimension == UnitDimension::angle) return "deg";
  std::string unit = field.unit;
  std::replace(unit.begin(), unit.end(), '_', '/');  // kg_m3: kg/m3
  return unit;
}

// A formula and its value, built together so that the text written to a cell and the value
// cached beside it come from one expression: each equation of the workbook is written once.
struct Expr {
  std::string f;  // spreadsheet formula text, references absolute
  double v;  // its value
};

// A text cell or formula and its value.
struct Text {
  std::string f;
  std::string v;
};

std::string number_text(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return x < 0 ? "(" + std::string(buffer) + ")" : buffer;
}

Expr num(double x) { return {number_text(x), x}; }
Expr operator+(const Expr& a, const Expr& b) { return {"(" + a.f + "+" + b.f + ")", a.v + b.v}; }
Expr operator-(const Expr& a, const Expr& b) { return {"(" + a.f + "-" + b.f + ")", a.v - b.v}; }
Expr operator*(const Expr& a, const Expr& b) { return {a.f + "*" + b.f, a.v * b.v}; }
Expr operator/(const Expr& a, const Expr& b) { return {a.f + "/(" + b.f + ")", a.v / b.v}; }
Expr ln(const Expr& a) { return {"LN(" + a.f + ")", std::log(a.v)}; }
Expr exp(const Expr& a) { return {"EXP(" + a.f + ")", std::exp(a.v)}; }
Expr sqrt(const Expr& a) { return {"SQRT(" + a.f + ")", std::sqrt(a.v)}; }
Expr abs(const Expr& a) { return {"ABS(" + a.f + ")", std::abs(a.v)}; }
Expr power(const Expr& a, double n) { return {"POWER(" + a.f + "," + number_text(n) + ")", std::pow(a.v, n)}; }
Expr cos_deg(const Expr& a) { return {"COS(RADIANS(" + a.f + "))", std::cos(radians(a.v))}; }
Expr max(const Expr& a, const Expr& b) { return {"MAX(" + a.f + "," + b.f + ")", std::max(a.v, b.v)}; }
Expr min(const Expr& a, const Expr& b) { return {"MIN(" + a.f + "," + b.f + ")", std::min(a.v, b.v)}; }
// Comparisons are the numbers 1 or 0, not TRUE or FALSE, so that a product of them is a
// logical and and every cell holds a number. Texts compare exactly (EXACT), as "m" is not "M".
Expr truth(const std::string& test, bool value) { return {"(" + test + ")*1", value ? 1.0 : 0.0}; }
Expr at_most(const Expr& a, const Expr& b) { return truth(a.f + "<=" + b.f, a.v <= b.v); }
Expr below(const Expr& a, const Expr& b) { return truth(a.f + "<" + b.f, a.v < b.v); }
Expr equal(const Expr& a, const Expr& b) { return truth(a.f + "=" + b.f, a.v == b.v); }
Expr same(const Text& a, const Text& b) { return truth("EXACT(" + a.f + "," + b.f + ")", a.v == b.v); }
Expr is(const Text& a, const std::string& literal) { return truth("EXACT(" + a.f + ",\"" + literal + "\")", a.v == literal); }
Expr either(const Expr& a, const Expr& b) { return {"MAX(" + a.f + "," + b.f + ")", std::max(a.v, b.v)}; }
Expr choose(const Expr& condition, const Expr& yes, const Expr& no) {
  return {"IF(" + condition.f + "," + yes.f + "," + no.f + ")", condition.v != 0 ? yes.v : no.v};
}
Text choose(const Expr& condition, const Text& yes, const Text& no) {
  return {"IF(" + condition.f + "," + yes.f + "," + no.f + ")", condition.v != 0 ? yes.v : no.v};
}
Text literal(const std::string& text) { return {"\"" + text + "\"", text}; }

std::string column_name(int col) {
  std::string name;
  for (++col; col > 0; col = (col - 1) / 26) name.insert(name.begin(), static_cast<char>('A' + (col - 1) % 26));
  return name;
}

// A range of one column, rows first..last, with the value of each cell.
struct Column {
  std::string f;
  std::vector<double> v;
};
// The k-th element (from 1) of a column: INDEX(column, k).
Expr element(const Column& column, const Expr& k) { return {"INDEX(" + column.f + "," + k.f + ")", column.v.at(static_cast<std::size_t>(k.v) - 1)}; }
struct TextColumn {
  std::string f;
  std::vector<std::string> v;
};
Text element(const TextColumn& column, const Expr& k) {
  return {"INDEX(" + column.f + "," + k.f + ")", column.v.at(static_cast<std::size_t>(k.v) - 1)};
}
// MATCH(MAX(range), range, 0): the first row holding the largest value, from 1.
Expr first_largest(const Column& column) {
  const auto it = std::max_element(column.v.begin(), column.v.end());
  return {"MATCH(MAX(" + column.f + ")," + column.f + ",0)", static_cast<double>(it - column.v.begin() + 1)};
}
Expr largest(const Column& column) { return {"MAX(" + column.f + ")", *std::max_element(column.v.begin(), column.v.end())}; }

struct Formats {
  lxw_workbook* book;
  lxw_format* title;
  lxw_format* heading;
  lxw_format* input;  // cells the user types into
  lxw_format* note;
  std::map<std::pair<std::string, bool>, lxw_format*> shown;  // by number format and whether it is an input

  // How a number is shown. Each format has three sections, positive;negative;zero, so that a
  // negative shows its minus sign and 0 shows as 0 whatever value the formula takes later (a
  // format's conditions, [>=1000] and the like, would leave negatives without their sign). The
  // decimals are chosen from the value's size when the cell is written: 4 significant digits (3
  // decimals from 1 to 10, none from 1000 up), thousands grouped (12,345), and scientific
  // notation below 1e-3. When an input changes a value's size, the sign, the zero and the
  // grouping still show; only the count of digits drifts. An input shows what was typed, and a
  // whole number below 1000 (a count, a flag) all its digits: both in General. Every cell keeps
  // every digit, and exports at full precision.
  static std::string number_format(double value) {
    const double size = std::abs(value);
    if (!(size >= 1e-3)) return "0.000E+00;-0.000E+00;0";  // NaN too: a refused request's placeholder
    // Clamped before the conversion: an infinite value (a request beyond every number) has no digit count.
    const int decimals = static_cast<int>(std::clamp(3 - std::floor(std::log10(size)), 0.0, 6.0));
    const std::string digits = "#,##0" + (decimals == 0 ? "" : "." + std::string(static_cast<std::size_t>(decimals), '0'));
    return digits + ";-" + digits + ";0";
  }
  lxw_format* four_digits(double value, bool is_input = false) {
    const bool general = is_input || (value == std::round(value) && std::abs(value) < 1000);
    return numbers(general ? "General" : number_format(value), is_input);
  }
  // A number with the decimals a source prints: "9.70" shows as 9.70.
  lxw_format* printed(int decimals) {
    const std::string digits = decimals == 0 ? "0" : "0." + std::string(static_cast<std::size_t>(decimals), '0');
    return numbers(digits + ";-" + digits + ";0", false);
  }
  lxw_format* numbers(const std::string& number_format, bool is_input) {
    lxw_format*& format = shown[{number_format, is_input}];
    if (!format) {
      format = workbook_add_format(book);
      if (number_format != "General") format_set_num_format(format, number_format.c_str());
      if (is_input) format_set_bg_color(format, input_colour);
    }
    return format;
  }
  static constexpr lxw_color_t input_colour = 0xFFF2AB;
};

// A worksheet whose rows are label | value | unit | equation and note. Formulas refer to other
// sheets by name; references to the sheet itself are written without it.
// A cell's limit counts characters, as libxlsxwriter does (UTF-8: every byte but 10xxxxxx
// starts one); a text is cut at the start of a character, never inside one.
std::size_t characters(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}
std::string first_characters(const std::string& text, std::size_t count) {
  std::size_t seen = 0;
  for (std::size_t at = 0; at < text.size(); ++at)
    if ((static_cast<unsigned char>(text[at]) & 0xC0) != 0x80 && seen++ == count) return text.substr(0, at);
  return text;
}

class Sheet {
 public:
  Sheet(lxw_workbook* book, const std::string& name, Formats& formats)
      : sheet_(workbook_add_worksheet(book, name.c_str())), prefix_("'" + name + "'!"), formats_(formats) {
    worksheet_set_column(sheet_, 0, 0, 26, nullptr);
    worksheet_set_column(sheet_, 1, 1, 18, nullptr);
    worksheet_set_column(sheet_, 2, 2, 13, nullptr);
    worksheet_set_column(sheet_, 3, 3, 70, nullptr);
    // Printed across, one page wide, on A4.
    worksheet_set_landscape(sheet_);
    worksheet_set_paper(sheet_, 9);
    worksheet_fit_to_pages(sheet_, 1, 0);
  }
  lxw_worksheet* raw() const { return sheet_; }

  std::string ref(int row, int col) const { return prefix_ + "$" + column_name(col) + "$" + std::to_string(row + 1); }
  std::string range(int first_row, int last_row, int first_col, int last_col = -1) const {
    if (last_col < 0) last_col = first_col;
    return prefix_ + "$" + column_name(first_col) + "$" + std::to_string(first_row + 1) + ":$" + column_name(last_col) + "$" +
        std::to_string(last_row + 1);
  }

  void title(const std::string& text, const std::string& explanation) {
    worksheet_write_string(sheet_, 0, 0, text.c_str(), formats_.title);
    worksheet_write_string(sheet_, 1, 0, explanation.c_str(), formats_.note);
  }
  void heading(int row, int col, const std::string& text) { worksheet_write_string(sheet_, row, col, text.c_str(), formats_.heading); }
  void note(int row, const std::string& text) {
    worksheet_write_string(sheet_, row, 0, first_characters(text, max_cell_characters).c_str(), formats_.note);
  }
  // A text longer than a cell holds is cut to it (overlong_cell refuses its row), not left blank.
  void text(int row, int col, const std::string& text) {
    worksheet_write_string(sheet_, row, col, first_characters(text, max_cell_characters).c_str(), nullptr);
  }

  // A drop-down of the texts of `list` (ends with nullptr) on an input cell.
  void choices(int row, int col, const char** list) {
    lxw_data_validation validation{};
    validation.validate = LXW_VALIDATION_TYPE_LIST;
    validation.value_list = const_cast<char**>(list);  // libxlsxwriter only reads it
    worksheet_data_validation_cell(sheet_, row, col, &validation);
  }
  // Every number the workbook caches is finite: a value beyond the range of doubles would be
  // cached as INF or NAN, which no spreadsheet reads as the formula's result.
  void require_finite(int row, int col, double value) const {
    if (!std::isfinite(value))
      throw Error(ErrorKind::bad_number,
                  "with these inputs the workbook's cell " + ref(row, col) + " would be beyond the range of numbers; give values of ordinary size");
  }
  Expr number(int row, int col, double value) {
    require_finite(row, col, value);
    worksheet_write_number(sheet_, row, col, value, nullptr);
    return {ref(row, col), value};
  }
  Expr input(int row, int col, double value) {
    require_finite(row, col, value);
    worksheet_write_number(sheet_, row, col, value, formats_.four_digits(value, true));
    return {ref(row, col), value};
  }
  // An input that takes a number greater than `above` (and below `below` if given): anything
  // else, "250 m" typed with its unit too, is refused on typing with `hint`.
  Expr number_input(int row, int col, double value, const std::string& hint, double above = 0, std::optional<double> below = std::nullopt) {
    const Expr e = input(row, col, value);
    lxw_data_validation validation{};
    validation.validate = LXW_VALIDATION_TYPE_DECIMAL;
    validation.criteria = below ? LXW_VALIDATION_CRITERIA_BETWEEN : LXW_VALIDATION_CRITERIA_GREATER_THAN;
    validation.value_number = above;
    validation.minimum_number = above;
    validation.maximum_number = below.value_or(0);
    std::string title = "A number only", message = hint;
    validation.error_title = title.data();
    validation.error_message = message.data();
    worksheet_data_validation_cell(sheet_, row, col, &validation);
    return e;
  }
  // A number as a source prints it, shown with the decimals printed.
  Expr printed(int row, int col, const std::string& text) {
    const std::size_t point = text.find('.');
    const double value = std::stod(text);
    worksheet_write_number(sheet_, row, col, value, formats_.printed(point == std::string::npos ? 0 : static_cast<int>(text.size() - point - 1)));
    return {ref(row, col), value};
  }
  Text text_cell(int row, int col, const std::string& value) {
    worksheet_write_string(sheet_, row, col, value.c_str(), nullptr);
    return {ref(row, col), value};
  }
  Text input_text(int row, int col, const std::string& value) {
    worksheet_write_string(sheet_, row, col, value.c_str(), formats_.input);
    return {ref(row, col), value};
  }
  Expr formula(int row, int col, const Expr& e, lxw_format* format = nullptr) {
    require_finite(row, col, e.v);
    worksheet_write_formula_num(sheet_, row, col, local(e.f).c_str(), format, e.v);
    return {ref(row, col), e.v};
  }
  // A result shown to 4 significant digits where `valid` is 1, and left blank where it is 0:
  // a refused request must not look like a result.
  Expr result(int row, int col, const Expr& valid, const Expr& e) {
    const std::string text = local("IF(" + valid.f + "," + e.f + ",\"\")");
    if (valid.v != 0) {
      require_finite(row, col, e.v);
      worksheet_write_formula_num(sheet_, row, col, text.c_str(), formats_.four_digits(e.v), e.v);
    } else {
      worksheet_write_formula_str(sheet_, row, col, text.c_str(), formats_.four_digits(e.v), "");
    }
    return {ref(row, col), e.v};
  }
  Text formula(int row, int col, const Text& t) {
    worksheet_write_formula_str(sheet_, row, col, local(t.f).c_str(), nullptr, t.v.c_str());
    return {ref(row, col), t.v};
  }
  // A row of the form label | value | unit | note.
  void describe(int row, const std::string& label, const std::string& unit, const std::string& note) {
    worksheet_write_string(sheet_, row, 0, label.c_str(), nullptr);
    if (!unit.empty()) worksheet_write_string(sheet_, row, 2, unit.c_str(), nullptr);
    if (!note.empty()) worksheet_write_string(sheet_, row, 3, note.c_str(), formats_.note);
  }
  Expr input_row(int row, const std::string& label, double value, const std::string& unit, const std::string& note) {
    describe(row, label, unit, note);
    return input(row, 1, value);
  }
  Expr formula_row(int row, const std::string& label, const Expr& e, const std::string& unit, const std::string& note) {
    describe(row, label, unit, note);
    return formula(row, 1, e, formats_.four_digits(e.v));
  }
  Expr result_row(int row, const std::string& label, const Expr& valid, const Expr& e, const std::string& unit, const std::string& note) {
    describe(row, label, unit, note);
    return result(row, 1, valid, e);
  }
  Text text_row(int row, const std::string& label, const Text& t, const std::string& note) {
    describe(row, label, "", note);
    return formula(row, 1, t);
  }

 private:
  std::string local(const std::string& formula) const {
    std::string out = formula;
    for (std::size_t at = out.find(prefix_); at != std::string::npos; at = out.find(prefix_, at)) out.erase(at, prefix_.size());
    return "=" + out;
  }
  lxw_worksheet* sheet_;
  std::string prefix_;
  Formats& formats_;
};

// The quantities a design sheet takes, in the order of the constants sheet's laws: R, T, the
// seven fitted parameters and the beam ratio l. Lb is not log-linear (the calculator's alone).
const std::array<Quantity, 10> log_linear = {Quantity::R, Quantity::T, Quantity::L1, Quantity::L2, Quantity::L4,
                                             Quantity::D, Quantity::M, Quantity::m,  Quantity::mb, Quantity::l};

// The material sheet's factors from the table's material to the user's (section 7).
struct MaterialFactors {
  Expr mass, diameter, energy;
  Expr g;  // the user's [m/s^2]
};

// A given's factor from the table's material to the user's: masses, D and T scale (section 7).
Expr material_factor(const MaterialFactors& f, Quantity q) {
  if (q == Quantity::T) return f.energy;
  if (q == Quantity::D) return f.diameter;
  if (quantity_dimension(q) == Dimension::mass) return f.mass;
  return num(1);
}

// One row per segment of the table: its block, interval, branch, and the log-linear law
// log Z = c + p log(R/R0) + q log(T/T0) of each quantity (eq:ZRT).
struct ConstantsSheet {
  int rows = 0;
  Column theta, F, X_min, X_max, X_d;
  TextColumn branch;
  std::array<Column, param_count> Z0, a, p, q;
  std::array<std::array<Column, 3>, log_linear.size()> law;  // c, p, q
  std::string laws;  // the range of all laws, a row per segment and c, p, q per quantity
  Expr R0, T0;
  std::string quantity_names;  // the range of the names, for MATCH
  Material reference;
  Expr beta2, youngs_modulus, wood_density, g;
};

std::string describe_material_note() { return "the table's material: its masses and T are rescaled to yours on the material sheet"; }

ConstantsSheet write_constants(lxw_workbook* book, Formats& formats, const ScalingTable& table) {
  Sheet s(book, "constants", formats);
  s.title("Constants of " + table.name + " (eq:ZRT): Z/Z0 = a_Z (R/R0)^p_Z (T/T0)^q_Z",
          "Each row is one X-segment of one (theta_i, F) block. Edit the numbers to use another table; every sheet follows.");
  // The segment table is many narrow columns; the labels above it overflow into them.
  worksheet_set_column(s.raw(), 0, 80, 13, nullptr);
  ConstantsSheet c;
  c.reference = table.reference;
  c.R0 = s.input_row(3, "R0", table.R0, "m", "reference range");
  c.T0 = s.input_row(4, "T0", table.T0, "J", "reference energy");
  c.beta2 = s.input_row(5, "beta2", table.reference.beta2, "", describe_material_note() + " (eq:bend_L2)");
  c.youngs_modulus = s.input_row(6, "Young's modulus", table.reference.youngs_modulus, "Pa", describe_material_note());
  c.wood_density = s.input_row(7, "wood density", table.reference.wood_density, "kg/m3", describe_material_note());
  c.g = s.input_row(8, "g", table.reference.g, "m/s2", describe_material_note());
  std::vector<std::string> provenance;
  for (const auto& [key, text] : table.provenance) provenance.push_back(key + ": " + text);
  s.text(9, 0, "provenance: " + join(provenance, "; "));
  s.heading(10, 0, "quantities");
  for (std::size_t k = 0; k < log_linear.size(); ++k) s.text(10, 1 + static_cast<int>(k), std::string(quantity_name(log_linear[k])));
  c.quantity_names = "constants!$B$11:$" + column_name(static_cast<int>(log_linear.size())) + "$11";

  const int header = 12, first = 13;
  const char* fixed[] = {"theta_i [deg]", "F", "X_min", "X_max", "branch", "X_d"};
  for (int k = 0; k < 6; ++k) s.heading(header, k, fixed[k]);
  const int Z0_col = 6, a_col = Z0_col + param_count, p_col = a_col + param_count, q_col = p_col + param_count, law_col = q_col + param_count;
  for (Param param : all_params) {
    const std::string name(param_name(param));
    s.heading(header, Z0_col + index(param), "Z0 " + name);
    s.heading(header, a_col + index(param), "a " + name);
    s.heading(header, p_col + index(param), "p " + name);
    s.heading(header, q_col + index(param), "q " + name);
  }
  for (std::size_t k = 0; k < log_linear.size(); ++k) {
    const std::string name(quantity_name(log_linear[k]));
    for (int j = 0; j < 3; ++j) s.heading(header, law_col + 3 * static_cast<int>(k) + j, std::string(j == 0 ? "c " : j == 1 ? "p " : "q ") + name);
  }
  s.text(header - 1, law_col, "log-linear laws: ln Z = c + p ln(R/R0) + q ln(T/T0), c = ln(a_Z Z0) (eq:RT_Z1Z2); l = L1/L2 by difference");

  int row = first;
  for (const TableBlock& block : table.blocks)
    for (const Segment& segment : block.segments) {
      c.theta.v.push_back(s.input(row, 0, block.theta_i_deg).v);
      c.F.v.push_back(s.input(row, 1, block.F).v);
      c.X_min.v.push_back(s.input(row, 2, segment.X_min).v);
      c.X_max.v.push_back(s.input(row, 3, segment.X_max).v);
      c.branch.v.push_back(s.input_text(row, 4, std::string(branch_name(segment.branch))).v);
      // Without two branches, X_d is never used: 0 stands in for it.
      c.X_d.v.push_back(s.input(row, 5, block.branch_switch_X.value_or(0)).v);
      std::array<Expr, param_count> Z0, a, p, q;
      for (Param param : all_params) {
        const int k = index(param);
        Z0[k] = s.input(row, Z0_col + k, block.Z0[k]);
        a[k] = s.input(row, a_col + k, segment.a[k]);
        p[k] = s.input(row, p_col + k, segment.exponents(k, 0));
        q[k] = s.input(row, q_col + k, segment.exponents(k, 1));
        c.Z0[k].v.push_back(Z0[k].v), c.a[k].v.push_back(a[k].v), c.p[k].v.push_back(p[k].v), c.q[k].v.push_back(q[k].v);
      }
      for (std::size_t k = 0; k < log_linear.size(); ++k) {
        std::array<Expr, 3> law;
        switch (log_linear[k]) {
          case Quantity::R: law = {ln(c.R0), num(1), num(0)}; break;
          case Quantity::T: law = {ln(c.T0), num(0), num(1)}; break;
          case Quantity::l: {
            const int L1 = index(Param::L1), L2 = index(Param::L2);
            law = {ln(a[L1] * Z0[L1]) - ln(a[L2] * Z0[L2]), p[L1] - p[L2], q[L1] - q[L2]};
            break;
          }
          default: {
            const int z = static_cast<int>(k) - 2;  // L1 ... mb follow R and T in Param order
            law = {ln(a[z] * Z0[z]), p[z], q[z]};
          }
        }
        for (int j = 0; j < 3; ++j) c.law[k][j].v.push_back(s.formula(row, law_col + 3 * static_cast<int>(k) + j, law[j]).v);
      }
      ++row;
    }
  c.rows = row - first;
  const int last = row - 1;
  auto name_range = [&](Column& column, int col) { column.f = s.range(first, last, col); };
  name_range(c.theta, 0), name_range(c.F, 1), name_range(c.X_min, 2), name_range(c.X_max, 3), name_range(c.X_d, 5);
  c.branch.f = s.range(first, last, 4);
  for (Param param : all_params) {
    const int k = index(param);
    name_range(c.Z0[k], Z0_col + k), name_range(c.a[k], a_col + k), name_range(c.p[k], p_col + k), name_range(c.q[k], q_col + k);
  }
  for (std::size_t k = 0; k < log_linear.size(); ++k)
    for (int j = 0; j < 3; ++j) name_range(c.law[k][j], law_col + 3 * static_cast<int>(k) + j);
  c.laws = s.range(first, last, law_col, law_col + 3 * static_cast<int>(log_linear.size()) - 1);
  return c;
}

// eq:kMkD's k_M and k_D, and the factors of section 7 from the table's material to the user's.
MaterialFactors write_material(lxw_workbook* book, Formats& formats, const ConstantsSheet& c, const Material& material) {
  Sheet s(book, "material", formats);
  s.title("Material, allowed bending and gravity (section 4, section 7)",
          "Type your wood, beta2 and g; the design sheets rescale the table's masses, D and T by the factors below (eq:ExtraScalings).");
  const Expr beta2 = s.input_row(3, "beta2", material.beta2, "", "allowed bending u2/L2 of the short beam section (eq:bend_L2); the paper: 1/300");
  const Expr E = s.input_row(4, "Young's modulus", material.youngs_modulus, "Pa", "of the beam's wood");
  const Expr rho = s.input_row(5, "wood density", material.wood_density, "kg/m3", "of the beam's wood");
  const Expr g = s.input_row(6, "g", material.g, "m/s2", "gravitational acceleration (the moon: 1.62)");
  const Expr pi = {"PI()", M_PI};
  auto k_M = [&](const Expr& gg, const Expr& r, const Expr& e) { return num(4) / num(3) * pi * gg * r * r / e; };
  auto k_D = [&](const Expr& gg, const Expr& r, const Expr& e) { return num(16) / num(3) * gg * r / e; };
  const Expr kM = s.formula_row(8, "k_M", k_M(g, rho, E), "kg/m4", "eq:kMkD: (4 pi/3) g rho^2 / E");
  const Expr kD = s.formula_row(9, "k_D", k_D(g, rho, E), "1/m", "eq:kMkD: (16/3) g rho / E");
  const Expr kM0 = s.formula_row(10, "k_M of the table", k_M(c.g, c.wood_density, c.youngs_modulus), "kg/m4",
                                 "eq:kMkD with the constants sheet's material");
  const Expr kD0 = s.formula_row(11, "k_D of the table", k_D(c.g, c.wood_density, c.youngs_modulus), "1/m",
                                 "eq:kMkD with the constants sheet's material");
  MaterialFactors f;
  f.mass = s.formula_row(13, "mass factor", (kM / beta2) / (kM0 / c.beta2), "",
                         "masses at equal lengths: M = K^2 (k_M/beta2) L2^4 (eq:ExtraScalings)");
  f.diameter = s.formula_row(14, "diameter factor", sqrt((kD / beta2) / (kD0 / c.beta2)), "", "D = sqrt(K k_D/beta2) L2^1.5 (eq:ExtraScalings)");
  f.energy = s.formula_row(15, "energy factor", f.mass * g / c.g, "", "T in units of M g L2 (section 3)");
  f.g = g;
  return f;
}

// eq:ZRT for one fitted parameter in the segment `segment` (a row of the constants sheet), in
// the user's material: D and the masses times the material sheet's factors (section 7).
Expr fitted(const ConstantsSheet& c, const MaterialFactors& f, Param param, const Expr& segment, const Expr& lr, const Expr& lt) {
  const int z = index(param);
  const Expr Z = element(c.a[z], segment) * element(c.Z0[z], segment) * exp(element(c.p[z], segment) * lr + element(c.q[z], segment) * lt);
  if (param == Param::D) return Z * f.diameter;
  if (param == Param::M || param == Param::m || param == Param::mb) return Z * f.mass;
  return Z;
}
// eq:ZRT for the energy at the target in the user's material [J].
Expr target_energy(const ConstantsSheet& c, const MaterialFactors& f, const Expr& lt) { return c.T0 * exp(lt) * f.energy; }
// The counterweight arm from L2 + L3 = F H, H = L1 cos(theta_i) (section 2).
Expr counterweight_arm(const Expr& F, const Expr& theta, const Expr& L1, const Expr& L2) { return F * L1 * cos_deg(theta) - L2; }
// eq:DU of an unpropped counterweight (psi_i = 0) and a uniform beam (L_CM = (L1 - L2)/2):
// (1 - mu_b (l - 1)/2)(1 + cos theta_i) M g L2 [J].
Expr potential_drop(const Expr& mu_b, const Expr& l, const Expr& theta, const Expr& M, const Expr& g, const Expr& L2) {
  return (num(1) - mu_b * (l - num(1)) / num(2)) * (num(1) + cos_deg(theta)) * M * g * L2;
}
// Largest relative change of R or T per relative change of the givens, whose laws have the
// exponents (p1, q1) and (p2, q2): the infinity norm of the inverse of eq:ZiZj_RT.
Expr amplification_of(const Expr& p1, const Expr& q1, const Expr& p2, const Expr& q2, const Expr& det) {
  return max(abs(q2) + abs(q1), abs(p2) + abs(p1)) / abs(det);
}

// 1 where the calculator gives a design: a segment holds the givens, the amplification is at
// most 50 and the counterweight arm L3 is positive; else 0.
// Where no segment holds the givens, the lookup's row may lie far out (a line of constant X
// bounded at |ln(R/R0)| = 50), where L3 overflows: it is not evaluated then.
Expr design_valid(const Expr& ok, const Expr& amplification, const Expr& L3) {
  return choose(ok, (num(1) - below(num(50), amplification)) * below(num(0), L3), num(0));
}

// What the calculator would say of a design sheet's or a site's givens: "ok", or why not.
Text design_status(const Expr& ok, const Expr& amplification, const Expr& L3) {
  return choose(ok,
                choose(below(num(50), amplification), literal("refused: the pair barely fixes the capacity (amplification above 50)"),
                       choose(at_most(L3, num(0)), literal("refused: no room for the counterweight arm (L3 <= 0)"), literal("ok"))),
                literal("no segment of the table holds these givens: X lies outside every interval of this block (theta_i and F choose it)"));
}

// A given of a pair as the segment table takes it: the column of its law among the constants
// sheet's quantities (from 1) and the log of its value in the table's material.
struct LawGiven {
  Expr column, log_value;
};

// What the segment table chose: `ok` when some row holds the givens, the segment (a row of the
// constants sheet), the capacity ln(R/R0), ln(T/T0) and the amplification.
struct Solution {
  Expr best, ok, segment, lr, lt, amplification;
};

// One row of the table of segments: its sheet, its row, the segment k it solves in, and the law
// of a given in that segment.
struct SegmentRow {
  Sheet& s;
  const ConstantsSheet& c;
  int row;
  Expr k;
  // c, p or q (j = 0, 1, 2) of the law in column `column` in this segment: column 3 (column - 1) + j + 1 of the laws.
  Expr law(const Expr& column, int j) const {
    const std::size_t q = static_cast<std::size_t>(column.v) - 1;
    return Expr{"INDEX(" + c.laws + "," + k.f + ",3*(" + column.f + "-1)+" + std::to_string(j + 1) + ")",
                c.law[q][j].v.at(static_cast<std::size_t>(k.v) - 1)};
  }
};

// What a row solved: ln(R/R0) and ln(T/T0), whether it found a solution, and its amplification.
struct RowSolution {
  Expr lr, lt, found, amplification;
};

// Two log-linear givens in one segment (eq:ZiZj_RT): their laws and D_ij in columns 2 to 8.
RowSolution solve_pair_row(const SegmentRow& at, const std::vector<LawGiven>& givens) {
  Sheet& s = at.s;
  const int row = at.row;
  const auto law = [&](const Expr& column, int j) { return at.law(column, j); };
  RowSolution out;
  const Expr c1 = s.formula(row, 2, law(givens[0].column, 0)), p1 = s.formula(row, 3, law(givens[0].column, 1)),
             q1 = s.formula(row, 4, law(givens[0].column, 2));
  const Expr c2 = s.formula(row, 5, law(givens[1].column, 0)), p2 = s.formula(row, 6, law(givens[1].column, 1)),
             q2 = s.formula(row, 7, law(givens[1].column, 2));
  const Expr det = s.formula(row, 8, p1 * q2 - q1 * p2);  // D_ij of eq:ZiZj_RT
  const Expr b1 = givens[0].log_value - c1, b2 = givens[1].log_value - c2;
  const Expr safe_det = choose(below(abs(det), num(1e-12)), num(1), det);
  out.lr = (b1 * q2 - q1 * b2) / safe_det;
  out.lt = (p1 * b2 - b1 * p2) / safe_det;
  out.found = num(1) - below(abs(det), num(1e-12));
  out.amplification = amplification_of(p1, q1, p2, q2, safe_det);
  return out;
}

// Lb and one log-linear given in one segment: the root (1: left of the minimum, 2: right) of the
// excess of log(L1 + L2) over log Lb along the line where the given holds, by Newton's method
// from the segment's end on that side (columns 2 to 8 and 18 on).
RowSolution solve_beam_row(const SegmentRow& segment_row, const LawGiven& given, const Expr& log_Lb, int r, int iterations) {
  Sheet& s = segment_row.s;
  const ConstantsSheet& c = segment_row.c;
  const int row = segment_row.row;
  const Expr& k = segment_row.k;
  const auto law = [&](const Expr& column, int j) { return segment_row.law(column, j); };
  const Expr sqrt26 = sqrt(num(26));
  RowSolution out;
  const Expr cA = s.formula(row, 2, law(given.column, 0)), pA = s.formula(row, 3, law(given.column, 1)), qA = s.formula(row, 4, law(given.column, 2));
  const Expr root = s.number(row, 5, r % 2 + 1);  // 1: left of the minimum, 2: right
  // The line ln A = c + p lr + q lt: its point nearest the origin and its unit direction.
  const Expr norm = sqrt(pA * pA + qA * qA), b = (given.log_value - cA) / norm;
  const Expr lr0 = s.formula(row, 19, pA / norm * b), lt0 = s.formula(row, 20, qA / norm * b);
  const Expr dr = s.formula(row, 21, qA / norm), dt = s.formula(row, 22, num(0) - pA / norm);
  // ln L1 = alpha1 + beta1 s and ln L2 = alpha2 + beta2 s along the line (eq:ZRT).
  const Expr L1_column = num(3), L2_column = num(4);  // L1 and L2 among the quantities
  auto along = [&](const Expr& column, int col) {
    const Expr alpha = s.formula(row, col, law(column, 0) + law(column, 1) * lr0 + law(column, 2) * lt0);
    const Expr beta = s.formula(row, col + 1, law(column, 1) * dr + law(column, 2) * dt);
    return std::pair{alpha, beta};
  };
  // Named, not bound: a lambda below uses them, which structured bindings allow only from C++20 (clang 14 refuses).
  const std::pair<Expr, Expr> line1 = along(L1_column, 23), line2 = along(L2_column, 25);
  const Expr &alpha1 = line1.first, &beta1 = line1.second, &alpha2 = line2.first, &beta2 = line2.second;
  // The part of the line inside the segment's X interval; where X is constant along it (the
  // beam ratio l) the line is bounded by |ln(R/R0)|, |ln(T/T0)| <= 50, beyond any engine.
  const Expr dX = (num(5) * dr - dt) / sqrt26, X0 = (num(5) * lr0 - lt0) / sqrt26;
  const Expr flat = below(abs(dX), num(1e-12));
  const Expr safe_dX = choose(flat, num(1), dX);
  const Expr to_min = (element(c.X_min, k) - X0) / safe_dX, to_max = (element(c.X_max, k) - X0) / safe_dX;
  const Expr lo = s.formula(row, 6, choose(flat, num(-50), min(to_min, to_max)));
  const Expr hi = s.formula(row, 7, choose(flat, num(50), max(to_min, to_max)));
  // ln(L1 + L2) - ln Lb and its slope, with the larger exponent taken out, so that no EXP overflows far along the line.
  auto excess = [&](const Expr& at) {
    const Expr a1 = alpha1 + beta1 * at, a2 = alpha2 + beta2 * at, top = max(a1, a2);
    return top + ln(exp(a1 - top) + exp(a2 - top)) - log_Lb;
  };
  auto slope = [&](const Expr& at) {
    const Expr a1 = alpha1 + beta1 * at, a2 = alpha2 + beta2 * at, top = max(a1, a2);
    const Expr w1 = exp(a1 - top), w2 = exp(a2 - top);
    return (beta1 * w1 + beta2 * w2) / (w1 + w2);
  };
  // The minimum of the convex excess: where the slopes of the two exponentials cancel, or an end.
  const Expr stationary = (ln(num(0) - beta2 / beta1) - alpha1 + alpha2) / (beta1 - beta2);
  const Expr s_min = s.formula(
      row, 8, choose(below(beta1 * beta2, num(0)), min(max(stationary, lo), hi), choose(at_most(num(0), beta1) * at_most(num(0), beta2), lo, hi)));
  const Expr left = equal(root, num(1));
  const Expr start = choose(left, lo, hi);
  out.found = s.formula(row, 18, at_most(excess(s_min), num(0)) * at_most(num(0), excess(start)) * choose(left, below(lo, s_min), below(s_min, hi)));
  Expr at = s.formula(row, 27, start);
  for (int n = 1; n <= iterations; ++n) at = s.formula(row, 27 + n, choose(out.found, at - excess(at) / slope(at), at));
  out.lr = lr0 + at * dr;
  out.lt = lt0 + at * dt;
  // The local law of ln Lb, the weighted mean of L1's and L2's, gives the pair's conditioning.
  const Expr w1 = exp(alpha1 + beta1 * at - max(alpha1 + beta1 * at, alpha2 + beta2 * at)),
             w2 = exp(alpha2 + beta2 * at - max(alpha1 + beta1 * at, alpha2 + beta2 * at));
  const Expr pLb = (w1 * law(L1_column, 1) + w2 * law(L2_column, 1)) / (w1 + w2);
  const Expr qLb = (w1 * law(L1_column, 2) + w2 * law(L2_column, 2)) / (w1 + w2);
  const Expr det = pA * qLb - qA * pLb;
  out.amplification = choose(out.found, amplification_of(pA, qA, pLb, qLb, choose(below(abs(det), num(1e-300)), num(1), det)), num(0));
  return out;
}

// The table of segments from row `header` down: each row solves the givens in one segment,
// computes X (eq:Xi), whether X lies inside the segment, and a score that prefers the branch with
// the higher Q (lower below X_d, upper above; section 6.2), then the depth inside. Two
// log-linear givens take one row per segment (eq:ZiZj_RT). With `log_Lb` (Lb = L1 + L2, not
// log-linear) and one log-linear given, log Lb along the line where the given holds is the log
// of a sum of two exponentials of the line's parameter s, convex, with at most two roots: two
// rows per segment, the root left and right of the minimum, each found by Newton's method,
// which from the side where the excess is positive climbs a convex function's root monotonically.
Solution solve_in_segments(Sheet& s, int header, const ConstantsSheet& c, const Expr& theta, const Expr& F, const Text& branch,
                           const std::vector<LawGiven>& givens, const std::optional<Expr>& log_Lb) {
  const bool beam = log_Lb.has_value();
  const int per_segment = beam ? 2 : 1, first = header + 1, last = first + per_segment * c.rows - 1;
  constexpr int iterations = 24;  // Newton's steps: the 168 roots of the test converge to 1e-14 within 7
  // Columns 2 to 8 hold the pair's laws and D_ij, or for Lb the other given's law and the line's span.
  const std::vector<std::string> pair_columns = {"c1", "p1", "q1", "c2", "p2", "q2", "D_ij"};
  const std::vector<std::string> beam_columns = {"c", "p", "q", "root", "s_lo", "s_hi", "s_min"};
  std::vector<std::string> columns = {"segment", "block"};
  columns.insert(columns.end(), beam ? beam_columns.begin() : pair_columns.begin(), beam ? beam_columns.end() : pair_columns.end());
  for (const char* name : {"ln(R/R0)", "ln(T/T0)", "X", "inside", "allowed", "preferred", "depth", "score", "amplification"}) columns.push_back(name);
  if (beam) {
    for (const char* name : {"found", "lr0", "lt0", "dr", "dt", "alpha1", "beta1", "alpha2", "beta2"}) columns.push_back(name);
    for (int n = 0; n <= iterations; ++n) columns.push_back("s" + std::to_string(n));
  }
  for (std::size_t k = 0; k < columns.size(); ++k) s.heading(header, static_cast<int>(k), columns[k]);
  s.text(header - 1, 0,
         beam ? "Every segment of the table, twice: the roots of log Lb on the line where the other given holds, left and right of its "
                "minimum (Newton's method from the segment's ends); the highest score is the engine above."
              : "Every segment of the table, solved (eq:ZiZj_RT); the highest score is the engine above.");
  Column segment_col, lr_col, lt_col, score_col, amp_col;
  const Expr sqrt26 = sqrt(num(26));
  const Expr automatic = is(branch, "auto");
  for (int r = 0; r < per_segment * c.rows; ++r) {
    const int row = first + r;
    const Expr k = s.number(row, 0, r / per_segment + 1);
    const Expr block = s.formula(row, 1, equal(theta, element(c.theta, k)) * below(abs(F - element(c.F, k)), num(1e-9)));
    const SegmentRow at{s, c, row, k};
    const RowSolution solved = beam ? solve_beam_row(at, givens[0], *log_Lb, r, iterations) : solve_pair_row(at, givens);
    const Expr &lr = solved.lr, &lt = solved.lt, &found = solved.found, &amplification = solved.amplification;
    const Expr lr_cell = s.formula(row, 9, lr), lt_cell = s.formula(row, 10, lt);
    const Expr X = s.formula(row, 11, (num(5) * lr_cell - lt_cell) / sqrt26);  // eq:XY_RT
    const Expr X_min = element(c.X_min, k), X_max = element(c.X_max, k);
    const Expr inside = s.formula(row, 12, block * at_most(X_min - num(1e-12), X) * at_most(X, X_max + num(1e-12)) * found);
    const Text segment_branch = element(c.branch, k);
    const Expr allowed = s.formula(row, 13, either(either(is(segment_branch, "none"), automatic), same(segment_branch, branch)));
    const Expr X_d = element(c.X_d, k);
    const Expr preferred = s.formula(
        row, 14, choose(is(segment_branch, "lower"), below(X, X_d), choose(is(segment_branch, "upper"), at_most(X_d, X), num(1))));
    const Expr depth = s.formula(row, 15, min(X - X_min, X_max - X));
    const Expr score = s.formula(row, 16, inside * allowed * (num(10) + num(5) * automatic * preferred + depth));
    const Expr amp = s.formula(row, 17, amplification);
    segment_col.v.push_back(k.v), lr_col.v.push_back(lr_cell.v), lt_col.v.push_back(lt_cell.v), score_col.v.push_back(score.v),
        amp_col.v.push_back(amp.v);
  }
  segment_col.f = s.range(first, last, 0), lr_col.f = s.range(first, last, 9), lt_col.f = s.range(first, last, 10);
  score_col.f = s.range(first, last, 16), amp_col.f = s.range(first, last, 17);
  Solution out;
  out.best = largest(score_col);
  out.ok = at_most(num(10), out.best);
  const Expr row = first_largest(score_col);
  out.segment = element(segment_col, row);
  out.lr = element(lr_col, row), out.lt = element(lt_col, row);
  out.amplification = element(amp_col, row);
  return out;
}

// The branch a sheet's user picks, in the order of BranchChoice (the list ends in nullptr, as choices takes it).
const char* branch_choices[] = {"auto", "lower", "upper", nullptr};

// What a design sheet's user types: the givens' names and values, theta_i, F and the branch.
struct DesignSheetInputs {
  std::array<Text, 2> names;
  std::array<Expr, 2> values;
  Expr theta, F;
  Text branch;
};

// The design sheet's yellow cells, opened on `request`; the first `fixed` givens' names fixed.
DesignSheetInputs write_design_inputs(Sheet& s, const DesignRequest& request, int fixed) {
  DesignSheetInputs in;
  std::array<Text, 2>& names = in.names;
  std::array<Expr, 2>& values = in.values;
  const Given givens[] = {request.first, request.second};
  // The log-linear givens, picked from a list; Lb is a sheet of its own.
  static std::vector<const char*> quantities = [] {
    std::vector<const char*> names;
    for (Quantity q : log_linear) names.push_back(quantity_name(q).data());
    names.push_back(nullptr);
    return names;
  }();
  const std::vector<std::string> listed(quantities.begin(), quantities.end() - 1);
  for (int k = 0; k < 2; ++k) {
    const int row = 3 + 2 * k;
    const std::string which = k == 0 ? "first" : "second";
    const std::string quantity(quantity_name(givens[k].quantity));
    s.describe(row, which + " given", "", k < fixed ? "fixed on this sheet" : "one of " + join(listed, ", ") + " (Lb: the sheet 'from Lb and one')");
    names[k] = k < fixed ? s.text_cell(row, 1, quantity) : s.input_text(row, 1, quantity);
    if (k >= fixed) s.choices(row, 1, quantities.data());
    s.describe(row + 1, which + " value", "", "a number in SI base units, as the unit beside it says: 250 for 250 m, 3110 for 3.11 t");
    values[k] = s.number_input(row + 1, 1, givens[k].value,
                               "Type a number alone, in the unit shown beside it (m, J or kg): 250 for 250 m, 3110 for 3.11 t.");
  }
  s.describe(7, "theta_i", "deg", "initial beam angle; the table has the blocks on the constants sheet");
  in.theta = s.number_input(7, 1, request.theta_i_deg, "Type the angle in degrees, a number from 0 to 90: 30 for 30 deg.", 0, 90);
  s.describe(8, "F", "", "(L2 + L3)/H; type =2/3 for two thirds");
  in.F = s.number_input(8, 1, request.F, "Type a positive number, or =2/3 for two thirds.");
  s.describe(9, "branch", "", "auto, lower or upper: two optima compete where the branches overlap (section 6.2)");
  in.branch = s.input_text(9, 1, branch_choices[static_cast<int>(request.branch)]);
  s.choices(9, 1, branch_choices);
  return in;
}

// Which law each log-linear given follows (its column among the quantities, rows 11 and 12),
// its unit beside it, and its value's log in the table's material (rows 13 and 14); a first
// given Lb as its log alone (`log_Lb`).
std::vector<LawGiven> given_laws(Sheet& s, const ConstantsSheet& c, const MaterialFactors& f, const DesignSheetInputs& in, bool beam,
                                 std::optional<Expr>& log_Lb) {
  const std::array<Text, 2>& names = in.names;
  const std::array<Expr, 2>& values = in.values;
  std::vector<LawGiven> laws;
  if (beam) {
    s.text(4, 2, "m");
    log_Lb = s.formula_row(13, "ln of the first given", ln(values[0]), "", "ln Lb: a length, the same in every material");
  }
  for (int k = beam ? 1 : 0; k < 2; ++k) {
    const auto found = std::find_if(log_linear.begin(), log_linear.end(), [&](Quantity q) { return quantity_name(q) == names[k].v; });
    // Its column among the quantity names, matched case-sensitively (0 if none).
    const Expr position{"SUMPRODUCT(EXACT(" + c.quantity_names + "," + names[k].f + ")*(COLUMN(" + c.quantity_names + ")-1))",
                        found == log_linear.end() ? 0.0 : static_cast<double>(found - log_linear.begin() + 1)};
    const Expr column = s.formula_row(11 + k, std::string(k == 0 ? "first" : "second") + " given's column", position, "",
                                      "its place among the quantities of the constants sheet");
    // Masses, D and T of the table are in its own material: divide by the factors (section 7).
    std::string choose_factor = "CHOOSE(" + column.f;
    for (Quantity q : log_linear) choose_factor += "," + material_factor(f, q).f;
    const Expr factor{choose_factor + ")", material_factor(f, log_linear[static_cast<std::size_t>(column.v) - 1]).v};
    // The unit of the given's value, beside it.
    static const char* units[] = {"m", "J", "m", "m", "m", "m", "kg", "kg", "kg", "(pure number)"};
    std::string unit_choice = "CHOOSE(" + column.f;
    for (const char* unit : units) unit_choice += ",\"" + std::string(unit) + "\"";
    s.formula(4 + 2 * k, 2, Text{unit_choice + ")", units[static_cast<std::size_t>(column.v) - 1]});
    laws.push_back({column,
                    s.formula_row(13 + k, std::string("ln of the ") + (k == 0 ? "first" : "second") + " given", ln(values[k] / factor), "",
                                  "in the table's material: masses, D and T divided by the material sheet's factors")});
  }

  return laws;
}

// A design sheet: the optimal engine for two givens, solved in every segment of the table, the
// segment whose interval holds the solution's X (eq:Xi) chosen by a lookup. `fixed` says how
// many of the givens' names are fixed (2 for R and T, 1 for R or Lb and one parameter, 0 for any
// pair). A first given Lb makes the sheet for Lb and one log-linear parameter.
struct DesignResult {
  Expr valid;  // 1 when the request gives an engine, else 0
  Expr R, T, L1, L2, L3, L4, D, M, m, mb;  // what the model-scaling sheet takes from it
};

DesignResult write_design(lxw_workbook* book, Formats& formats, const std::string& name, const std::string& heading, const ConstantsSheet& c,
                          const MaterialFactors& f, const DesignRequest& request, int fixed, const std::string& refusal) {
  const bool beam = request.first.quantity == Quantity::Lb;
  Sheet s(book, name, formats);
  s.title(heading,
          beam ? "Type the yellow cells. The rows below find Lb on the line where the other given holds, in every segment of the table, "
                 "and keep the one whose interval holds X; the engine follows from eq:ZRT."
               : "Type the yellow cells. The rows below solve eq:ZiZj_RT in every segment of the table and keep the one whose "
                 "interval holds X; the engine follows from eq:ZRT.");
  if (!refusal.empty()) s.note(2, refusal);  // why the givens it opened on give no engine, in the calculator's words
  const DesignSheetInputs in = write_design_inputs(s, request, fixed);
  const Expr &theta = in.theta, &F = in.F;
  const Text& branch = in.branch;

  std::optional<Expr> log_Lb;
  const std::vector<LawGiven> laws = given_laws(s, c, f, in, beam, log_Lb);
  const Solution solved = solve_in_segments(s, 40, c, theta, F, branch, laws, log_Lb);
  const Expr best = s.formula_row(16, "best score", solved.best, "", "0: no segment of the table holds the solution");
  s.formula_row(17, "segment", solved.segment, "", "the segment whose interval holds X: the row below with the best score");
  const Expr lr = solved.lr, lt = solved.lt, amplification = solved.amplification, k = solved.segment;
  const Expr ok = at_most(num(10), best);
  // The status first: a refused request leaves every result blank, so that it never looks like one.
  const Expr L3 = counterweight_arm(F, theta, fitted(c, f, Param::L1, k, lr, lt), fitted(c, f, Param::L2, k, lr, lt));
  s.text_row(19, "status", design_status(ok, amplification, L3), "what the calculator would say; the results below are blank unless it is ok");
  DesignResult out;
  out.valid = s.formula_row(20, "valid", design_valid(ok, amplification, L3), "", "1 when the status is ok, else 0");
  s.text_row(21, "segment branch", element(c.branch, k), "the branch of the chosen segment (section 6.2)");
  s.heading(22, 0, "the optimal engine");
  int row = 23;
  auto output = [&](const std::string& label, const Expr& e, const std::string& unit, const std::string& note) {
    return s.result_row(row++, label, out.valid, e, unit, note);
  };
  const Expr sqrt26 = sqrt(num(26));
  out.R = output("R", c.R0 * exp(lr), "m", "range in vacuum at the base level (eq:ZRT with Z = R)");
  out.T = output("T", target_energy(c, f, lt), "J", "energy at the target (eq:T), in your material");
  output("T in kJ", out.T / num(1000), "kJ", "the same energy in kilojoules");
  output("X", (num(5) * lr - lt) / sqrt26, "", "eq:Xi: (5 ln(R/R0) - ln(T/T0))/sqrt(26)");
  output("Y", (lr + num(5) * lt) / sqrt26, "", "eq:XY_RT");
  // The engine's values under their keys, units and labels (fields.hpp), with where each comes from.
  auto engine_output = [&](std::optional<double> V::*member, const Expr& e, const std::string& source) {
    const InputField& field = field_of(member);
    return output(field.key, e, sheet_unit(field), std::string(field.label) + " (" + source + ")");
  };
  out.L1 = engine_output(&V::L1, fitted(c, f, Param::L1, k, lr, lt), "eq:ZRT");
  out.L2 = engine_output(&V::L2, fitted(c, f, Param::L2, k, lr, lt), "eq:ZRT");
  out.L3 = engine_output(&V::L3, counterweight_arm(F, theta, out.L1, out.L2), "L2 + L3 = F H, H = L1 cos(theta_i), section 2");
  out.L4 = engine_output(&V::L4, fitted(c, f, Param::L4, k, lr, lt), "eq:ZRT");
  out.D = engine_output(&V::D, fitted(c, f, Param::D, k, lr, lt), "eq:ZRT, eq:bend_L2");
  out.M = engine_output(&V::M, fitted(c, f, Param::M, k, lr, lt), "eq:ZRT");
  output("M in t", out.M / num(1000), "t", "the same counterweight in tonnes");
  out.m = engine_output(&V::m, fitted(c, f, Param::m, k, lr, lt), "eq:ZRT");
  out.mb = engine_output(&V::mb, fitted(c, f, Param::mb, k, lr, lt), "eq:ZRT");
  if (beam) output("Lb", out.L1 + out.L2, "m", "beam length L1 + L2: the given, back");
  output("amplification", amplification, "",
         "relative change of R or T per relative change of a given (eq:ZiZj_RT); above 10 ill-conditioned, above 50 refused");
  worksheet_print_area(s.raw(), 0, 0, static_cast<lxw_row_t>(row), 3);
  return out;
}

// The paper's historical sites (section 7.1, sec:AVS; tab:Alcala_la_Vieja): 50 kg stones,
// theta_i = 30 deg, F = 2/3. Each row's R and m give T and the optimal engine by the same
// segment table and eq:ZRT as the design sheets, beside the numbers the table prints.
struct PrintedSite {
  const char* site;
  const char* level;  // [m], in brackets where the paper ignores it
  double level_m, R;  // [m]
  // T [kJ], L1, L2, L4, D [m], M [t], mb [kg], eps [%], v [m/s], h [m], A [deg], as printed
  std::array<const char*, 11> printed;
};
const PrintedSite paper_sites[] = {
    {"Ca", "(-15)", -15, 150, {"40.3", "4.13", "0.88", "3.55", "0.25", "3.11", "174", "90.0", "37.7", "10.0", "40.3"}},
    {"Ma", "(-54)", -54, 480, {"124", "5.50", "0.71", "5.15", "0.31", "11.5", "334", "92.8", "68.5", "13.8", "39.1"}},
    {"Ma", "-54", -54, 426, {"111", "5.36", "0.75", "4.96", "0.31", "9.70", "320", "92.5", "64.5", "13.5", "39.1"}},
    {"Sa", "(-20)", -20, 250, {"66.0", "4.72", "0.85", "4.19", "0.28", "5.16", "242", "91.4", "49.1", "11.7", "39.7"}},
};

void write_sites(lxw_workbook* book, Formats& formats, const ConstantsSheet& c, const MaterialFactors& f) {
  Sheet s(book, "sites", formats);
  s.title("The paper's sites (section 7.1, sec:AVS, tab:Alcala_la_Vieja): 50 kg stones, theta_i = 30 deg, F = 2/3",
          "Type R, m or the level in the yellow cells. Each site's T and engine follow from R and m as on the sheet 'from R and one' "
          "(eq:RT_ZiZj, eq:ZRT); below each, the paper's printed row and how far the workbook lies from it.");
  worksheet_set_column(s.raw(), 0, 0, 26, nullptr);
  worksheet_set_column(s.raw(), 1, 14, 9, nullptr);
  worksheet_set_column(s.raw(), 15, 15, 40, nullptr);
  s.describe(3, "theta_i", "", "");
  const Expr theta = s.number(3, 1, 30);
  s.text(3, 2, "deg: the paper's, for every site");
  s.describe(4, "F", "", "");
  const Expr F = s.formula(4, 1, num(2) / num(3), formats.four_digits(2.0 / 3));
  s.text(4, 2, "(L2 + L3)/H: the paper's, for every site");
  const char* headings[] = {"site", "level", "R", "m", "T", "L1", "L2", "L4", "D", "M", "mb", "eps", "v", "h", "A", "status", "valid"};
  const char* units[] = {"", "m", "m", "kg", "kJ", "m", "m", "m", "m", "t", "kg", "%", "m/s", "m", "deg", "", ""};
  for (int col = 0; col < 17; ++col) {
    s.heading(6, col, headings[col]);
    s.text(7, col, units[col]);
  }
  const Text automatic = literal("auto");
  const int table_rows = c.rows + 4;
  int row = 8;
  for (std::size_t k = 0; k < std::size(paper_sites); ++k, row += 4) {
    const PrintedSite& site = paper_sites[k];
    // The paper's row: its numbers with the decimals it prints.
    const int paper = row + 1;
    s.text(paper, 0, std::string(site.site) + ", the paper");
    s.text(paper, 1, site.level);
    s.number(paper, 2, site.R);
    s.number(paper, 3, 50);
    std::array<Expr, 11> printed;
    for (std::size_t j = 0; j < printed.size(); ++j) printed[j] = s.printed(paper, 4 + static_cast<int>(j), site.printed[j]);

    s.text(row, 0, std::string(site.site) + ", the workbook");
    s.input(row, 1, site.level_m);
    const Expr R = s.number_input(row, 2, site.R, "Type the range in metres, a number alone: 150 for 150 m.");
    const Expr m = s.number_input(row, 3, 50, "Type the stone's mass in kilograms, a number alone: 50 for 50 kg.");
    // R and m (the 1st and 8th quantities), m in the table's material (section 7).
    const int header = 40 + static_cast<int>(k) * table_rows;
    s.text(header - 2, 0,
           std::string("Site ") + site.site + " (row " + std::to_string(k + 1) + " of tab:Alcala_la_Vieja), R and m in every segment:");
    const Solution solved = solve_in_segments(s, header, c, theta, F, automatic, {{num(1), ln(R)}, {num(8), ln(m / f.mass)}}, std::nullopt);
    const Expr L1 = fitted(c, f, Param::L1, solved.segment, solved.lr, solved.lt);
    const Expr L2 = fitted(c, f, Param::L2, solved.segment, solved.lr, solved.lt);
    const Expr L3 = counterweight_arm(F, theta, L1, L2);
    const Expr valid = s.formula(row, 16, design_valid(solved.ok, solved.amplification, L3));
    s.formula(row, 15, design_status(solved.ok, solved.amplification, L3));
    auto result = [&](int col, const Expr& e) { return s.result(row, col, valid, e); };
    auto fit = [&](Param param) { return fitted(c, f, param, solved.segment, solved.lr, solved.lt); };
    std::array<Expr, 9> computed;  // T [kJ], L1, L2, L4, D, M [t], mb, eps [%], v
    computed[0] = result(4, target_energy(c, f, solved.lt) / num(1000));
    computed[1] = result(5, L1), computed[2] = result(6, L2), computed[3] = result(7, fit(Param::L4)), computed[4] = result(8, fit(Param::D));
    computed[5] = result(9, fit(Param::M) / num(1000)), computed[6] = result(10, fit(Param::mb));
    const Expr T = computed[0] * num(1000), M = computed[5] * num(1000);
    // eq:Aux: eps = T/DeltaU with eq:DU; v from eq:T, T = m v^2/2 + m g h, with the paper's h.
    computed[7] = result(11, num(100) * T / potential_drop(computed[6] / M, computed[1] / computed[2], theta, M, f.g, computed[2]));
    computed[8] = result(12, sqrt(num(2) * (T / m - f.g * printed[9])));
    s.text(row + 2, 0, std::string(site.site) + ": workbook/paper - 1 [%]");
    for (std::size_t j = 0; j < computed.size(); ++j)
      s.result(row + 2, 4 + static_cast<int>(j), valid, num(100) * (computed[j] / printed[j] - num(1)));
  }
  s.text(row, 0, "eps is eq:Aux, T/DeltaU with eq:DU; v is eq:T, T = m v^2/2 + m g h, solved with the paper's h.");
  s.text(row + 1, 0, "h and A of the paper come from its simulation of each shot, not from eq:ZRT: trebuchet-verify shot computes them.");
  s.text(row + 2, 0,
         "The level (of the target, relative to the engine) is the paper's: it is ignored where it is in brackets, and the row "
         "without brackets aims 54 m short of 480 m (sec:AVS); it does not enter the formulas.");
  worksheet_print_area(s.raw(), 0, 0, static_cast<lxw_row_t>(row + 2), 15);
}

// Where the sheet of sites puts a row's cells: the sites from row first_row down, and in each,
// after the line and the passed-through columns, the two givens, theta_i, F, the branch, the
// status, valid, then the engine's values.
struct SitesLayout {
  static constexpr int first_row = 6;
  explicit SitesLayout(int passed)
      : passed(passed),
        given_col(passed + 1),
        theta_col(passed + 3),
        F_col(passed + 4),
        branch_col(passed + 5),
        status_col(passed + 6),
        valid_col(passed + 7),
        out_col(passed + 8) {}
  int passed, given_col, theta_col, F_col, branch_col, status_col, valid_col, out_col;
};

// One site's row `row` (its k-th, its table of segments at `tables` below the rows): its givens,
// theta_i, F and branch as inputs, the engine by the segment table of the pair `a`, `b` (Lb
// first, `swap` where the file gives it second).
void write_site_row(Sheet& s, const ConstantsSheet& c, const MaterialFactors& f, const UserSites& sites, std::size_t k, const SitesLayout& layout,
                    Quantity a, Quantity b, bool swap, int tables) {
  const int passed = layout.passed, given_col = layout.given_col, theta_col = layout.theta_col, F_col = layout.F_col, branch_col = layout.branch_col,
            status_col = layout.status_col, valid_col = layout.valid_col, out_col = layout.out_col;
  const bool beam = a == Quantity::Lb;
  const int first_row = SitesLayout::first_row, table_rows = (beam ? 2 : 1) * c.rows + 4;
  // A given's column among the constants sheet's laws (from 1).
  const auto law_column = [](Quantity q) {
    return num(static_cast<double>(std::find(log_linear.begin(), log_linear.end(), q) - log_linear.begin() + 1));
  };
  const SiteRow& site = sites.rows[k];
  const int row = first_row + static_cast<int>(k);
  s.number(row, 0, site.line);
  for (int p = 0; p < passed; ++p) s.text(row, 1 + p, site.passed[static_cast<std::size_t>(p)]);
  s.text(row, out_col + 12, site.refusal.empty() ? "ok" : site.refusal);
  if (!site.request) {
    s.text(row, status_col, "refused when read: see the calculator's message; correct the file and write the workbook again");
    return;
  }
  const DesignRequest& r = *site.request;
  const Expr v1 = s.number_input(row, given_col, r.first.value, "Type a number alone, in the unit under the column's name.");
  const Expr v2 = s.number_input(row, given_col + 1, r.second.value, "Type a number alone, in the unit under the column's name.");
  const Expr value_a = swap ? v2 : v1, value_b = swap ? v1 : v2;
  const Expr theta = s.number_input(row, theta_col, r.theta_i_deg, "Type the angle in degrees, a number from 0 to 90: 30 for 30 deg.", 0, 90);
  const Expr F = s.number_input(row, F_col, r.F, "Type a positive number, or =2/3 for two thirds.");
  const Text branch = s.input_text(row, branch_col, branch_choices[static_cast<int>(r.branch)]);
  s.choices(row, branch_col, branch_choices);
  const int header = tables + static_cast<int>(k) * table_rows;
  s.text(header - 2, 0, "Line " + std::to_string(site.line) + " of " + sites.source + ", in every segment:");
  std::vector<LawGiven> laws;
  std::optional<Expr> log_Lb;
  if (beam)
    log_Lb = ln(value_a);
  else
    laws.push_back({law_column(a), ln(value_a / material_factor(f, a))});
  laws.push_back({law_column(b), ln(value_b / material_factor(f, b))});
  const Solution solved = solve_in_segments(s, header, c, theta, F, branch, laws, log_Lb);
  auto fit = [&](Param param) { return fitted(c, f, param, solved.segment, solved.lr, solved.lt); };
  const Expr L1 = fit(Param::L1), L2 = fit(Param::L2), L3 = counterweight_arm(F, theta, L1, L2);
  s.formula(row, status_col, design_status(solved.ok, solved.amplification, L3));
  const Expr valid = s.formula(row, valid_col, design_valid(solved.ok, solved.amplification, L3));
  const Expr outputs[] = {c.R0 * exp(solved.lr),
                          target_energy(c, f, solved.lt) / num(1000),
                          L1,
                          L2,
                          L3,
                          fit(Param::L4),
                          L1 * cos_deg(theta),
                          fit(Param::D),
                          fit(Param::M) / num(1000),
                          fit(Param::m),
                          fit(Param::mb),
                          (num(5) * solved.lr - solved.lt) / sqrt(num(26))};  // eq:Xi
  for (std::size_t j = 0; j < std::size(outputs); ++j) s.result(row, out_col + static_cast<int>(j), valid, outputs[j]);
}

// The user's sites (trebuchet-calc --spreadsheet FILE --batch SITES.csv): a row each, its givens,
// theta_i, F and branch typed in yellow cells, and the optimal engine by the same segment table
// and eq:ZRT as the design sheets, each row with its own table of segments below. A row whose
// cells could not be read keeps its place with the calculator's message and no formulas.
void write_user_sites(lxw_workbook* book, Formats& formats, const ConstantsSheet& c, const MaterialFactors& f, const UserSites& sites) {
  Sheet s(book, "your sites", formats);
  const std::optional<DesignRequest> example = [&]() -> std::optional<DesignRequest> {
    for (const SiteRow& site : sites.rows)
      if (site.request) return site.request;
    return std::nullopt;
  }();
  // The pair, Lb first (the segment table's one given that is not log-linear), as the file's header names it.
  const Quantity first = example ? example->first.quantity : Quantity::R, second = example ? example->second.quantity : Quantity::m;
  const bool swap = second == Quantity::Lb;
  const Quantity a = swap ? second : first, b = swap ? first : second;
  s.title("Your sites, from " + sites.source + ": " + std::to_string(sites.rows.size()) + " row(s), the optimal engine of each",
          "Type a given, theta_i, F or the branch in a yellow cell and the row follows (eq:RT_ZiZj, eq:ZRT, as on the sheet 'from R and one'; "
          "Lb as on 'from Lb and one'). Values in SI base units: 250 for 250 m, 3110 for 3.11 t. The status says why a row has no engine.");
  const SitesLayout layout(static_cast<int>(sites.columns.size()));
  const int passed = layout.passed, given_col = layout.given_col, branch_col = layout.branch_col, status_col = layout.status_col,
            valid_col = layout.valid_col, out_col = layout.out_col;
  const auto unit_of = [](Quantity q) { return sheet_unit(*find_field(quantity_name(q))); };
  std::vector<std::pair<std::string, std::string>> columns = {{"line", ""}};
  for (const std::string& name : sites.columns) columns.push_back({name, ""});
  columns.insert(columns.end(),
                 {{std::string(quantity_name(first)), unit_of(first)},
                  {std::string(quantity_name(second)), unit_of(second)},
                  {"theta_i", "deg"},
                  {"F", ""},
                  {"branch", ""},
                  {"status", ""},
                  {"valid", ""},
                  {"R", "m"},
                  {"T", "kJ"},
                  {"L1", "m"},
                  {"L2", "m"},
                  {"L3", "m"},
                  {"L4", "m"},
                  {"H", "m"},
                  {"D", "m"},
                  {"M", "t"},
                  {"m", "kg"},
                  {"mb", "kg"},
                  {"X", ""},
                  {"the calculator, when this file was written", ""}});
  const int header_row = 4, first_row = SitesLayout::first_row;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    s.heading(header_row, static_cast<int>(k), columns[k].first);
    s.text(header_row + 1, static_cast<int>(k), columns[k].second);
  }
  worksheet_set_column(s.raw(), 0, 0, 6, nullptr);
  worksheet_set_column(s.raw(), 1, static_cast<lxw_col_t>(passed), 14, nullptr);
  worksheet_set_column(s.raw(), static_cast<lxw_col_t>(given_col), static_cast<lxw_col_t>(branch_col), 9, nullptr);
  worksheet_set_column(s.raw(), static_cast<lxw_col_t>(status_col), static_cast<lxw_col_t>(status_col), 44, nullptr);
  worksheet_set_column(s.raw(), static_cast<lxw_col_t>(valid_col), static_cast<lxw_col_t>(out_col + 11), 9, nullptr);
  worksheet_set_column(s.raw(), static_cast<lxw_col_t>(out_col + 12), static_cast<lxw_col_t>(out_col + 12), 90, nullptr);
  worksheet_freeze_panes(s.raw(), static_cast<lxw_row_t>(first_row), 0);
  const int tables = first_row + static_cast<int>(sites.rows.size()) + 6;
  for (std::size_t k = 0; k < sites.rows.size(); ++k) {
    write_site_row(s, c, f, sites, k, layout, a, b, swap, tables);
  }
  const int notes = first_row + static_cast<int>(sites.rows.size()) + 1;
  s.text(notes, 0, "The status is what the calculator would say of the row as it stands; the last column, what it said of the file's row.");
  s.text(notes + 1, 0, "H = L1 cos(theta_i) and L3 from L2 + L3 = F H (section 2); masses, D and T in the material of the sheet 'material'.");
  worksheet_print_area(s.raw(), 0, 0, static_cast<lxw_row_t>(notes + 1), static_cast<lxw_col_t>(out_col + 12));
}

// The quantities that follow from an engine (section 2, eq:Design, eq:kMkD, eq:DU).
void write_derived(lxw_workbook* book, Formats& formats, const Engine& e, const Expr& g) {
  Sheet s(book, "derived", formats);
  s.title("Derived quantities of an engine (section 2, eq:Design, eq:kMkD, eq:DU)",
          "Type an engine in the yellow cells (it opens on the optimum for Alcala la Vieja, site Ca: 150 m, 50 kg); g is the material sheet's.");
  auto engine_input = [&](int row, std::optional<double> V::*member, double value) {
    const InputField& field = field_of(member);
    return s.input_row(row, field.key, value, sheet_unit(field), field.help);
  };
  const Expr L1 = engine_input(3, &V::L1, e.L1);
  const Expr L2 = engine_input(4, &V::L2, e.L2);
  const Expr L4 = engine_input(5, &V::L4, e.L4);
  const Expr M = engine_input(6, &V::M, e.M);
  const Expr m = engine_input(7, &V::m, e.m);
  const Expr mb = engine_input(8, &V::mb, e.mb);
  const Expr theta = s.input_row(9, "theta_i", e.theta_i_deg, "deg", "initial beam angle from the downward vertical");
  const Expr F = s.input_row(10, "F", arm_fraction(e), "", "(L2 + L3)/H; type =2/3 for two thirds");
  int row = 12;
  auto output = [&](const std::string& label, const Expr& value, const std::string& unit, const std::string& note) {
    return s.formula_row(row++, label, value, unit, note);
  };
  const Expr H = output("H", L1 * cos_deg(theta), "m", "pivot height H = L1 cos(theta_i) (section 2)");
  output("L3", F * H - L2, "m", "counterweight arm from L2 + L3 = F H (section 2)");
  output("Lb", L1 + L2, "m", "beam length L1 + L2");
  const Expr l = output("l", L1 / L2, "", "l = L1/L2 (eq:Design)");
  output("l4", L4 / L1, "", "l4 = L4/L1 (eq:Design)");
  output("L", (F * H - L2) / L2, "", "L = L3/L2 (eq:Design)");
  output("mu", m / M, "", "mu = m/M (eq:Design)");
  const Expr mu_b = output("mu_b", mb / M, "", "mu_b = mb/M (eq:Design)");
  output("K", (l + num(1)) / mu_b, "", "K = (l + 1)/mu_b (eq:kMkD)");
  output("DeltaU", potential_drop(mu_b, l, theta, M, g, L2), "J",
         "potential energy released by a shot (eq:DU) of an unpropped counterweight (psi_i = 0, as every design here): "
         "(1 - mu_b (l - 1)/2)(1 + cos theta_i) M g L2; a propped one adds L (1 - cos psi_i) M g L2 (trebuchet-verify --psi-i)");
}

// An optimal engine at lambda times its size stays optimal: X is unchanged (eq:ExtraScalings).
void write_model_scaling(lxw_workbook* book, Formats& formats, const DesignResult& full, double scale) {
  Sheet s(book, "model scaling", formats);
  s.title("A model of the optimal engine (eq:ExtraScalings)",
          "The full-size engine is the one on the sheet 'from R and T' (blank here when that sheet refuses its request). Lengths and R scale with "
          "lambda, D with lambda^1.5, masses with lambda^4, T with lambda^5.");
  const Expr lambda = s.input_row(3, "lambda", scale, "",
                                  "size of the model over the full size; it opens on the 80 m model of Denny's table of the 425 m engine (80/425)");
  s.heading(5, 0, "quantity");
  s.heading(5, 1, "model");
  s.heading(5, 2, "unit");
  s.heading(5, 3, "full size, and the scaling");
  // Each value with the power of lambda it scales with (eq:ExtraScalings).
  const std::tuple<std::optional<double> V::*, Expr, double> rows[] = {
      {&V::R, full.R, 1},   {&V::T, full.T, 5},   {&V::L1, full.L1, 1}, {&V::L2, full.L2, 1}, {&V::L3, full.L3, 1},
      {&V::L4, full.L4, 1}, {&V::D, full.D, 1.5}, {&V::M, full.M, 4},   {&V::m, full.m, 4},   {&V::mb, full.mb, 4}};
  int row = 6;
  for (const auto& [member, full_size, exponent] : rows) {
    const InputField& field = field_of(member);
    s.result_row(row, field.key, full.valid, full_size * power(lambda, exponent), sheet_unit(field), "");
    s.result(row, 4, full.valid, full_size);
    s.text(row, 3, "full size (column E) times lambda^" + number_text(exponent));
    ++row;
  }
}

void write_glossary(lxw_workbook* book, Formats& formats) {
  Sheet s(book, "glossary", formats);
  s.title("Glossary", "The symbols of the workbook, as in Horsdal's paper (section and equation labels in brackets).");
  // The engine's values as the table of inputs says them (fields.hpp), then the workbook's own symbols.
  std::vector<std::array<std::string, 3>> entries;
  for (auto member : {&V::R, &V::T, &V::L1, &V::L2, &V::L3, &V::L4, &V::Lb, &V::H, &V::D, &V::M, &V::m, &V::mb, &V::theta_i_deg, &V::F, &V::beta2}) {
    const InputField& field = field_of(member);
    const std::string unit = sheet_unit(field);
    entries.push_back({field.key, field.help, unit.empty() ? "dimensionless" : unit});
  }
  const std::array<std::array<const char*, 3>, 14> symbols = {{
      {"R0, T0", "reference capacity of the table", "m, J"},
      {"X", "eq:Xi: (5 ln(R/R0) - ln(T/T0))/sqrt(26); optimal engines of equal X are scaled copies", "dimensionless"},
      {"Y", "eq:XY_RT: (ln(R/R0) + 5 ln(T/T0))/sqrt(26), the size along X = const", "dimensionless"},
      {"segment", "an X interval of a (theta_i, F) block with its own constants a, p, q (tab:CPNC)", ""},
      {"branch", "where two optima compete (section 6.2): lower below X_d, upper above; none elsewhere", ""},
      {"X_d", "the X where the lower and upper branch are equally good", "dimensionless"},
      {"a, p, q", "the fitted constants of eq:ZRT: Z/Z0 = a (R/R0)^p (T/T0)^q", "dimensionless"},
      {"D_ij", "determinant of the pair's exponents (eq:ZiZj_RT); near 0 the pair barely fixes the capacity", "dimensionless"},
      {"amplification", "largest relative change of R or T per relative change of a given", "dimensionless"},
      {"l, l4, L", "L1/L2, L4/L1, L3/L2 (eq:Design)", "dimensionless"},
      {"mu, mu_b", "m/M and mb/M (eq:Design)", "dimensionless"},
      {"K", "(l + 1)/mu_b (eq:kMkD)", "dimensionless"},
      {"DeltaU", "potential energy released by a shot (eq:DU)", "J"},
      {"Q, eps", "quality and efficiency of a shot (eq:Q, eq:Aux); the verifier computes them", "dimensionless"},
  }};
  for (const auto& [symbol, meaning, unit] : symbols) entries.push_back({symbol, meaning, unit});
  entries.push_back({"k_M, k_D", "material constants of eq:kMkD: (4 pi/3) g rho^2/E and (16/3) g rho/E", "kg/m4, 1/m"});
  s.heading(3, 0, "symbol");
  s.heading(3, 1, "unit");
  s.heading(3, 3, "meaning");
  int row = 4;
  for (const auto& [symbol, meaning, unit] : entries) {
    s.text(row, 0, symbol);
    s.text(row, 1, unit);
    s.text(row, 3, meaning);
    ++row;
  }
  s.text(row + 1, 0, "Yellow cells are inputs; every other number is a formula. The verifier (trebuchet-verify) checks a design by simulating it.");
}

}  // namespace

DesignRequest SpreadsheetInputs::example(Quantity first, double first_value, Quantity second, double second_value) {
  DesignRequest request;
  request.first = {first, first_value};
  request.second = {second, second_value};
  return request;
}

DesignRequest* SpreadsheetInputs::open_on(const DesignRequest& request, std::vector<Given> givens, bool block_given) {
  const auto set_block = [&](DesignRequest& sheet) { sheet.theta_i_deg = request.theta_i_deg, sheet.F = request.F; };
  for (DesignRequest* sheet : {&capacity, &range_and_one, &any_pair, &beam_length}) {
    if (block_given) set_block(*sheet);
    sheet->branch = request.branch, sheet->material = request.material;
  }
  if (givens.empty()) return nullptr;
  if (givens.size() != 2)
    throw Error(ErrorKind::given_count,
                "{{spreadsheet}} opens on the paper's examples, or on exactly two givens; found " + std::to_string(givens.size()));
  std::sort(givens.begin(), givens.end(), [](const Given& a, const Given& b) { return a.quantity < b.quantity; });
  const bool has_R = givens[0].quantity == Quantity::R;
  if (givens[1].quantity == Quantity::Lb) std::swap(givens[0], givens[1]);
  const bool has_Lb = givens[0].quantity == Quantity::Lb;
  DesignRequest& sheet = has_Lb ? beam_length : has_R && givens[1].quantity == Quantity::T ? capacity : has_R ? range_and_one : any_pair;
  sheet.first = givens[0], sheet.second = givens[1];
  set_block(sheet);
  return &sheet;
}

DesignRequest SpreadsheetInputs::villard() {
  DesignRequest request = example(Quantity::Lb, 9, Quantity::l, 4.5);
  request.F = 1;
  return request;
}

Engine SpreadsheetInputs::alcala_ca() { return design_optimal_engine(builtin_scaling_table(), example(Quantity::R, 150, Quantity::m, 50)).engine; }

void write_spreadsheet(const ScalingTable& table, const SpreadsheetInputs& inputs, const std::string& path) {
  check_material(inputs.material);
  const DesignRequest &capacity = inputs.capacity, &range_and_one = inputs.range_and_one, &any_pair = inputs.any_pair,
                      &beam_length = inputs.beam_length;
  if (beam_length.first.quantity != Quantity::Lb || beam_length.second.quantity == Quantity::Lb)
    throw Error(ErrorKind::given_count, "the sheet 'from Lb and one' takes Lb first and one other quantity");
  for (const DesignRequest* sheet : {&capacity, &range_and_one, &any_pair, &beam_length})
    table.block(sheet->theta_i_deg, sheet->F);  // the calculator's refusal of a (theta_i, F) the table lacks
  // Written under a temporary name and moved into place when closed: a failure leaves no half workbook.
  PendingOutput output(path, "spreadsheet");
  // libxlsxwriter finds an unwritable path only when it closes the file, and says so on stderr: try it first.
  if (!std::ofstream(output.temporary(), std::ios::binary))
    throw Error(ErrorKind::usage, "{{spreadsheet}}: cannot write '" + path + "'; give a file you can write to");
  // Freed unwritten if a sheet throws; workbook_close writes and frees it otherwise.
  std::unique_ptr<lxw_workbook, decltype(&lxw_workbook_free)> owned(workbook_new(output.temporary().c_str()), lxw_workbook_free);
  lxw_workbook* book = owned.get();
  if (!book) throw Error(ErrorKind::usage, "{{spreadsheet}}: cannot write '" + path + "'; give a file you can write to");
  Formats formats{};
  formats.book = book;
  formats.title = workbook_add_format(book);
  format_set_bold(formats.title);
  format_set_font_size(formats.title, 13);
  formats.heading = workbook_add_format(book);
  format_set_bold(formats.heading);
  formats.input = workbook_add_format(book);
  format_set_bg_color(formats.input, Formats::input_colour);
  formats.note = workbook_add_format(book);
  format_set_font_color(formats.note, 0x555555);
  const ConstantsSheet constants = write_constants(book, formats, table);
  const MaterialFactors factors = write_material(book, formats, constants, inputs.material);
  const auto refusal_of = [&](const DesignRequest& sheet) { return inputs.refusal.first == &sheet ? inputs.refusal.second : std::string(); };
  const DesignResult capacity_sheet = write_design(book, formats, "from R and T", "The optimal engine for a capacity (R, T) (eq:ZRT)", constants,
                                                   factors, capacity, 2, refusal_of(capacity));
  worksheet_activate(workbook_get_worksheet_by_name(book, "from R and T"));  // it opens on the first design, not on the constants
  write_design(book, formats, "from R and one", "The optimal engine for R and one parameter (eq:RT_ZiZj with Z_i = R)", constants, factors,
               range_and_one, 1, refusal_of(range_and_one));
  write_design(book, formats, "from any pair", "The optimal engine for any two givens (eq:RT_ZiZj, eq:ZiZj_RT)", constants, factors, any_pair, 0,
               refusal_of(any_pair));
  write_design(book, formats, "from Lb and one", "The optimal engine for the beam length Lb = L1 + L2 and one parameter", constants, factors,
               beam_length, 1, refusal_of(beam_length));
  write_sites(book, formats, constants, factors);
  if (inputs.sites) {  // the user's, and the workbook opens on them
    write_user_sites(book, formats, constants, factors, *inputs.sites);
    worksheet_activate(workbook_get_worksheet_by_name(book, "your sites"));
  }
  write_derived(book, formats, inputs.engine, factors.g);
  write_model_scaling(book, formats, capacity_sheet, inputs.model_scale);
  write_glossary(book, formats);
  if (workbook_close(owned.release()) != LXW_NO_ERROR)
    throw Error(ErrorKind::usage, "{{spreadsheet}}: cannot write '" + path + "'; give a file you can write to");
  output.commit();
}

std::string overlong_cell(const std::vector<std::string>& columns, const std::vector<std::string>& passed) {
  for (std::size_t k = 0; k < passed.size() && k < columns.size(); ++k)
    if (characters(passed[k]) > max_cell_characters)
      return "column '" + columns[k] + "' holds " + std::to_string(characters(passed[k])) + " characters, more than a spreadsheet's cell holds (" +
          std::to_string(max_cell_characters) + "); shorten it";
  return "";
}

}  // namespace trebuchet
