#include "trebuchet/app/run/what_if.hpp"

#include <sstream>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/sweep.hpp"
#include "trebuchet/app/records/design_input.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/records/schema.hpp"
#include "trebuchet/app/records/shot_record.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

WhatIf parse_what_if(std::string_view text, int points, std::string_view name) {
  const std::string given(text);
  const auto equals = given.find('=');
  const std::string key = given.substr(0, equals);
  // A shot's value of the engine, its parts or its release: not its capacity, nor the material (its flags would override it).
  const auto varies = [](const InputField& f) {
    return (f.operations & op_shot) && f.group != FieldGroup::capacity && f.group != FieldGroup::material;
  };
  const InputField* field = find_field(key);
  for (const InputField& f : input_fields())
    if (!field && key == f.flag) field = &f;
  if (!field || !varies(*field)) {
    std::vector<std::string> names;
    for (const InputField& f : input_fields())
      if (varies(f)) names.emplace_back(f.key);
    throw Error(ErrorKind::usage,
                std::string(name) + ": '" + key + "' is no value of an engine to vary; give one of " + join(names, ", ") + ", e.g. " +
                    std::string(name) + " L4=2m..5m");
  }
  const auto range = equals == std::string::npos ? std::nullopt
                                                 : parse_spread(given.substr(equals + 1), field->dimension, std::string(name) + " " + field->key);
  if (!range || range->kind != Spread::Kind::uniform)
    throw Error(ErrorKind::usage, std::string(name) + ": '" + given + "' gives no range; write " + field->key + "=low..high, e.g. L4=2m..5m");
  what_if_values(range->a, range->b, points);  // the count and the ends checked here, before any shot
  return {field, range->a, range->b, points};
}

namespace {

// The points of a sweep of a release that share one trajectory (run_what_if).
constexpr std::size_t released_run = 20;

}  // namespace

std::vector<WhatIfPoint> run_what_if(const DesignValues& values, const std::string& where, const WhatIf& what_if, const DesignCheck& check,
                                     int threads, const Progress& progress) {
  const InputField& field = *what_if.field;
  if (!check.series_path.empty() || !check.plot_dir.empty()) throw Error(ErrorKind::usage, "a sweep's points draw no series or pictures");
  // A sweep of one release (release_angle) over a design that sets it another way (pin_angle)
  // would release at the swept value and drop the other without a word: refused by name.
  if (field.group == FieldGroup::release) {
    DesignValues others = values;
    others.*field.member = std::nullopt;
    if (const std::optional<SetRelease> other = release_of(others, where)) {
      const char* key = release_field(other->by).key;
      throw Error(ErrorKind::usage,
                  engine_key_name(where, key) + " sets the release that the sweep varies as " + field.key + "; give one of them (drop it, or vary " +
                      key + " instead)");
    }
  }
  const std::vector<double> grid = what_if_values(what_if.from, what_if.to, what_if.points);
  std::vector<WhatIfPoint> points(grid.size());
  // The value laid over the design as its flag would be (overlay_flags): what it fixes another
  // way goes with it (a record's F beside its L3, an H beside L1 and theta_i).
  const auto record_at = [&](std::size_t i) {
    points[i].value = grid[i];
    DesignValues value;
    value.*field.member = grid[i];
    std::vector<std::string> unsaid;  // the sweep's own change, said by its table
    DesignValues at = overlay_flags(values, value, where, unsaid);
    at.R.reset(), at.T.reset();  // a capacity the design carries (the calculator's) is one engine's; each point is another
    return engine_record(at, where);
  };
  if (field.group != FieldGroup::release) {
    for_each_index(
        grid.size(), threads,
        [&](std::size_t i) {
          try {
            points[i].report = check_design(record_at(i), check);
          } catch (const Error& e) {
            points[i].error = e;
          }
        },
        progress);
    return points;
  }
  // A release changes nothing before it: the points share one trajectory up to the latest release
  // (check_released_designs), a run of neighbouring points at a time, each run claimed by the next
  // free thread; what a run saves grows little past a few points, and `progress` hears of each.
  const std::size_t runs = (grid.size() + released_run - 1) / released_run;
  for_each_index(
      runs, threads,
      [&](std::size_t run) {
        std::vector<EngineRecord> records;
        std::vector<std::size_t> place;
        for (std::size_t i = run * released_run; i < std::min(grid.size(), (run + 1) * released_run); ++i) try {
            records.push_back(record_at(i));
            place.push_back(i);
          } catch (const Error& e) {
            points[i].error = e;
          }
        std::vector<ReleasedDesign> checked = check_released_designs(records, check);
        for (std::size_t k = 0; k < checked.size(); ++k)
          points[place[k]].report = std::move(checked[k].report), points[place[k]].error = checked[k].error;
      },
      progress ? Progress([&](std::size_t done, std::size_t) { progress(std::min(done * released_run, grid.size()), grid.size()); }) : Progress());
  return points;
}

