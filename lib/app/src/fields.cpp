#include "trebuchet/app/fields.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "trebuchet/error.hpp"

namespace trebuchet {

namespace {

using V = DesignValues;
using D = UnitDimension;
using G = FieldGroup;
constexpr unsigned shot = op_shot, shot_complete = op_shot | op_complete, given_too = op_given | op_shot | op_complete;
constexpr unsigned material_everywhere = op_calculator | op_shot | op_complete | op_optimize;

}  // namespace

// The rows, in the order of the programs' help. The ranges are what the core checks
// (check_engine, check_material, check_ordinary); tests/test_fields.cpp holds each to it.
const std::vector<InputField>& input_fields() {
  static const std::vector<InputField> fields = {
      // The paper's engine (eq:Parameters) and its initial angles (eq:InitialConditions).
      {&V::L1,
       "L1",
       "--L1",
       {},
       D::length,
       "m",
       G::engine,
       given_too,
       "long arm",
       "long beam section, pivot to spigot",
       "6.13m",
       "",
       "1e-6 to 1e6 m"},
      {&V::L2,
       "L2",
       "--L2",
       {},
       D::length,
       "m",
       G::engine,
       given_too,
       "short arm",
       "short beam section, pivot to hinge",
       "1.08m",
       "",
       "1e-6 to 1e6 m"},
      {&V::L3,
       "L3",
       "--L3",
       {},
       D::length,
       "m",
       G::engine,
       shot,
       "counterweight arm",
       "counterweight arm, hinge to the counterweight's centre (or F)",
       "1.2m",
       "",
       "1e-6 to 1e6 m"},
      {&V::F,
       "F",
       "--F",
       {},
       D::dimensionless,
       "",
       G::alternative,
       op_calculator | shot_complete | op_optimize,
       "(L2 + L3)/H",
       "counterweight arm fraction (L2 + L3)/H, instead of L3 (section 2; not the force factor of eq:F)",
       "2/3",
       "2/3",
       "positive"},
      {&V::L4, "L4", "--L4", {}, D::length, "m", G::engine, given_too, "sling", "sling length, spigot to projectile", "5.80m", "", "1e-6 to 1e6 m"},
      {&V::M, "M", "--M", {}, D::mass, "kg", G::engine, given_too, "counterweight", "counterweight mass", "14.3t", "", "1e-9 to 1e12 kg"},
      {&V::m, "m", "--m", {}, D::mass, "kg", G::engine, given_too | op_optimize, "projectile", "projectile mass", "100kg", "", "1e-9 to 1e12 kg"},
      {&V::mb,
       "mb",
       "--mb",
       {},
       D::mass,
       "kg",
       G::engine,
       given_too,
       "beam mass",
       "beam mass (or D)",
       "660kg",
       "from D, eq:BeamMass",
       "0, or 1e-9 to 1e12 kg"},
      {&V::D,
       "D",
       "--D",
       {},
       D::length,
       "m",
       G::alternative,
       given_too,
       "beam diameter",
       "beam diameter: the beam's stress; without mb, mb = rho_d (pi/4) D^2 Lb (eq:BeamMass)",
       "0.4m",
       "0: not given",
       "0, or 1e-6 to 1e6 m"},
      {&V::theta_i_deg,
       "theta_i_deg",
       "--theta",
       {"theta"},
       D::angle,
       "",
       G::engine,
       op_calculator | shot_complete | op_optimize,
       "θi [deg]",
       "initial beam angle theta_i from the downward vertical",
       "30",
       "30",
       "0 to 90 deg, both excluded (the calculator: 30 or 40)"},
      {&V::psi_i_deg,
       "psi_i_deg",
       "--psi-i",
       {"psi_i"},
       D::angle,
       "",
       G::engine,
       shot,
       "ψi [deg]",
       "initial counterweight angle psi_i of a propped counterweight (negative: held back, the sense opposite to the beam's turn)",
       "-20",
       "0, hanging",
       "-90 to 90 deg, both excluded"},
      // What a completion may be given in place of L1 and L2 (and the calculator as a given).
      {&V::Lb,
       "Lb",
       "--Lb",
       {},
       D::length,
       "m",
       G::alternative,
       op_given | op_complete,
       "beam length",
       "beam length L1 + L2",
       "9.5m",
       "",
       "1e-6 to 1e6 m"},
      {&V::H,
       "H",
       "--H",
       {},
       D::length,
       "m",
       G::alternative,
       op_complete,
       "pivot height",
       "pivot height L1 cos(theta_i)",
       "3.5m",
       "",
       "1e-6 to 1e6 m"},
      {&V::l,
       "l",
       "--l",
       {},
       D::dimensionless,
       "",
       G::alternative,
       op_given | op_complete | op_optimize,
       "beam ratio L1/L2",
       "beam ratio L1/L2",
       "4.5",
       "",
       "above 1"},
      // A capacity: to check a shot against, or to design for.
      {&V::R,
       "R",
       "--R",
       {},
       D::length,
       "m",
       G::capacity,
       op_given | shot | op_optimize,
       "range",
       "range from the pivot to where the projectile comes down at the target level",
       "150m",
       "",
       "positive"},
      {&V::T,
       "T",
       "--T",
       {},
       D::energy,
       "J",
       G::capacity,
       op_given | shot | op_optimize,
       "energy",
       "kinetic energy of the projectile at the target level (eq:T)",
       "40kJ",
       "",
       "positive"},
      // The material (eq:kMkD, eq:bend_L2, eq:BeamMass).
      {&V::beta2,
       "beta2",
       "--beta2",
       {},
       D::dimensionless,
       "",
       G::material,
       material_everywhere,
       "β2",
       "allowed bending of the short beam section under M (eq:bend_L2)",
       "1/300",
       "1/300",
       "1e-9 to 1"},
      {&V::youngs_modulus,
       "youngs_modulus",
       "--youngs-modulus",
       {},
       D::pressure,
       "Pa",
       G::material,
       material_everywhere,
       "Young's modulus",
       "Young's modulus of the beam's wood",
       "12GPa",
       "12 GPa",
       "1e3 to 1e15 Pa"},
      {&V::wood_density,
       "wood_density",
       "--wood-density",
       {},
       D::density,
       "kg_m3",
       G::material,
       material_everywhere,
       "wood density",
       "density of the beam's wood, for D and mb (eq:BeamMass)",
       "700kg/m3",
       "700 kg/m3",
       "1 to 1e5 kg/m3"},
      {&V::g,
       "g",
       "--g",
       {},
       D::acceleration,
       "m_s2",
       G::material,
       material_everywhere,
       "g",
       "gravitational acceleration; the moon's is 1.62 m/s2",
       "9.81m/s2",
       "9.81 m/s2",
       "1e-6 to 1e6 m/s2"},
      // The engine as built (EngineParts): a shot takes all of them, complete those that do not
      // depend on the values it chooses (its beam is uniform, its counterweight a point or given).
      {&V::beam_cm,
       "beam_cm",
       "--beam-cm",
       {},
       D::length,
       "m",
       G::part,
       shot,
       "beam's centre of mass",
       "the beam as built: its centre of mass from the pivot toward the tip (with its inertia or radius of gyration)",
       "1.5m",
       "a uniform beam's",
       "on the beam"},
      {&V::beam_inertia,
       "beam_inertia",
       "--beam-inertia",
       {},
       D::inertia,
       "kg*m2",
       G::part,
       shot,
       "beam's inertia",
       "the beam's moment of inertia about the pivot",
       "2000kg*m2",
       "a uniform beam's",
       "positive"},
      {&V::beam_gyration,
       "beam_gyration",
       "--beam-gyration",
       {},
       D::length,
       "m",
       G::part,
       shot,
       "beam's radius of gyration",
       "the beam's radius of gyration about the pivot, sqrt(I/mb), instead of its inertia",
       "2.2m",
       "a uniform beam's",
       "1e-6 to 1e6 m"},
      {&V::D_hinge,
       "D_hinge",
       "--D-hinge",
       {},
       D::length,
       "m",
       G::part,
       shot,
       "taper at the hinge",
       "a tapered beam of the wood: its diameter at the hinge end (with the tip's; gives mb)",
       "0.45m",
       "",
       "1e-6 to 1e6 m"},
      {&V::D_tip,
       "D_tip",
       "--D-tip",
       {},
       D::length,
       "m",
       G::part,
       shot,
       "taper at the tip",
       "the tapered beam's diameter at the tip",
       "0.2m",
       "",
       "1e-6 to 1e6 m"},
      {&V::counterweight_inertia,
       "counterweight_inertia",
       "--counterweight-inertia",
       {},
       D::inertia,
       "kg*m2",
       G::part,
       shot_complete,
       "counterweight's inertia",
       "the counterweight's moment of inertia about its centre",
       "500kg*m2",
       "0, a point",
       "0 or more"},
      {&V::box_width,
       "box_width",
       "--box-width",
       {},
       D::length,
       "m",
       G::part,
       shot,
       "box width",
       "a box counterweight: its width (with its height), inertia M (w^2 + h^2)/12",
       "1.2m",
       "",
       "1e-6 to 1e6 m"},
      {&V::box_height,
       "box_height",
       "--box-height",
       {},
       D::length,
       "m",
       G::part,
       shot,
       "box height",
       "the box counterweight's height",
       "0.8m",
       "",
       "1e-6 to 1e6 m"},
      {&V::axle_friction,
       "axle_friction",
       "--axle-friction",
       {},
       D::dimensionless,
       "",
       G::part,
       shot_complete,
       "axle friction",
       "Coulomb friction coefficient of the axle at the pivot (with its radius)",
       "0.1",
       "0",
       "0, or 1e-6 to 2"},
      {&V::axle_radius,
       "axle_radius",
       "--axle-radius",
       {},
       D::length,
       "m",
       G::part,
       shot_complete,
       "axle radius",
       "the axle's radius",
       "5cm",
       "0",
       "1e-6 to 1e6 m"},
      {&V::hinge_friction,
       "hinge_friction",
       "--hinge-friction",
       {},
       D::dimensionless,
       "",
       G::part,
       shot_complete,
       "hinge friction",
       "friction coefficient of the counterweight's hinge pin (with its radius)",
       "0.1",
       "0",
       "0, or 1e-6 to 2"},
      {&V::hinge_radius,
       "hinge_radius",
       "--hinge-radius",
       {},
       D::length,
       "m",
       G::part,
       shot_complete,
       "hinge radius",
       "the hinge pin's radius",
       "3cm",
       "0",
       "1e-6 to 1e6 m"},
      {&V::trough_friction,
       "trough_friction",
       "--trough-friction",
       {},
       D::dimensionless,
       "",
       G::part,
       shot_complete,
       "trough friction",
       "friction coefficient of the projectile sliding on the trough",
       "0.3",
       "0",
       "0, or 1e-6 to 2"},
      {&V::rope_diameter,
       "rope_diameter",
       "--rope-diameter",
       {},
       D::length,
       "m",
       G::part,
       shot_complete,
       "rope diameter",
       "the sling rope's diameter, for its drag when the air acts in the sling",
       "2cm",
       "0, no drag",
       "0 to half the sling's length"},
      {&V::rope_cd,
       "rope_cd",
       "--rope-cd",
       {},
       D::dimensionless,
       "",
       G::part,
       shot_complete,
       "rope's drag coefficient",
       "drag coefficient of the rope across the flow",
       "1.2",
       "1.2",
       "1e-3 to 1e2"}};
  return fields;
}

const InputField& field_of(std::optional<double> DesignValues::*member) {
  // The rows by their member's place in DesignValues: a batch writes every engine's keys.
  constexpr std::size_t members = sizeof(DesignValues) / sizeof(std::optional<double>);
  static const DesignValues probe{};
  const auto place = [](std::optional<double> DesignValues::*m) {
    return static_cast<std::size_t>(reinterpret_cast<const char*>(&(probe.*m)) - reinterpret_cast<const char*>(&probe)) /
        sizeof(std::optional<double>);
  };
  static const std::array<const InputField*, members> rows = [&] {
    std::array<const InputField*, members> out{};
    for (const InputField& field : input_fields()) out[place(field.member)] = &field;
    return out;
  }();
  const InputField* row = rows[place(member)];
  if (!row) throw Error(ErrorKind::numerical, "internal error: a member of DesignValues has no row in input_fields()");
  return *row;
}

const InputField* find_field(std::string_view name) {
  for (const InputField& field : input_fields()) {
    if (name == field.key) return &field;
    for (const char* alias : field.aliases)
      if (name == alias) return &field;
  }
  return nullptr;
}

std::string option_help(const InputField& field) {
  std::string help = field.help;
  if (*field.fallback) help += std::string(" (default ") + field.fallback + ")";
  if (field.dimension != UnitDimension::dimensionless && field.dimension != UnitDimension::angle) help += " [" + unit_list(field.dimension) + "]";
  if (field.dimension == UnitDimension::angle) help += " [deg]";
  return help;
}

std::vector<const char*> names_of(const InputField& field) {
  std::vector<const char*> names{field.key};
  names.insert(names.end(), field.aliases.begin(), field.aliases.end());
  return names;
}

std::string csv_column_of(const InputField& field) { return *field.unit ? std::string(field.key) + "_" + field.unit : field.key; }

std::size_t edit_distance(std::string_view a, std::string_view b) {
  auto same = [](char x, char y) { return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y)); };
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1])) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

