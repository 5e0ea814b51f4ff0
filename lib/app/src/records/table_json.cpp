#include "trebuchet/app/records/table_json.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/input/text_input.hpp"

namespace trebuchet {
namespace {

using nlohmann::json;

// The text of every non-integer number of a JSON document, by its path as messages name it
// ("blocks[0].segments[1].p.L1"), read with nlohmann's SAX interface, which hands the text over.
// The printed digits of a constant tell how exact it is.
class NumberTexts : public nlohmann::json_sax<json> {
 public:
  std::map<std::string, std::string> texts;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t& text) override {
    texts[next_path()] = text;
    return true;
  }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& name) override {
    key_ = name;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  struct Frame {
    bool array;
    std::size_t index;
    std::string path;
  };
  std::string next_path() {
    if (frames_.empty()) return "";
    Frame& f = frames_.back();
    if (f.array) return f.path + "[" + std::to_string(f.index++) + "]";
    return f.path.empty() ? key_ : f.path + "." + key_;
  }
  bool value() {
    next_path();
    return true;
  }
  bool open(bool array) {
    frames_.push_back({array, 0, next_path()});
    return true;
  }
  bool close() {
    frames_.pop_back();
    return true;
  }
  std::vector<Frame> frames_;
  std::string key_;
};

// One unit in the last printed digit of a number's text ("-0.1851" -> 1e-4, "2.5e3" -> 100); 0
// for an integer literal, which is exact.
double last_digit_unit(const std::map<std::string, std::string>& texts, const std::string& path) {
  const auto it = texts.find(path);
  if (it == texts.end()) return 0;
  const std::string& text = it->second;
  const auto e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  const auto dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  const int exponent = e == std::string::npos ? 0 : std::atoi(text.c_str() + e + 1);
  return std::pow(10.0, exponent - decimals);
}

// Walks a JSON document and reports the first problem with the path of the offending key.
class TableReader {
 public:
  explicit TableReader(const std::string& origin) : origin_(origin) {}

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    throw Error(ErrorKind::data_file, origin_ + ": " + (path.empty() ? "top level" : path) + ": " + problem);
  }

  static std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

  const json& member(const json& object, const std::string& path, const std::string& key) const {
    if (!object.is_object()) fail(path, "expected an object");
    auto it = object.find(key);
    if (it == object.end()) fail(path, "missing key '" + key + "'");
    return *it;
  }

  double number(const json& object, const std::string& path, const std::string& key) const {
    const json& value = member(object, path, key);
    // parse_json keeps a number beyond a double (1e400) as its text.
    if (value.is_string() && std::isinf(std::strtod(value.get<std::string>().c_str(), nullptr)))
      fail(join(path, key), value.get<std::string>() + " is beyond the range of numbers");
    if (!value.is_number()) fail(join(path, key), "expected a number, got " + std::string(value.type_name()));
    double x = value.get<double>();
    if (!std::isfinite(x)) fail(join(path, key), "not a finite number");
    return x;
  }

  double positive(const json& object, const std::string& path, const std::string& key) const {
    double x = number(object, path, key);
    if (!(x > 0)) fail(join(path, key), "must be positive, got " + format_number(x));
    return x;
  }

  int count(const json& object, const std::string& path, const std::string& key) const {
    const double x = number(object, path, key);
    if (!(x >= 0 && x <= std::numeric_limits<int>::max() && x == std::floor(x)))
      fail(join(path, key), "expected a whole number from 0 to " + std::to_string(std::numeric_limits<int>::max()) + ", got " + format_number(x));
    return static_cast<int>(x);
  }

  std::string text(const json& object, const std::string& path, const std::string& key) const {
    const json& value = member(object, path, key);
    if (!value.is_string()) fail(join(path, key), "expected a string, got " + std::string(value.type_name()));
    return value.get<std::string>();
  }

  const json& array(const json& object, const std::string& path, const std::string& key) const {
    const json& value = member(object, path, key);
    if (!value.is_array() || value.empty()) fail(join(path, key), "expected a non-empty array");
    return value;
  }