nlohmann::ordered_json what_if_json(const WhatIf& what_if, const std::vector<WhatIfPoint>& points,
                                    const std::function<std::string(std::string_view)>& word) {
  const InputField& field = *what_if.field;
  nlohmann::ordered_json all = nlohmann::ordered_json::array(), values = nlohmann::ordered_json::array();
  for (const WhatIfPoint& p : points) {
    values.push_back(p.value);
    all.push_back(p.report ? p.report->json : nlohmann::ordered_json{{field.key, p.value}, {"error", p.error->message(word)}});
  }
  return {{"vary", field.key},    {"unit", field.dimension == UnitDimension::angle ? "deg" : field.unit},
          {"from", what_if.from}, {"to", what_if.to},
          {"values", values},     {"points", all}};
}

std::string what_if_table(const WhatIf& what_if, const std::vector<WhatIfPoint>& points, UnitSystem units,
                          const std::function<std::string(std::string_view)>& word) {
  const InputField& field = *what_if.field;
  const auto q = [&](double si, UnitDimension dimension) { return quantity_text(si, dimension, units, 4); };
  const auto sig = [](double x) { return format_significant(x, 4); };
  using Column = std::pair<const char*, std::function<std::string(const Verification&, const DesignReport&)>>;
  const std::vector<Column> columns = {
      // A shot that warns (the model stops holding) is marked where its range is read, its warnings below.
      {"R", [&](const Verification& v, const DesignReport&) { return q(v.capacity.R, UnitDimension::length) + (v.warnings.empty() ? "" : " !"); }},
      {"eps", [&](const Verification& v, const DesignReport&) { return sig(100 * v.eps) + " %"; }},
      {"Q", [&](const Verification& v, const DesignReport&) { return sig(100 * v.Q) + " %"; }},
      {"A", [&](const Verification& v, const DesignReport&) { return sig(v.A_deg) + " deg"; }},
      {"pin to bend",
       [&](const Verification& v, const DesignReport& r) { return r.pin_releases ? sig(v.pin_to_bend_deg) + " deg" : std::string("none"); }},
      {"axle load", [&](const Verification& v, const DesignReport&) { return q(v.loads[pivot_load].value, UnitDimension::force); }},
      {"sling", [&](const Verification& v, const DesignReport&) { return q(v.loads[sling_tension_load].value, UnitDimension::force); }},
      {"beam",
       [&](const Verification& v, const DesignReport&) {
         if (!v.beam) return std::string("-");
         return v.beam->margin >= 1 ? "margin " + format_significant(v.beam->margin, 3) : "BREAKS " + format_significant(v.beam->margin, 3);
       }},
  };
  const int width = 13;
  std::ostringstream out;
  const auto cell = [&](const std::string& text) { out << text << std::string(text.size() < width ? width - text.size() : 1, ' '); };
  out << "what if " << field.key << " (" << field.label << ") runs from " << q(what_if.from, field.dimension) << " to "
      << q(what_if.to, field.dimension) << ", the rest held: " << points.size() << " shots";
  const WhatIfPoint* shot = nullptr;
  for (const WhatIfPoint& p : points)
    if (p.report && !shot) shot = &p;
  if (field.group == FieldGroup::release)
    out << ", each released at that " << std::string(field.label).substr(0, std::string(field.label).find(" ["));  // "pin angle [deg]": its words
  else if (shot)
    out << ", each " << describe_release(shot->report->settings);
  out << "\n";
  cell(field.key);
  for (const auto& [name, value] : columns) cell(name);
  out << "\n";
  for (const WhatIfPoint& p : points) {
    cell(q(p.value, field.dimension));
    if (p.report)
      for (const auto& [name, value] : columns) cell(value(p.report->verification, *p.report));
    else
      out << p.error->message(word);
    out << "\n";
  }
  for (const WhatIfPoint& p : points)
    if (p.report)
      for (const std::string& warning : p.report->verification.warnings)
        out << "warning at " << field.key << " = " << q(p.value, field.dimension) << ": " << with_words(warning, word) << "\n";
  out << "R: range (!: the model stops holding in that shot, its warning above); eps: efficiency T/Delta U; Q: quality (eq:Q); A: the "
         "projectile's climb at the release; pin to bend: for that release (none: no pin makes the optimum's);\n"
         "axle load, sling: their largest up to the release; beam: the modulus of rupture over the beam's larger stress (below 1 it breaks)\n";
  return out.str();
}

std::string what_if_csv(const WhatIf& what_if, const std::vector<WhatIfPoint>& points, const std::function<std::string(std::string_view)>& word) {
  std::vector<std::string> header = {csv_column_of(*what_if.field)};
  for (const std::string& column : verification_csv_header()) header.push_back(column);
  header.push_back("error");
  std::string text = csv_line(header);
  for (const WhatIfPoint& p : points) {
    std::vector<std::string> cells = {format_number(p.value)};
    if (p.report) {
      cells.insert(cells.end(), p.report->csv.begin(), p.report->csv.end());
      cells.push_back("");
    } else {
      cells.resize(header.size() - 1);
      cells.push_back(p.error->message(word));
    }
    text += csv_line(cells);
  }
  return text;
}

}  // namespace trebuchet