bool near_name(std::string_view word, std::string_view name) {
  const std::size_t allowed = name.size() <= 2 ? 0 : name.size() <= 4 ? 1 : 2;
  return edit_distance(word, name) <= allowed;
}

std::string near_miss(std::string_view word, const std::vector<std::string>& known) {
  // An input's name with its unit left off, or another unit put on: "theta_i" (theta_i_deg),
  // "L4_ft", "M_kg", "theta_deg".
  for (const InputField& field : input_fields()) {
    if (std::find(known.begin(), known.end(), field.key) == known.end()) continue;  // not this reader's
    std::string_view key = field.key;
    const std::string_view stem = field.dimension == UnitDimension::angle ? key.substr(0, key.rfind("_deg")) : key;
    std::vector<std::string_view> names{stem};
    for (const char* alias : field.aliases) names.emplace_back(alias);
    for (std::string_view name : names) {
      if (word == name && word != key) return field.key;
      if (word.size() > name.size() + 1 && word.substr(0, name.size()) == name && word[name.size()] == '_' &&
          is_unit_word(word.substr(name.size() + 1)))
        return field.key;
    }
  }
  std::string best;
  std::size_t best_distance = 0;
  for (const std::string& name : known) {
    const std::size_t distance = edit_distance(word, name);
    if (near_name(word, name) && name != word && (best.empty() || distance < best_distance)) best = name, best_distance = distance;
  }
  return best;
}

const char* dimension_name(UnitDimension dimension) {
  switch (dimension) {
    case UnitDimension::length: return "length";
    case UnitDimension::mass: return "mass";
    case UnitDimension::energy: return "energy";
    case UnitDimension::dimensionless: return "dimensionless";
    case UnitDimension::angle: return "angle";
    case UnitDimension::acceleration: return "acceleration";
    case UnitDimension::pressure: return "pressure";
    case UnitDimension::density: return "density";
    case UnitDimension::time: return "time";
    case UnitDimension::speed: return "speed";
    case UnitDimension::force: return "force";
    case UnitDimension::moment: return "moment";
    case UnitDimension::inertia: return "inertia";
  }
  return "dimensionless";
}

std::vector<std::string> input_names(unsigned operations) {
  std::vector<std::string> names;
  for (const InputField& field : input_fields()) {
    if (!(field.operations & operations)) continue;
    names.emplace_back(field.key);
    for (const char* alias : field.aliases) names.emplace_back(alias);
  }
  return names;
}

}  // namespace trebuchet
