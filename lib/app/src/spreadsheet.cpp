#include "trebuchet/app/spreadsheet.hpp"

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
#include "trebuchet/app/fields.hpp"
#include "trebuchet/app/output_files.hpp"
#include "trebuchet/app/units.hpp"

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
  std::map<std::pair<int, bool>, lxw_format*> shown;  // by kind (below) and whether it is an input

  // How a number is shown. The format is fixed when the cell is written, but the value follows
  // the inputs, so it must read well at any size: a whole number (a count, a given) in
  // General; a tiny constant in scientific notation; any other result by its size, to 3 to 5
  // significant digits, never rounding a value above 5e-5 to 0: "[>=1000]#,##0;[>=10]0.0#;0.0###"
  // (negatives take the last form). An input shows what was typed (General). Every cell keeps
  // every digit, and exports at full precision.
  lxw_format* four_digits(double value, bool is_input = false) {
    const int kind = is_input || (value == std::round(value) && std::abs(value) < 1e15) ? 0 : std::abs(value) < 1e-3 ? 1 : 2;
    lxw_format*& format = shown[{kind, is_input}];
    if (!format) {
      format = workbook_add_format(book);
      if (kind == 1) format_set_num_format(format, "0.000E+00");
      if (kind == 2) format_set_num_format(format, "[>=1000]#,##0;[>=10]0.0#;0.0###");
      if (is_input) format_set_bg_color(format, input_colour);
    }
    return format;
  }
  static constexpr lxw_color_t input_colour = 0xFFF2AB;
};

// A worksheet whose rows are label | value | unit | equation and note. Formulas refer to other
// sheets by name; references to the sheet itself are written without it.
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
  void text(int row, int col, const std::string& text) { worksheet_write_string(sheet_, row, col, text.c_str(), nullptr); }

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

// A design sheet: the optimal engine for two givens, by eq:ZiZj_RT in every segment, the segment
// whose interval holds the solution's X (eq:Xi) chosen by a lookup. `fixed` says how many of the
// givens' names are fixed (2 for R and T, 1 for R and one parameter, 0 for any pair).
struct DesignResult {
  Expr valid;  // 1 when the request gives an engine, else 0
  Expr R, T, L1, L2, L3, L4, D, M, m, mb;  // what the model-scaling sheet takes from it
};

