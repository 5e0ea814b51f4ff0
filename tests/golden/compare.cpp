// golden-compare EXPECTED ACTUAL RENAMES TOLERANCES: the outputs of run.sh in ACTUAL against
// those recorded in EXPECTED before issue 10's restructuring. Per case:
//  - the exit code is the same;
//  - stdout, after the documented renames (RENAMES) of the expected text, has the same
//    numbers and words: JSON by key (a key the new output adds is listed, not an error), other
//    text token by token;
//  - on success (exit 0 or 1), stderr has the same numbers; its words name options, which
//    became subcommands. Error messages are reworded on purpose (issue 11); the robustness
//    corpus pins them, this check pins their exit codes.
// Numbers agree to the case's relative tolerance or absolute floor (TOLERANCES: NAME RTOL ATOL;
// default 1e-9 and 1e-12, round-off carried through a shot), or to one unit of the last digit
// the expected text printed. On lines that report cost (shots, simplex
// iterations, wall time, seconds) only the words are compared.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using nlohmann::json;

std::string read(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

struct Renames {
  std::vector<std::pair<std::string, std::string>> text;  // old -> new, plain text
  std::set<std::string> splice;  // JSON objects whose members moved up one level
  std::set<std::string> cost_keys;  // JSON keys that report cost, not results
};

Renames read_renames(const std::string& path) {
  Renames r;
  std::istringstream lines(read(path));
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    const std::string a = line.substr(0, tab), b = tab == std::string::npos ? "" : line.substr(tab + 1);
    if (a == "splice")
      r.splice.insert(b);
    else if (a == "cost")
      r.cost_keys.insert(b);
    else
      r.text.emplace_back(a, b);
  }
  return r;
}

struct Tolerance {
  double rtol = 1e-9, atol = 1e-12;
};

struct Case {
  std::string name;
  Tolerance tolerance;
  std::vector<std::string> problems;
  std::vector<std::string> added_keys;
  double worst = 0;  // largest relative difference of a number

  void note(const std::string& problem) { problems.push_back(name + ": " + problem); }

  // Agreement of two printed numbers: relative, or within the last printed digit of `expected`.
  bool same_number(const std::string& expected, double a, double b) {
    if (a == b) return true;
    const double scale = std::max(std::abs(a), std::abs(b));
    worst = std::max(worst, std::abs(a - b) / scale);
    if (std::abs(a - b) <= tolerance.rtol * scale || std::abs(a - b) <= tolerance.atol) return true;
    // One unit of the last printed digit: 149.52 -> 0.01, 7.678e+00 -> 0.001.
    const auto mantissa_end = expected.find_first_of("eE");
    const std::string mantissa = expected.substr(0, mantissa_end);
    const auto dot = mantissa.find('.');
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
    const int exponent = mantissa_end == std::string::npos ? 0 : std::stoi(expected.substr(mantissa_end + 1));
    return mantissa.size() <= 8 && std::abs(a - b) <= std::pow(10.0, exponent - decimals) * 1.0000001;
  }

  void compare_json(const json& e, const json& a, const std::string& path, const Renames& renames) {
    if (e.is_object()) {
      if (!a.is_object()) return note(path + ": expected an object");
      for (auto it = e.begin(); it != e.end(); ++it) {
        if (renames.cost_keys.count(it.key())) continue;
        if (!a.contains(it.key())) {
          note(path + "." + it.key() + ": missing");
          continue;
        }
        compare_json(it.value(), a.at(it.key()), path + "." + it.key(), renames);
      }
      for (auto it = a.begin(); it != a.end(); ++it)
        if (!e.contains(it.key())) added_keys.push_back(path + "." + it.key());
    } else if (e.is_array()) {
      if (!a.is_array() || a.size() != e.size()) return note(path + ": arrays differ in length");
      for (std::size_t i = 0; i < e.size(); ++i) compare_json(e[i], a[i], path + "[" + std::to_string(i) + "]", renames);
    } else if (e.is_number()) {
      if (!a.is_number()) return note(path + ": expected a number");
      if (!same_number(e.dump(), e.get<double>(), a.get<double>())) note(path + ": " + e.dump() + " became " + a.dump());
    } else if (e != a) {
      note(path + ": " + e.dump() + " became " + a.dump());
    }
  }