  ParamVector per_param(const json& object, const std::string& path, const std::string& key, bool must_be_positive) const {
    const json& values = member(object, path, key);
    const std::string here = join(path, key);
    ParamVector result;
    for (Param param : all_params) {
      const std::string name(param_name(param));
      result[index(param)] = must_be_positive ? positive(values, here, name) : number(values, here, name);
    }
    return result;
  }

 private:
  std::string origin_;
};

Branch parse_branch(const TableReader& reader, const json& segment, const std::string& path) {
  const json& value = reader.member(segment, path, "branch");
  if (!value.is_string()) reader.fail(path + ".branch", "expected \"none\", \"lower\" or \"upper\"");
  const std::string text = value.get<std::string>();
  if (text == "none") return Branch::none;
  if (text == "lower") return Branch::lower;
  if (text == "upper") return Branch::upper;
  reader.fail(path + ".branch", "expected \"none\", \"lower\" or \"upper\", got \"" + text + "\"");
}

// eq:ZRT holds p_Z + 5 q_Z = n_Z for every parameter (eq:f_ZX: p_Z = n_Z + 5 b_Z, q_Z = -b_Z).
// A printed constant may be off by one unit of its last digit (a rounding of a rounded value:
// the paper's (30 deg, 2/3) D pair misses by 0.0004 with four decimals), so the sum may miss
// n_Z by unit(p) + 5 unit(q), plus round-off; integers count as exact.
void check_exponents(const TableReader& reader, const Segment& segment, const ParamVector& n, const std::string& path,
                     const std::map<std::string, std::string>& texts) {
  for (Param param : all_params) {
    const std::string name(param_name(param));
    const double p = segment.exponents(index(param), 0), q = segment.exponents(index(param), 1);
    const double allowed = last_digit_unit(texts, path + ".p." + name) + 5 * last_digit_unit(texts, path + ".q." + name) + 1e-12;
    if (!(std::abs(p + 5 * q - n[index(param)]) <= allowed))
      reader.fail(path,
                  "p + 5 q = " + format_significant(p + 5 * q, 6) + " for " + name + ", not n = " + format_number(n[index(param)]) +
                      " as eq:ZRT requires (to " + format_significant(allowed, 2) +
                      ", what the printed digits allow); "
                      "correct p or q of " +
                      name);
  }
}

Segment parse_segment(const TableReader& reader, const json& object, const std::string& path) {
  Segment segment{};
  segment.X_min = reader.number(object, path, "X_min");
  segment.X_max = reader.number(object, path, "X_max");
  if (!(segment.X_min < segment.X_max)) reader.fail(path, "X_min must be below X_max");
  segment.branch = parse_branch(reader, object, path);
  segment.a = reader.per_param(object, path, "a", true);
  segment.exponents << reader.per_param(object, path, "p", false), reader.per_param(object, path, "q", false);
  return segment;
}

void check_overlaps(const TableReader& reader, const TableBlock& block, const std::string& path) {
  for (std::size_t i = 0; i < block.segments.size(); ++i)
    for (std::size_t j = i + 1; j < block.segments.size(); ++j) {
      const Segment& s = block.segments[i];
      const Segment& t = block.segments[j];
      const bool overlap = std::max(s.X_min, t.X_min) < std::min(s.X_max, t.X_max);
      const bool labelled = s.branch != Branch::none && t.branch != Branch::none && s.branch != t.branch;
      if (overlap && !labelled)
        reader.fail(path + ".segments",
                    "segments [" + format_number(s.X_min) + ", " + format_number(s.X_max) + "] and [" + format_number(t.X_min) + ", " +
                        format_number(t.X_max) + "] overlap; label them \"lower\" and \"upper\"");
    }
}

