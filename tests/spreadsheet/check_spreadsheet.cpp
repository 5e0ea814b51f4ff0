// The workbook of trebuchet-calc --spreadsheet in a real spreadsheet program (issue 15).
// check-spreadsheet DIR writes 60 workbooks into DIR, each sheet on its own inputs, so that the
// design sheets see every block, every segment, both branches, every log-linear pair, R with
// every parameter, other materials and the extremes where the calculator refuses. LibreOffice
// headless then exports every sheet as CSV twice: once recalculated on load, once as cached.
// Checks:
// - every cell recalculated equals the value the writer cached (numbers to 1e-12 relative, or
//   absolute below 1; the CSV carries 15 digits), so the file opens right without recalculation;
// - every output of a design sheet equals the calculator's (design_optimal_engine, what
//   trebuchet-calc prints) to 1e-9 relative, and the status says "ok" exactly where the
//   calculator gives a design; the derived and model sheets equal the calculator's too.
// Exit 0 when all hold; each failure is printed.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "trebuchet/app.hpp"
#include "trebuchet/app/spreadsheet.hpp"

namespace {

using namespace trebuchet;
namespace fs = std::filesystem;

using Cells = std::vector<std::vector<std::string>>;

Cells read_csv(const fs::path& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("LibreOffice wrote no " + path.string());
  CsvReader reader(file, path.string());
  Cells cells = {reader.header()};
  CsvRow row;
  while (reader.next(row)) cells.push_back(row.cells);
  return cells;
}

std::optional<double> number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (*end != '\0') return std::nullopt;
  return value;
}

// Column B of the row whose column A is `label` (the first such row).
std::string value_of(const Cells& cells, const std::string& label) {
  for (const auto& row : cells)
    if (row.size() > 1 && row[0] == label) return row[1];
  return "";
}

int failures = 0;
double worst_cached = 0, worst_calculator = 0;
int compared_cached = 0, compared_calculator = 0, designs = 0, refusals = 0;

void fail(const std::string& what) {
  ++failures;
  if (failures <= 40) std::cout << "FAIL " << what << "\n";
}

void same_as_cached(const Cells& recalculated, const Cells& cached, const std::string& where) {
  if (recalculated.size() != cached.size()) return fail(where + ": the two exports differ in rows");
  for (std::size_t r = 0; r < cached.size(); ++r)
    for (std::size_t c = 0; c < cached[r].size() && c < recalculated[r].size(); ++c) {
      const std::string& a = recalculated[r][c];
      const std::string& b = cached[r][c];
      const std::string cell = where + " row " + std::to_string(r + 1) + " column " + std::to_string(c + 1);
      const auto x = number(a), y = number(b);
      if (x && y) {
        ++compared_cached;
        // Relative, but absolute below 1: cells near 0 (X, depth) are differences of terms of
        // order 1, which a spreadsheet's LN and EXP leave a few units of 1e-16 apart.
        const double difference = std::abs(*x - *y) / std::max({std::abs(*x), std::abs(*y), 1.0});
        worst_cached = std::max(worst_cached, difference);
        if (difference > 1e-12) fail(cell + ": recalculated " + a + ", cached " + b);
      } else if (a != b) {
        fail(cell + ": recalculated '" + a + "', cached '" + b + "'");
      }
    }
}

void close_to(const Cells& sheet, const std::string& label, double expected, const std::string& where) {
  const std::string text = value_of(sheet, label);
  const auto value = number(text);
  ++compared_calculator;
  if (!value) return fail(where + " " + label + ": '" + text + "' is not a number; the calculator has " + format_number(expected));
  const double difference = std::abs(*value / expected - 1);
  worst_calculator = std::max(worst_calculator, difference);
  if (difference > 1e-9) fail(where + " " + label + ": " + text + " against the calculator's " + format_number(expected));
}

