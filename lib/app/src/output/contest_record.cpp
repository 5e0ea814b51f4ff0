#include "trebuchet/app/output/contest_record.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "trebuchet/format.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/app/output/report.hpp"
#include "trebuchet/app/records/shot_record.hpp"

namespace trebuchet {
namespace {

const char* const limit_words[contest_limit_count] = {"box width", "box height", "counterweight M", "peak axle load", "peak acceleration"};
const UnitDimension limit_dimensions[contest_limit_count] = {UnitDimension::length, UnitDimension::length, UnitDimension::mass, UnitDimension::force,
                                                             UnitDimension::acceleration};

// `text` and the spaces that take it to `width` columns: at least one, where it is as wide or wider.
std::string padded(const std::string& text, std::size_t width) { return text + std::string(text.size() < width ? width - text.size() : 1, ' '); }

// The clearance binds where asking for 10 % less gains; at the ground (none asked for) it only touches.
bool clearance_binds(const ContestEngine& best) {
  return best.gain_if_clearance_relaxed && *best.gain_if_clearance_relaxed > binding_gain * best.objective;
}

// What a limit costs, in words: "binds; 10 % more gains 3.08 m"; that the engine stands at it
// without its binding; or, clear of it (`clear`: "stands short of it", "keeps more than it"),
// that the looser limit lets another engine past this one.
std::string gain_words(const std::optional<double>& gain, bool at_limit, bool binds, const ContestRequest& request, UnitSystem units,
                       const char* looser, const char* clear) {
  if (!gain || (!binds && !at_limit)) return "";
  if (!binds) return std::string(": stands at it, but ") + looser + " gains nothing: does not bind";
  return (at_limit ? std::string(": binds; ") : std::string(": binds, though this engine ") + clear + "; ") + looser + " gains " +
      (request.efficiency ? format_significant(100 * *gain, 3) + " % in eps" : quantity_text(*gain, UnitDimension::length, units, 4)) +
      (at_limit ? "" : ", with another engine");
}

}  // namespace

LimitsToMeet contest_record_limits(const nlohmann::json& record) {
  LimitsToMeet out;
  if (!record.is_object() || !record.contains("limits") || !record["limits"].is_object()) return out;
  for (int k = 0; k < contest_limit_count; ++k) {
    const char* key = contest_limit_key(static_cast<ContestLimit>(k));
    if (const auto& limits = record["limits"];
        limits.contains(key) && limits[key].is_object() && limits[key].contains("limit") && limits[key]["limit"].is_number())
      out.limits[k] = limits[key]["limit"].get<double>();
  }
  if (record.contains("min_clearance") && record["min_clearance"].is_object() && record["min_clearance"].contains("least") &&
      record["min_clearance"]["least"].is_number())
    out.min_clearance = record["min_clearance"]["least"].get<double>();
  return out;
}

nlohmann::ordered_json contest_json(const ContestEngine& best, const ContestRequest& request, const std::vector<ContestEngine>& front) {
  nlohmann::ordered_json out = verification_json(best.verification);
  out["pin_to_bend_deg"] = best.verification.pin_to_bend_deg;  // with the pin's friction
  nlohmann::ordered_json engine;
  write_engine(engine, best.engine);
  out["engine"] = engine;
  out["assumptions"] = assumptions_json(best.engine, request.settings);
  out["objective"] = request.efficiency ? "eps" : "R";
  out["shots"] = best.shots;
  nlohmann::ordered_json limits = nlohmann::ordered_json::object();
  for (int k = 0; k < contest_limit_count; ++k) {
    const auto limit = static_cast<ContestLimit>(k);
    nlohmann::ordered_json one{{"measured", best.measured[k]}};
    one["limit"] = request.limits[k] ? nlohmann::ordered_json(*request.limits[k]) : nlohmann::ordered_json(nullptr);
    one["at_limit"] = best.at_limit[k];
    one["binds"] = best.binds[k];
    if (const auto& gain = best.gain_if_relaxed[k]) one["gain_if_relaxed_10_percent"] = *gain;  // R [m] or eps
    limits[contest_limit_key(limit)] = one;
  }
  out["limits"] = limits;
  nlohmann::ordered_json clearance{
      {"measured", best.clearance}, {"least", request.min_clearance}, {"at_limit", best.clearance_at_limit}, {"binds", clearance_binds(best)}};
  if (best.gain_if_clearance_relaxed) clearance["gain_if_relaxed_10_percent"] = *best.gain_if_clearance_relaxed;
  out["min_clearance"] = clearance;
  nlohmann::ordered_json reached = nlohmann::ordered_json::array();
  for (const auto& objective : best.start_objectives)
    reached.push_back(objective ? nlohmann::ordered_json(*objective) : nlohmann::ordered_json(nullptr));
  out["search"] = {{"local_searches", best.start_objectives.size()},
                   {"reached_best", searches_at_best(best.start_objectives, best.objective, best.start_objectives.size())},
                   {"objectives", reached},
                   {"from_starts", best.local_searches},
                   {"hops", best.hops},
                   {"hops_gained", best.hops_gained}};
  if (!front.empty()) {
    nlohmann::ordered_json points = nlohmann::ordered_json::array();
    for (const ContestEngine& p : front)
      points.push_back({{"axle_load", p.measured[axle_limit]},
                        {"R", p.verification.capacity.R},
                        {"eps", p.verification.eps},
                        {"M", p.engine.M},
                        {"L1", p.engine.L1},
                        {"L2", p.engine.L2},
                        {"L3", p.engine.L3},
                        {"L4", p.engine.L4},
                        {"pin_angle_deg", p.verification.pin_angle_deg},
                        {"pin_to_bend_deg", p.verification.pin_to_bend_deg}});
    out["pareto"] = points;
  }
  out[version_key] = project_version();
  return out;
}

std::string contest_table(const ContestEngine& best, const ContestRequest& request, const std::vector<ContestEngine>& front, UnitSystem units) {
  std::ostringstream out;
  out << "the best " << machine_words(request.machine) << " for " << (request.efficiency ? "eps" : "the range") << " within the limits ("
      << best.shots << " shots; docs/machines.md):\n"
      << verification_table(best.engine, request.settings, best.verification, std::nullopt, units)
      << "pin to bend for this release: " << pin_to_bend_text(best.verification, best.engine.parts.pin_friction, best.pin_releases) << "\nlimits:\n";
  const std::size_t width = units == UnitSystem::si ? 16 : 26;  // imperial gives SI beside
  bool any = false;
  for (int k = 0; k < contest_limit_count; ++k) {
    const std::string measured = quantity_text(best.measured[k], limit_dimensions[k], units, 5);
    out << "  " << padded(limit_words[k], 20);
    if (request.limits[k])
      out << padded(measured, width) << "limit " << quantity_text(*request.limits[k], limit_dimensions[k], units, 5)
          << gain_words(best.gain_if_relaxed[k], best.at_limit[k], best.binds[k], request, units, "10 % more", "stands short of it");
    else
      out << measured;
    out << "\n";
    any = any || best.binds[k];
  }
  const std::string clearance = quantity_text(best.clearance, UnitDimension::length, units, 5);
  out << "  counterweight clear " << padded(clearance, width) << "least " << quantity_text(request.min_clearance, UnitDimension::length, units, 5)
      << " above the ground" << (best.clearance_at_limit && !best.gain_if_clearance_relaxed ? ": touches the ground" : "")
      << gain_words(best.gain_if_clearance_relaxed, best.clearance_at_limit, clearance_binds(best), request, units, "10 % less", "keeps more than it")
      << "\n";
  any = any || clearance_binds(best) || best.clearance_at_limit;
  if (!any)
    out << "  no limit binds: the engine stops short of them where the model stops holding (a larger one would put its counterweight or tip below "
           "the base)\n";
  // The contest's own searches from its starts, its hops from the best, then the searches that
  // refined a better engine a gain's search shot.
  const std::size_t own = static_cast<std::size_t>(best.local_searches);
  const std::size_t from_gains = best.start_objectives.size() - std::min(best.start_objectives.size(), own + best.hops_gained);
  const std::string hopped = best.hops == 0 ? ""
                                            : "; then " + std::to_string(best.hops) + (best.hops == 1 ? " hop" : " hops") + " from the best, " +
          std::to_string(best.hops_gained) + " of which found a better engine";
  out << "search: " << searches_at_best(best.start_objectives, best.objective, own) << " of " << own
      << " local searches reached this best to 1e-4 (from the paper's proportions and the best of " << contest_sample_size << " Sobol points)"
      << hopped
      << (from_gains ? "; another search (a gain's or the Pareto front's) shot a better engine within the limits, refined by " +
                  std::to_string(from_gains) + " more"
                     : std::string())
      << "\n";
  if (!front.empty()) {
    out << "Pareto front of " << (request.efficiency ? "eps" : "the range") << " against the peak axle load (" << front.size()
        << (front.size() == 1 ? " optimum" : " optima") << "):\n"
        << "  " << padded("axle load", width) << padded("R", width) << padded("eps", 10) << padded("M", width) << "pin to bend\n";
    for (const ContestEngine& p : front) {
      const std::string load = quantity_text(p.measured[axle_limit], UnitDimension::force, units, 4);
      const std::string range = quantity_text(p.verification.capacity.R, UnitDimension::length, units, 5);
      const std::string eps = format_significant(100 * p.verification.eps, 4) + " %";
      const std::string mass = quantity_text(p.engine.M, UnitDimension::mass, units, 4);
      out << "  " << padded(load, width) << padded(range, width) << padded(eps, 10) << padded(mass, width)
          << (p.pin_releases ? format_significant(p.verification.pin_to_bend_deg, 4) + " deg" : std::string("none")) << "\n";
    }
  }
  return out.str();
}

std::vector<PictureFile> pareto_pictures(const std::vector<ContestEngine>& front, const ContestRequest& request) {
  std::ostringstream data;
  data << "axle_load_kN,R_m,eps\n";
  for (const ContestEngine& p : front)
    data << format_significant(p.measured[axle_limit] / 1e3, 9) << "," << format_significant(p.verification.capacity.R, 9) << ","
         << format_significant(p.verification.eps, 9) << "\n";
  std::ostringstream gp;
  gp << "# Made by trebuchet-verify contest --plot; run with gnuplot in this folder.\n"
     << "set encoding utf8\nset datafile separator ','\nset terminal svg size 900,600 dynamic font 'sans,13'\nset output 'pareto.svg'\n"
     << "set grid lc rgb '#dddddd'\nset key noenhanced top left\n"
     << "set title \"The best " << machine_words(request.machine) << " for each largest axle load, within the other limits\" noenhanced\n"
     << "set xlabel 'peak load on the axle [kN]'\nset ylabel '" << (request.efficiency ? "efficiency eps" : "range R [m]") << "'\n"
     << "plot 'pareto.csv' every ::1 using 1:" << (request.efficiency ? 3 : 2)
     << " with linespoints lw 2 pt 7 lc rgb '#1f5fbf' title 'Pareto front'\n";
  return {{"pareto.csv", data.str()}, {"pareto.gp", gp.str()}};
}

}  // namespace trebuchet