TableBlock parse_block(const TableReader& reader, const json& object, const std::string& path, const ParamVector& n,
                       const std::map<std::string, std::string>& texts, MachineKind machine) {
  TableBlock block{};
  block.theta_i_deg = reader.positive(object, path, "theta_i_deg");
  // Another machine's block has its counterweight at the short arm's end, "L": 0 (L3/L2), not an F.
  if (machine == MachineKind::hinged)
    block.F = reader.positive(object, path, "F");
  else if (reader.number(object, path, "L") != 0)
    reader.fail(path + ".L", "the table's engines have their counterweight at the short arm's end: L must be 0");
  block.Z0 = reader.per_param(object, path, "Z0", true);
  if (object.contains("branch_switch_X")) block.branch_switch_X = reader.number(object, path, "branch_switch_X");
  const json& segments = reader.array(object, path, "segments");
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string here = path + ".segments[" + std::to_string(i) + "]";
    block.segments.push_back(parse_segment(reader, segments[i], here));
    check_exponents(reader, block.segments.back(), n, here, texts);
  }
  std::stable_sort(block.segments.begin(), block.segments.end(), [](const Segment& a, const Segment& b) { return a.X_min < b.X_min; });
  check_overlaps(reader, block, path);
  return block;
}

}  // namespace

ScalingTable parse_scaling_table(std::string_view json_text, const std::string& origin) {  // tab:CPNC and its re-derivations
  if (json_depth(json_text) > max_json_depth)
    throw Error(ErrorKind::data_file,
                origin + ": arrays or objects nest more than " + std::to_string(max_json_depth) +
                    " levels deep; give a table in the schema of data/cpnc.json");
  if (const auto key = duplicate_key(json_text))
    throw Error(ErrorKind::data_file, origin + ": the key \"" + *key + "\" is given twice in one object; keep one");
  json document;
  try {
    document = json::parse(json_text);
  } catch (const json::exception& e) {  // parse errors, and numbers beyond double range
    throw Error(ErrorKind::data_file, origin + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  NumberTexts numbers;
  json::sax_parse(json_text, &numbers);
  const TableReader reader(origin);
  ScalingTable table{};
  table.origin = origin;
  if (document.is_object()) {
    if (document.contains("name") && document["name"].is_string()) table.name = document["name"].get<std::string>();
    if (document.contains("provenance") && document["provenance"].is_object()) {
      const nlohmann::ordered_json in_order = nlohmann::ordered_json::parse(json_text);  // keys in the file's order
      for (const auto& [key, text] : in_order["provenance"].items())
        if (text.is_string()) table.provenance.emplace_back(key, text.get<std::string>());
    }
  }
  if (document.contains("machine")) table.machine = parse_machine(reader.text(document, "", "machine"), "machine");
  table.R0 = reader.positive(document, "", "R0");
  table.T0 = reader.positive(document, "", "T0");
  const json& material = reader.member(document, "", "reference_material");
  table.reference = {reader.positive(material, "reference_material", "beta2"), reader.positive(material, "reference_material", "youngs_modulus"),
                     reader.positive(material, "reference_material", "wood_density"), reader.positive(material, "reference_material", "g")};
  table.n = reader.per_param(document, "", "n", true);
  const json& blocks = reader.array(document, "", "blocks");
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string path = "blocks[" + std::to_string(i) + "]";
    const TableBlock block = parse_block(reader, blocks[i], path, table.n, numbers.texts, table.machine);
    if (table.find_block(block.theta_i_deg, block.F))
      reader.fail(path,
                  "a second block for theta_i = " + format_number(block.theta_i_deg) + " deg, F = " + format_fraction(block.F) +
                      "; give each (theta_i, F) once");
    table.blocks.push_back(block);
  }
  return table;
}

nlohmann::ordered_json param_json(const ParamVector& values) {
  nlohmann::ordered_json out;
  for (Param p : all_params) out[std::string(param_name(p))] = values[index(p)];
  return out;
}

nlohmann::ordered_json material_json(const Material& m) {
  return {{"beta2", m.beta2}, {"youngs_modulus", m.youngs_modulus}, {"wood_density", m.wood_density}, {"g", m.g}};
}

nlohmann::ordered_json scaling_table_json(const ScalingTable& table) {
  nlohmann::ordered_json out;
  out["name"] = table.name;
  if (!table.provenance.empty())
    for (const auto& [key, text] : table.provenance) out["provenance"][key] = text;
  if (table.machine != MachineKind::hinged) out["machine"] = machine_name(table.machine);
  out["R0"] = table.R0;
  out["T0"] = table.T0;
  out["reference_material"] = material_json(table.reference);
  out["n"] = param_json(table.n);
  nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
  for (const TableBlock& block : table.blocks) {
    nlohmann::ordered_json b;
    b["theta_i_deg"] = block.theta_i_deg;
    if (table.machine == MachineKind::hinged)
      b["F"] = block.F;
    else
      b["L"] = 0;  // L3/L2: the counterweight at the short arm's end
    if (block.branch_switch_X) b["branch_switch_X"] = *block.branch_switch_X;
    b["Z0"] = param_json(block.Z0);
    nlohmann::ordered_json segments = nlohmann::ordered_json::array();
    for (const Segment& segment : block.segments)
      segments.push_back({{"X_min", segment.X_min},
                          {"X_max", segment.X_max},
                          {"branch", branch_name(segment.branch)},
                          {"a", param_json(segment.a)},
                          {"p", param_json(segment.exponents.col(0))},
                          {"q", param_json(segment.exponents.col(1))}});
    b["segments"] = segments;
    blocks.push_back(b);
  }
  out["blocks"] = blocks;
  return out;
}

ScalingTable load_scaling_table(const std::string& path) {
  try {
    return parse_scaling_table(read_text(path, "a constants file like data/cpnc.json"), path);
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::data_file) throw;
    throw Error(ErrorKind::data_file, e.what());
  }
}