  // Words and numbers of a text, numbers marked; lines reporting cost keep their words only.
  static std::vector<std::pair<bool, std::string>> tokens(const std::string& text, bool numbers_only) {
    static const std::regex token(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?|[A-Za-z_]+)");
    static const std::regex cost(R"(shots|simplex|wall|\d s on \d+ thread)");
    std::vector<std::pair<bool, std::string>> out;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
      const bool is_cost = std::regex_search(line, cost);
      for (std::sregex_iterator it(line.begin(), line.end(), token), end; it != end; ++it) {
        const std::string t = it->str();
        const bool is_number = std::isdigit(static_cast<unsigned char>(t.back())) || t.back() == '.';
        if (is_number ? !is_cost : !numbers_only) out.emplace_back(is_number, t);
      }
    }
    return out;
  }

  void compare_text(const std::string& expected, const std::string& actual, const std::string& what, bool numbers_only) {
    const auto e = tokens(expected, numbers_only), a = tokens(actual, numbers_only);
    if (e.size() != a.size()) return note(what + ": " + std::to_string(e.size()) + " tokens became " + std::to_string(a.size()));
    for (std::size_t i = 0; i < e.size(); ++i) {
      if (e[i].first != a[i].first) return note(what + ": token '" + e[i].second + "' became '" + a[i].second + "'");
      if (e[i].first ? !same_number(e[i].second, std::stod(e[i].second), std::stod(a[i].second)) : e[i].second != a[i].second)
        note(what + ": '" + e[i].second + "' became '" + a[i].second + "'");
    }
  }
};

void splice(json& j, const std::set<std::string>& keys) {
  if (j.is_array())
    for (json& element : j) splice(element, keys);
  if (!j.is_object()) return;
  for (const std::string& key : keys)
    if (j.contains(key) && j[key].is_object()) {
      const json inner = j[key];
      j.erase(key);
      for (auto it = inner.begin(); it != inner.end(); ++it) j[it.key()] = it.value();
    }
  for (auto it = j.begin(); it != j.end(); ++it) splice(it.value(), keys);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: golden-compare EXPECTED ACTUAL RENAMES TOLERANCES\n";
    return 2;
  }
  const std::filesystem::path expected_dir = argv[1], actual_dir = argv[2];
  const Renames renames = read_renames(argv[3]);
  std::map<std::string, Tolerance> tolerances;
  {
    std::istringstream lines(read(argv[4]));
    std::string line;
    while (std::getline(lines, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream fields(line);
      std::string name;
      Tolerance t;
      fields >> name >> t.rtol >> t.atol;
      tolerances[name] = t;
    }
  }
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(expected_dir))
    if (entry.path().extension() == ".code") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  int failed = 0;
  for (const std::string& name : names) {
    Case c{name, tolerances.count(name) ? tolerances[name] : Tolerance{}, {}, {}};
    auto file = [&](const std::filesystem::path& dir, const char* ext) { return read(dir / (name + ext)); };
    if (!std::filesystem::exists(actual_dir / (name + ".code"))) {
      c.note("not run");
    } else {
      const int expected_code = std::stoi(file(expected_dir, ".code")), actual_code = std::stoi(file(actual_dir, ".code"));
      if (expected_code != actual_code) c.note("exit code " + std::to_string(expected_code) + " became " + std::to_string(actual_code));
      std::string expected = file(expected_dir, ".out");
      for (const auto& [from, to] : renames.text)
        for (std::size_t at = expected.find(from); at != std::string::npos; at = expected.find(from, at + to.size()))
          expected.replace(at, from.size(), to);
      const std::string actual = file(actual_dir, ".out");
      json e = json::parse(expected, nullptr, false), a = json::parse(actual, nullptr, false);
      if (!e.is_discarded() && !a.is_discarded() && (e.is_object() || e.is_array())) {
        splice(e, renames.splice);
        c.compare_json(e, a, "stdout", renames);
      } else {
        c.compare_text(expected, actual, "stdout", false);
      }
      if (expected_code <= 1) c.compare_text(file(expected_dir, ".err"), file(actual_dir, ".err"), "stderr", true);
    }
    std::set<std::string> added(c.added_keys.begin(), c.added_keys.end());
    std::cout << (c.problems.empty() ? "same    " : "DIFFERS ") << name << "  (largest relative difference " << c.worst << ", tolerance "
              << c.tolerance.rtol << " / " << c.tolerance.atol << (added.empty() ? "" : ", " + std::to_string(added.size()) + " keys added") << ")\n";
    for (const std::string& p : c.problems) std::cout << "    " << p << "\n";
    failed += !c.problems.empty();
  }
  std::cout << names.size() - failed << " passed, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
}