// A design sheet against the calculator for the same request.
void check_design(const Cells& sheet, const ScalingTable& table, const DesignRequest& request, const std::string& where) {
  const std::string status = value_of(sheet, "status");
  std::optional<OptimalEngine> design;
  std::string refusal;
  try {
    design = design_optimal_engine(table, request);
  } catch (const Error& e) {
    refusal = e.what();
  }
  if (!design) {
    ++refusals;
    if (status == "ok") fail(where + ": the sheet says ok, the calculator refuses: " + refusal);
    // A refused request shows no engine: every result is blank (issue 22).
    for (const char* label : {"R", "T", "T in kJ", "L1", "L2", "L3", "L4", "D", "M", "M in t", "m", "mb"})
      if (!value_of(sheet, label).empty()) fail(where + ": refused, yet " + label + " shows '" + value_of(sheet, label) + "'");
    return;
  }
  ++designs;
  if (status != "ok") return fail(where + ": the sheet says '" + status + "', the calculator gives a design");
  const Engine& e = design->engine;
  const std::pair<const char*, double> outputs[] = {{"R", design->capacity.R},
                                                    {"T", design->capacity.T},
                                                    {"L1", e.L1},
                                                    {"L2", e.L2},
                                                    {"L3", e.L3},
                                                    {"L4", e.L4},
                                                    {"D", e.D},
                                                    {"M", e.M},
                                                    {"m", e.m},
                                                    {"mb", e.mb},
                                                    {"amplification", design->amplification}};
  for (const auto& [label, value] : outputs) close_to(sheet, label, value, where);
  close_to(sheet, "T in kJ", design->capacity.T / 1e3, where);
  close_to(sheet, "M in t", e.M / 1e3, where);
  // X and Y pass through 0: compared absolutely, on their scale of about 1.
  for (const auto& [label, value] : {std::pair{"X", design->coordinates.X}, std::pair{"Y", design->coordinates.Y}}) {
    const auto x = number(value_of(sheet, label));
    ++compared_calculator;
    if (!x || std::abs(*x - value) > 1e-9) fail(where + " " + label + ": '" + value_of(sheet, label) + "' against " + format_number(value));
  }
  if (value_of(sheet, "segment branch") != branch_name(design->branch)) fail(where + ": branch '" + value_of(sheet, "segment branch") + "'");
}

struct Case {
  SpreadsheetInputs inputs;
  std::string name;
};

DesignRequest request_of(Quantity a, double va, Quantity b, double vb, const TableBlock& block, BranchChoice branch, const Material& material) {
  DesignRequest request = SpreadsheetInputs::example(a, va, b, vb);
  request.theta_i_deg = block.theta_i_deg;
  request.F = block.F;
  request.branch = branch;
  request.material = material;
  return request;
}

std::vector<Case> cases(const ScalingTable& table) {
  const std::vector<Quantity> log_linear = {Quantity::R, Quantity::T, Quantity::L1, Quantity::L2, Quantity::L4,
                                            Quantity::D, Quantity::M, Quantity::m,  Quantity::mb, Quantity::l};
  std::vector<std::pair<Quantity, Quantity>> pairs;
  for (std::size_t i = 0; i < log_linear.size(); ++i)
    for (std::size_t j = i + 1; j < log_linear.size(); ++j) pairs.push_back({log_linear[i], log_linear[j]});
  // Every segment of every block, each visited in turn, at X across its interval.
  std::vector<std::pair<const TableBlock*, const Segment*>> segments;
  for (const TableBlock& block : table.blocks)
    for (const Segment& segment : block.segments) segments.push_back({&block, &segment});
  std::mt19937 random(2026);
  std::uniform_real_distribution<double> unit(0, 1);
  Material wood = table.reference, stiff = wood, moon = wood;
  stiff.beta2 = 1.0 / 200;
  moon.g = 1.62;
  const Material materials[] = {wood, wood, stiff, moon};
  const BranchChoice branches[] = {BranchChoice::automatic, BranchChoice::lower, BranchChoice::upper};

  std::vector<Case> all;
  for (int k = 0; k < 60; ++k) {
    Case c;
    const auto [block, segment] = segments[static_cast<std::size_t>(k) % segments.size()];
    const Material& material = materials[k % 4];
    c.inputs.material = material;
    const double X = segment->X_min + (0.05 + 0.9 * unit(random)) * (segment->X_max - segment->X_min);
    const Capacity capacity = capacity_at({X, -1 + 3 * unit(random)}, table.R0, table.T0);
    const SizeFactors to_material = size_factors(1, table.reference, 1, material);
    const BranchChoice branch = segment->branch == Branch::none ? branches[k % 3]
                                                                : (segment->branch == Branch::lower ? BranchChoice::lower : BranchChoice::automatic);
    c.inputs.capacity = request_of(Quantity::R, capacity.R, Quantity::T, capacity.T * to_material.energy, *block, branch, material);
    // The other sheets take their givens from the calculator's (R, T) optimum.
    const OptimalEngine optimum = design_optimal_engine(table, c.inputs.capacity);
    // Every fifteenth case lies beyond the table (R eight times larger): the calculator refuses.
    if (k % 15 == 14) c.inputs.capacity.first.value *= 8;
    const Quantity other = log_linear[1 + static_cast<std::size_t>(k) % (log_linear.size() - 1)];
    c.inputs.range_and_one = request_of(Quantity::R, optimum.capacity.R, other, quantity_value(optimum, other), *block, BranchChoice::automatic,
                                        material);
    const auto [qi, qj] = pairs[static_cast<std::size_t>(k) % pairs.size()];
    c.inputs.any_pair = request_of(qi, quantity_value(optimum, qi), qj, quantity_value(optimum, qj), *block, BranchChoice::automatic, material);
    c.inputs.engine = optimum.engine;
    c.inputs.model_scale = 0.05 + unit(random);
    c.name = "case" + std::to_string(k);
    all.push_back(c);
  }
  return all;
}