Shard parse_shard(const std::string& text) {
  Shard shard;
  const std::size_t slash = text.find('/');
  auto whole = [&](std::string_view digits, int& value) {  // digits only, no sign, and within int
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    return ec == std::errc() && end == digits.data() + digits.size() && !digits.empty() && digits.front() != '-';
  };
  const std::string_view view(text);
  if (slash == std::string::npos || !whole(view.substr(0, slash), shard.k) || !whole(view.substr(slash + 1), shard.n) || shard.n < 1 || shard.k < 1 ||
      shard.k > shard.n)
    throw Error(
        ErrorKind::usage,
        "{{shard}}: '" + text + "' is not a part; give k/N with 1 <= k <= N <= " + std::to_string(std::numeric_limits<int>::max()) + ", e.g. 2/8");
  return shard;
}

namespace {

const char* const part_kind = "trebuchet sweep part";

[[noreturn]] void fail(const std::string& origin, const std::string& problem) {
  throw Error(ErrorKind::data_file, origin + ": " + problem + "; give the parts that derive-table writes with {{shard}} k/N");
}

}  // namespace

nlohmann::ordered_json sweep_point_json(const SweepPoint& p) {
  nlohmann::ordered_json j;
  j["X"] = p.X, j["R"] = p.capacity.R, j["T"] = p.capacity.T;
  if (!p.error.empty()) {
    j["error"] = p.error;
    return j;
  }
  write_engine(j, p.engine);
  j["Q"] = p.shot.Q, j["eps"] = p.shot.eps, j["force_factor"] = p.shot.force_factor;
  j["theta_release_deg"] = p.shot.theta_release_deg;
  j["optima_found"] = p.optima_found;
  j["simulations"] = p.simulations;
  return j;
}

namespace {

SweepPoint read_point(const TableReader& reader, const nlohmann::json& j, const std::string& where) {
  SweepPoint p;
  p.X = reader.number(j, where, "X");
  p.capacity = {reader.positive(j, where, "R"), reader.positive(j, where, "T"), 0};
  if (j.is_object() && j.contains("error")) {
    p.error = reader.text(j, where, "error");
    if (p.error.empty()) reader.fail(TableReader::join(where, "error"), "empty; a failed point says why it failed");
    return p;
  }
  p.engine = read_engine(j, where).engine;
  p.shot.capacity = p.capacity;
  p.shot.Q = reader.positive(j, where, "Q"), p.shot.eps = reader.positive(j, where, "eps");
  p.shot.force_factor = reader.number(j, where, "force_factor");
  p.shot.theta_release_deg = reader.number(j, where, "theta_release_deg");
  p.optima_found = reader.count(j, where, "optima_found");
  p.simulations = reader.count(j, where, "simulations");
  return p;
}

}  // namespace