DesignResult write_design(lxw_workbook* book, Formats& formats, const std::string& name, const std::string& heading, const ConstantsSheet& c,
                          const MaterialFactors& f, const DesignRequest& request, int fixed) {
  Sheet s(book, name, formats);
  s.title(heading,
          "Type the yellow cells. The rows below solve eq:ZiZj_RT in every segment of the table and keep the one whose "
          "interval holds X; the engine follows from eq:ZRT.");
  std::array<Text, 2> names;
  std::array<Expr, 2> values;
  const Given givens[] = {request.first, request.second};
  for (int k = 0; k < 2; ++k) {
    const int row = 3 + 2 * k;
    const std::string which = k == 0 ? "first" : "second";
    const std::string quantity(quantity_name(givens[k].quantity));
    // The calculator's givens but Lb, whose pairs are not log-linear (write_spreadsheet).
    static std::vector<const char*> quantities = [] {
      std::vector<const char*> names;
      for (Quantity q : all_quantities)
        if (q != Quantity::Lb) names.push_back(quantity_name(q).data());
      names.push_back(nullptr);
      return names;
    }();
    std::vector<std::string> listed(quantities.begin(), quantities.end() - 1);
    s.describe(row, which + " given", "", k < fixed ? "fixed on this sheet" : "one of " + join(listed, ", ") + " (Lb: use trebuchet-calc)");
    names[k] = k < fixed ? s.text_cell(row, 1, quantity) : s.input_text(row, 1, quantity);
    if (k >= fixed) s.choices(row, 1, quantities.data());
    s.describe(row + 1, which + " value", "", "a number in SI base units, as the unit beside it says: 250 for 250 m, 3110 for 3.11 t");
    values[k] = s.number_input(row + 1, 1, givens[k].value,
                               "Type a number alone, in the unit shown beside it (m, J or kg): 250 for 250 m, 3110 for 3.11 t.");
  }
  s.describe(7, "theta_i", "deg", "initial beam angle; the table has the blocks on the constants sheet");
  const Expr theta = s.number_input(7, 1, request.theta_i_deg, "Type the angle in degrees, a number from 0 to 90: 30 for 30 deg.", 0, 90);
  s.describe(8, "F", "", "(L2 + L3)/H; type =2/3 for two thirds");
  const Expr F = s.number_input(8, 1, request.F, "Type a positive number, or =2/3 for two thirds.");
  s.describe(9, "branch", "", "auto, lower or upper: two optima compete where the branches overlap (section 6.2)");
  static const char* branches[] = {"auto", "lower", "upper", nullptr};  // in the order of BranchChoice
  const Text branch = s.input_text(9, 1, branches[static_cast<int>(request.branch)]);
  s.choices(9, 1, branches);

  // Which law each given follows, and its value in the table's material.
  std::array<Expr, 2> k_of, log_of;
  for (int k = 0; k < 2; ++k) {
    const auto found = std::find_if(log_linear.begin(), log_linear.end(), [&](Quantity q) { return quantity_name(q) == names[k].v; });
    // Its column among the quantity names, matched case-sensitively (0 if none).
    const Expr position{"SUMPRODUCT(EXACT(" + c.quantity_names + "," + names[k].f + ")*(COLUMN(" + c.quantity_names + ")-1))",
                        found == log_linear.end() ? 0.0 : static_cast<double>(found - log_linear.begin() + 1)};
    k_of[k] = s.formula_row(11 + k, std::string(k == 0 ? "first" : "second") + " given's column", position, "",
                            "its place among the quantities of the constants sheet");
    // Masses, D and T of the table are in its own material: divide by the factors (section 7).
    const Expr factor{
        "CHOOSE(" + k_of[k].f + ",1," + f.energy.f + ",1,1,1," + f.diameter.f + "," + f.mass.f + "," + f.mass.f + "," + f.mass.f + ",1)",
        std::array<double, 10>{1, f.energy.v, 1, 1, 1, f.diameter.v, f.mass.v, f.mass.v, f.mass.v, 1}[static_cast<std::size_t>(k_of[k].v) - 1]};
    // The unit of the given's value, beside it.
    static const char* units[] = {"m", "J", "m", "m", "m", "m", "kg", "kg", "kg", "(pure number)"};
    std::string unit_choice = "CHOOSE(" + k_of[k].f;
    for (const char* unit : units) unit_choice += ",\"" + std::string(unit) + "\"";
    s.formula(4 + 2 * k, 2, Text{unit_choice + ")", units[static_cast<std::size_t>(k_of[k].v) - 1]});
    log_of[k] = s.formula_row(13 + k, std::string("ln of the ") + (k == 0 ? "first" : "second") + " given", ln(values[k] / factor), "",
                              "in the table's material: masses, D and T divided by the material sheet's factors");
  }

  // One row per segment: eq:ZiZj_RT, X (eq:Xi), whether X lies inside, and a score that prefers
  // the branch with the higher Q (lower below X_d, upper above; section 6.2), then depth inside.
  const int header = 40, first = 41, last = first + c.rows - 1;
  const char* columns[] = {"segment",  "block",    "c1", "p1",     "q1",      "c2",        "p2",    "q2",    "D_ij",
                           "ln(R/R0)", "ln(T/T0)", "X",  "inside", "allowed", "preferred", "depth", "score", "amplification"};
  for (int k = 0; k < 18; ++k) s.heading(header, k, columns[k]);
  s.text(header - 1, 0, "Every segment of the table, solved (eq:ZiZj_RT); the highest score is the engine above.");
  Column lr_col, lt_col, score_col, amp_col;
  const Expr sqrt26 = sqrt(num(26));
  const Expr automatic = is(branch, "auto");
  for (int r = 0; r < c.rows; ++r) {
    const int row = first + r;
    const Expr k = s.number(row, 0, r + 1);
    const Expr block = s.formula(row, 1, equal(theta, element(c.theta, k)) * below(abs(F - element(c.F, k)), num(1e-9)));
    // c, p or q (j = 0, 1, 2) of a given's law in this segment: column 3 (k - 1) + j + 1 of the laws.
    auto law = [&](int given, int j) {
      const std::size_t q = static_cast<std::size_t>(k_of[given].v) - 1;
      return Expr{"INDEX(" + c.laws + "," + k.f + ",3*(" + k_of[given].f + "-1)+" + std::to_string(j + 1) + ")",
                  c.law[q][j].v.at(static_cast<std::size_t>(r))};
    };
    const Expr c1 = s.formula(row, 2, law(0, 0)), p1 = s.formula(row, 3, law(0, 1)), q1 = s.formula(row, 4, law(0, 2));
    const Expr c2 = s.formula(row, 5, law(1, 0)), p2 = s.formula(row, 6, law(1, 1)), q2 = s.formula(row, 7, law(1, 2));
    const Expr det = s.formula(row, 8, p1 * q2 - q1 * p2);  // D_ij of eq:ZiZj_RT
    const Expr b1 = log_of[0] - c1, b2 = log_of[1] - c2;
    const Expr safe_det = choose(below(abs(det), num(1e-12)), num(1), det);
    const Expr lr = s.formula(row, 9, (b1 * q2 - q1 * b2) / safe_det);
    const Expr lt = s.formula(row, 10, (p1 * b2 - b1 * p2) / safe_det);
    const Expr X = s.formula(row, 11, (num(5) * lr - lt) / sqrt26);  // eq:XY_RT
    const Expr X_min = element(c.X_min, k), X_max = element(c.X_max, k);
    const Expr inside = s.formula(row, 12,
                                  block * at_most(X_min - num(1e-12), X) * at_most(X, X_max + num(1e-12)) * (num(1) - below(abs(det), num(1e-12))));
    const Text segment_branch = element(c.branch, k);
    const Expr allowed = s.formula(row, 13, either(either(is(segment_branch, "none"), automatic), same(segment_branch, branch)));
    const Expr X_d = element(c.X_d, k);
    const Expr preferred = s.formula(
        row, 14, choose(is(segment_branch, "lower"), below(X, X_d), choose(is(segment_branch, "upper"), at_most(X_d, X), num(1))));
    const Expr depth = s.formula(row, 15, min(X - X_min, X_max - X));
    const Expr score = s.formula(row, 16, inside * allowed * (num(10) + num(5) * automatic * preferred + depth));
    const Expr amplification = s.formula(row, 17, max(abs(q2) + abs(q1), abs(p2) + abs(p1)) / abs(safe_det));
    lr_col.v.push_back(lr.v), lt_col.v.push_back(lt.v), score_col.v.push_back(score.v), amp_col.v.push_back(amplification.v);
  }
  lr_col.f = s.range(first, last, 9), lt_col.f = s.range(first, last, 10);
  score_col.f = s.range(first, last, 16), amp_col.f = s.range(first, last, 17);

  const Expr best = s.formula_row(16, "best score", largest(score_col), "", "0: no segment of the table holds the solution");
  const Expr k = s.formula_row(17, "segment", first_largest(score_col), "", "the row below with the best score: the segment whose interval holds X");
  const Expr lr = element(lr_col, k), lt = element(lt_col, k);
  const Expr amplification = element(amp_col, k);
  const Expr ok = at_most(num(10), best);
  auto Z = [&](Param param) {  // eq:ZRT
    const int z = index(param);
    return element(c.a[z], k) * element(c.Z0[z], k) * exp(element(c.p[z], k) * lr + element(c.q[z], k) * lt);
  };
  // The status first: a refused request leaves every result blank, so that it never looks like one.
  const Expr L1 = Z(Param::L1), L2 = Z(Param::L2), L3 = F * L1 * cos_deg(theta) - L2;
  const Text status = choose(ok,
                             choose(below(num(50), amplification), literal("refused: the pair barely fixes the capacity (amplification above 50)"),
                                    choose(at_most(L3, num(0)), literal("refused: no room for the counterweight arm (L3 <= 0)"), literal("ok"))),
                             literal("no segment of the table holds these givens: X lies outside every interval of this block"));
  s.text_row(19, "status", status, "what the calculator would say; the results below are blank unless it is ok");
  DesignResult out;
  out.valid = s.formula_row(20, "valid", ok * (num(1) - below(num(50), amplification)) * below(num(0), L3), "", "1 when the status is ok, else 0");
  s.text_row(21, "segment branch", element(c.branch, k), "the branch of the chosen segment (section 6.2)");
  s.heading(22, 0, "the optimal engine");
  int row = 23;
  auto output = [&](const std::string& label, const Expr& e, const std::string& unit, const std::string& note) {
    return s.result_row(row++, label, out.valid, e, unit, note);
  };
  out.R = output("R", c.R0 * exp(lr), "m", "range in vacuum at the base level (eq:ZRT with Z = R)");
  out.T = output("T", c.T0 * exp(lt) * f.energy, "J", "energy at the target (eq:T), in your material");
  output("T in kJ", out.T / num(1000), "kJ", "the same energy in kilojoules");
  output("X", (num(5) * lr - lt) / sqrt26, "", "eq:Xi: (5 ln(R/R0) - ln(T/T0))/sqrt(26)");
  output("Y", (lr + num(5) * lt) / sqrt26, "", "eq:XY_RT");
  // The engine's values under their keys, units and labels (fields.hpp), with where each comes from.
  auto engine_output = [&](std::optional<double> V::*member, const Expr& e, const std::string& source) {
    const InputField& field = field_of(member);
    return output(field.key, e, sheet_unit(field), std::string(field.label) + " (" + source + ")");
  };
  out.L1 = engine_output(&V::L1, L1, "eq:ZRT");
  out.L2 = engine_output(&V::L2, L2, "eq:ZRT");
  out.L3 = engine_output(&V::L3, F * out.L1 * cos_deg(theta) - out.L2, "L2 + L3 = F H, H = L1 cos(theta_i), section 2");
  out.L4 = engine_output(&V::L4, Z(Param::L4), "eq:ZRT");
  out.D = engine_output(&V::D, Z(Param::D) * f.diameter, "eq:ZRT, eq:bend_L2");
  out.M = engine_output(&V::M, Z(Param::M) * f.mass, "eq:ZRT");
  output("M in t", out.M / num(1000), "t", "the same counterweight in tonnes");
  out.m = engine_output(&V::m, Z(Param::m) * f.mass, "eq:ZRT");
  out.mb = engine_output(&V::mb, Z(Param::mb) * f.mass, "eq:ZRT");
  output("amplification", amplification, "",
         "relative change of R or T per relative change of a given (eq:ZiZj_RT); above 10 ill-conditioned, above 50 refused");
  worksheet_print_area(s.raw(), 0, 0, static_cast<lxw_row_t>(row), 3);
  return out;
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
  output("DeltaU", (num(1) - mu_b * (l - num(1)) / num(2)) * (num(1) + cos_deg(theta)) * M * g * L2, "J",
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

Engine SpreadsheetInputs::alcala_ca() { return design_optimal_engine(builtin_scaling_table(), example(Quantity::R, 150, Quantity::m, 50)).engine; }

void write_spreadsheet(const ScalingTable& table, const SpreadsheetInputs& inputs, const std::string& path) {
  check_material(inputs.material);
  for (const DesignRequest* sheet : {&inputs.capacity, &inputs.range_and_one, &inputs.any_pair}) {
    table.block(sheet->theta_i_deg, sheet->F);  // the calculator's refusal of a (theta_i, F) the table lacks
    for (const Given& given : {sheet->first, sheet->second})
      if (given.quantity == Quantity::Lb)
        throw Error(ErrorKind::given_count,
                    "the workbook's pairs are log-linear (eq:RT_ZiZj), and Lb = L1 + L2 is not; give l = L1/L2 "
                    "instead, or design with Lb in trebuchet-calc itself");
  }
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
  const DesignResult capacity = write_design(book, formats, "from R and T", "The optimal engine for a capacity (R, T) (eq:ZRT)", constants, factors,
                                             inputs.capacity, 2);
  worksheet_activate(workbook_get_worksheet_by_name(book, "from R and T"));  // it opens on the first design, not on the constants
  write_design(book, formats, "from R and one", "The optimal engine for R and one parameter (eq:RT_ZiZj with Z_i = R)", constants, factors,
               inputs.range_and_one, 1);
  write_design(book, formats, "from any pair", "The optimal engine for any two givens (eq:RT_ZiZj, eq:ZiZj_RT)", constants, factors, inputs.any_pair,
               0);
  write_derived(book, formats, inputs.engine, factors.g);
  write_model_scaling(book, formats, capacity, inputs.model_scale);
  write_glossary(book, formats);
  if (workbook_close(owned.release()) != LXW_NO_ERROR)
    throw Error(ErrorKind::usage, "{{spreadsheet}}: cannot write '" + path + "'; give a file you can write to");
  output.commit();
}

}  // namespace trebuchet
