#include "trebuchet/app/input/names.hpp"

#include <array>
#include <utility>

#include "trebuchet/error.hpp"

namespace trebuchet {
namespace {

// Each enum's names, one table serving both directions.
constexpr std::array<std::pair<Release, std::string_view>, 3> release_names = {
    {{Release::quality, "Q"}, {Release::efficiency, "eps"}, {Release::range, "range"}}};

constexpr std::array<std::pair<MachineKind, std::string_view>, 4> machine_table = {
    {{MachineKind::hinged, "hinged"}, {MachineKind::fixed, "fixed"}, {MachineKind::floating_arm, "floating-arm"}, {MachineKind::whipper, "whipper"}}};

constexpr std::array<std::pair<Stepper, std::string_view>, 11> stepper_table = {{{Stepper::rk2, "rk2"},
                                                                                 {Stepper::rk4, "rk4"},
                                                                                 {Stepper::rkf45, "rkf45"},
                                                                                 {Stepper::rkck, "rkck"},
                                                                                 {Stepper::rk8pd, "rk8pd"},
                                                                                 {Stepper::msadams, "msadams"},
                                                                                 {Stepper::rk1imp, "rk1imp"},
                                                                                 {Stepper::rk2imp, "rk2imp"},
                                                                                 {Stepper::rk4imp, "rk4imp"},
                                                                                 {Stepper::bsimp, "bsimp"},
                                                                                 {Stepper::msbdf, "msbdf"}}};

template <class Enum, std::size_t N>
std::string name_in(const std::array<std::pair<Enum, std::string_view>, N>& table, Enum value) {
  for (const auto& [known, name] : table)
    if (known == value) return std::string(name);
  return "?";
}

template <class Enum, std::size_t N>
const Enum* value_in(const std::array<std::pair<Enum, std::string_view>, N>& table, std::string_view name) {
  for (const auto& entry : table)
    if (entry.second == name) return &entry.first;
  return nullptr;
}

}  // namespace

std::string release_name(Release release) { return name_in(release_names, release); }

std::string release_by_name(ReleaseBy by) {
  constexpr std::array<std::pair<ReleaseBy, std::string_view>, 3> names{
      {{ReleaseBy::time, "time"}, {ReleaseBy::velocity_angle, "velocity_angle"}, {ReleaseBy::pin_angle, "pin_angle"}}};
  return name_in(names, by);
}

Release parse_release(std::string_view name, std::string_view option) {
  if (const Release* release = value_in(release_names, name)) return *release;
  throw Error(ErrorKind::usage,
              std::string(option) + ": '" + std::string(name) + "' is not a release criterion; use Q (eq:Q, eq:Q_n with {{n}}), eps or range");
}

std::string machine_name(MachineKind machine) { return name_in(machine_table, machine); }

std::string machine_words(MachineKind machine) {
  if (machine == MachineKind::whipper) return "whipper";
  return machine == MachineKind::hinged ? "engine" : machine_name(machine) + (machine == MachineKind::fixed ? "-counterweight engine" : " engine");
}

std::string machine_names() { return "hinged, fixed, floating-arm or whipper"; }

MachineKind parse_machine(std::string_view name, std::string_view option) {
  if (const MachineKind* machine = value_in(machine_table, name)) return *machine;
  if (name == "floating_arm") return MachineKind::floating_arm;
  throw Error(ErrorKind::usage, std::string(option) + ": '" + std::string(name) + "' is not a machine; use " + machine_names());
}

bool parse_efficiency_objective(std::string_view name, std::string_view option) {
  if (name != "range" && name != "eps")
    throw Error(ErrorKind::usage, std::string(option) + ": '" + std::string(name) + "' is not an objective; use range or eps");
  return name == "eps";
}

UnitSystem parse_unit_system(std::string_view name, std::string_view option) {
  if (name == "si" || name == "SI") return UnitSystem::si;
  if (name == "imperial") return UnitSystem::imperial;
  throw Error(ErrorKind::usage, std::string(option) + ": '" + std::string(name) + "' is not a system of units; use si or imperial");
}

std::string stepper_name(Stepper stepper) { return name_in(stepper_table, stepper); }

std::string stepper_names() {
  std::string list;
  for (std::size_t k = 0; k < stepper_table.size(); ++k)
    list += (k == 0 ? "" : k + 1 == stepper_table.size() ? " or " : ", ") + std::string(stepper_table[k].second);
  return list;
}

Stepper parse_stepper(std::string_view name, std::string_view option) {
  if (const Stepper* stepper = value_in(stepper_table, name)) return *stepper;
  throw Error(ErrorKind::usage, std::string(option) + ": '" + std::string(name) + "' is not a stepper; use " + stepper_names());
}

bool parse_range_from(std::string_view name, std::string_view option) {
  if (name != "pivot" && name != "release")
    throw Error(ErrorKind::usage, std::string(option) + ": '" + std::string(name) + "' is not a range; use pivot (the paper's) or release (Denny's)");
  return name == "release";
}

}  // namespace trebuchet