nlohmann::ordered_json sweep_part_json(const SweepPart& part) {
  const SweepSpec& spec = part.spec;
  nlohmann::ordered_json out;
  out["kind"] = part_kind;
  out["theta_i_deg"] = spec.theta_i_deg;
  out["F"] = spec.F;
  if (spec.machine != MachineKind::hinged) out["machine"] = machine_name(spec.machine);
  out["X_from"] = spec.X_from, out["X_to"] = spec.X_to, out["X_step"] = spec.X_step;
  out["R0"] = spec.R0, out["T0"] = spec.T0;
  out["reference_material"] = material_json(spec.material);
  out["quality"] = release_name(spec.criterion.release);
  out["n"] = spec.criterion.n;
  out["shard"] = std::to_string(part.shard.k) + "/" + std::to_string(part.shard.n);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const SweepPoint& p : part.points) list.push_back(sweep_point_json(p));
  out["points"] = list;
  return out;
}

SweepPart read_sweep_part(const nlohmann::json& j, const std::string& origin) {
  // "kind" may be any JSON at all: compared only when it is a string.
  if (!j.is_object() || !j.contains("kind") || !j["kind"].is_string() || j["kind"].get<std::string>() != part_kind) fail(origin, "not a sweep part");
  const TableReader reader(origin);
  SweepPart part;
  part.origin = origin;
  try {
    SweepSpec& spec = part.spec;
    spec.theta_i_deg = reader.positive(j, "", "theta_i_deg");
    spec.F = reader.positive(j, "", "F");
    if (j.contains("machine")) spec.machine = parse_machine(reader.text(j, "", "machine"), "machine");
    spec.X_from = reader.number(j, "", "X_from"), spec.X_to = reader.number(j, "", "X_to"), spec.X_step = reader.positive(j, "", "X_step");
    spec.R0 = reader.positive(j, "", "R0"), spec.T0 = reader.positive(j, "", "T0");
    const json& material = reader.member(j, "", "reference_material");
    spec.material = {reader.positive(material, "reference_material", "beta2"), reader.positive(material, "reference_material", "youngs_modulus"),
                     reader.positive(material, "reference_material", "wood_density"), reader.positive(material, "reference_material", "g")};
    spec.criterion.release = parse_release(reader.text(j, "", "quality"), "quality");
    spec.criterion.n = reader.number(j, "", "n");
    part.shard = parse_shard(reader.text(j, "", "shard"));
    const json& points = reader.member(j, "", "points");
    if (!points.is_array()) reader.fail("points", "expected an array");
    for (std::size_t i = 0; i < points.size(); ++i) part.points.push_back(read_point(reader, points[i], "points[" + std::to_string(i) + "]"));
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::data_file) throw;  // the reader's own: the file, the key's path and the problem
    fail(origin, std::string("malformed sweep part (") + e.named_message() + ")");
  }
  return part;
}

nlohmann::ordered_json derived_table_json(const DerivedTable& derived) {
  nlohmann::ordered_json out = scaling_table_json(derived.table);
  for (std::size_t b = 0; b < derived.table.blocks.size(); ++b) {
    nlohmann::ordered_json& block = out["blocks"][b];
    for (std::size_t s = 0; s < derived.fits[b].size(); ++s) {
      block["segments"][s]["points"] = derived.fits[b][s].points;
      block["segments"][s]["fit_max_deviation"] = param_json(derived.fits[b][s].fit_max_deviation);
    }
    nlohmann::ordered_json sweep = nlohmann::ordered_json::array();
    for (const SweepPoint& point : derived.sweeps[b]) sweep.push_back(sweep_point_json(point));
    block["sweep"] = sweep;
  }
  return out;
}

}  // namespace trebuchet