int run(const fs::path& dir) {
  const ScalingTable& table = builtin_scaling_table();
  fs::create_directories(dir);
  const std::vector<Case> all = cases(table);
  std::string files;
  for (const Case& c : all) {
    write_spreadsheet(table, c.inputs, (dir / (c.name + ".xlsx")).string());
    files += " '" + (dir / (c.name + ".xlsx")).string() + "'";
  }
  // Two LibreOffice profiles: one recalculates every formula on load, one never does.
  for (const auto& [mode, value] : {std::pair{"recalculated", 0}, std::pair{"cached", 1}}) {
    const fs::path profile = dir / (std::string("profile-") + mode);
    fs::create_directories(profile / "user");
    std::ofstream(profile / "user" / "registrymodifications.xcu")
        << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<oor:items xmlns:oor=\"http://openoffice.org/2001/registry\" "
           "xmlns:xs=\"http://www.w3.org/2001/XMLSchema\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">\n"
           "<item oor:path=\"/org.openoffice.Office.Calc/Formula/Load\"><prop oor:name=\"OOXMLRecalcMode\" oor:op=\"fuse\"><value>"
        << value << "</value></prop></item>\n</oor:items>\n";
    // CSV of every sheet (-1), comma, quote, UTF-8, full precision rather than as shown.
    const std::string command = "soffice -env:UserInstallation=file://" + fs::absolute(profile).string() +
        " --headless --convert-to 'csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false,false,-1' --outdir '" +
        (dir / mode).string() + "'" + files + " > '" + (dir / mode).string() + ".log' 2>&1";
    if (std::system(command.c_str()) != 0) {
      std::cout << "FAIL LibreOffice did not convert the workbooks (see " << (dir / mode).string() << ".log); install libreoffice-calc-nogui\n";
      return 1;
    }
  }
  const char* sheets[] = {"constants", "material", "from R and T", "from R and one", "from any pair", "derived", "model scaling", "glossary"};
  for (const Case& c : all) {
    std::map<std::string, Cells> recalculated;
    for (const char* sheet : sheets) {
      const std::string file = c.name + "-" + sheet + ".csv";
      recalculated[sheet] = read_csv(dir / "recalculated" / file);
      same_as_cached(recalculated[sheet], read_csv(dir / "cached" / file), c.name + " '" + sheet + "'");
    }
    check_design(recalculated["from R and T"], table, c.inputs.capacity, c.name + " 'from R and T'");
    check_design(recalculated["from R and one"], table, c.inputs.range_and_one, c.name + " 'from R and one'");
    check_design(recalculated["from any pair"], table, c.inputs.any_pair, c.name + " 'from any pair'");
    // The derived sheet against the calculator's fields of the same engine.
    const Engine& e = c.inputs.engine;
    const ScaledDesign s = scaled_design(e);
    const std::pair<const char*, double> derived[] = {{"H", pivot_height(e)}, {"L3", e.L3}, {"Lb", beam_length(e)}, {"l", s.l},  {"l4", s.l4},
                                                      {"L", e.L3 / e.L2},     {"mu", s.mu}, {"mu_b", s.mu_b},       {"K", s.K()}};
    for (const auto& [label, value] : derived) close_to(recalculated["derived"], label, value, c.name + " 'derived'");
    Engine under_material = e;
    under_material.material = c.inputs.material;
    close_to(recalculated["derived"], "DeltaU", potential_energy_drop(under_material), c.name + " 'derived'");
    // The model: the calculator's --scale of the (R, T) design.
    try {
      DesignRequest scaled = c.inputs.capacity;
      const OptimalEngine model = scale_optimal_engine(design_optimal_engine(table, scaled), c.inputs.model_scale);
      const Engine& me = model.engine;
      const std::pair<const char*, double> model_values[] = {{"R", model.capacity.R},
                                                             {"T", model.capacity.T},
                                                             {"L1", me.L1},
                                                             {"L2", me.L2},
                                                             {"L3", me.L3},
                                                             {"L4", me.L4},
                                                             {"D", me.D},
                                                             {"M", me.M},
                                                             {"m", me.m},
                                                             {"mb", me.mb}};
      for (const auto& [label, value] : model_values) close_to(recalculated["model scaling"], label, value, c.name + " 'model scaling'");
    } catch (const Error&) {
      // No full-size design: the model sheet has nothing to match.
    }
  }
  std::cout << all.size() << " workbooks, " << std::size(sheets) << " sheets each: " << compared_cached
            << " numbers recalculated by LibreOffice against the cached ones, worst relative difference " << worst_cached << "; "
            << compared_calculator << " outputs against the calculator, worst relative difference " << worst_calculator << "; " << designs
            << " designs and " << refusals << " refusals of the calculator, each matched by the sheet's status\n";
  std::cout << (failures == 0 ? "all agree\n" : std::to_string(failures) + " failures\n");
  return failures == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: check-spreadsheet DIR\n";
    return 2;
  }
  try {
    return run(argv[1]);
  } catch (const std::exception& e) {
    std::cout << "FAIL " << e.what() << "\n";
    return 1;
  }
}
