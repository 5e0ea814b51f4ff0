#include "trebuchet/completion.hpp"

#include <algorithm>
#include <cmath>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "trebuchet/angles.hpp"
#include "simplex.hpp"

namespace trebuchet {
namespace {

// Two values of one quantity agree to this, relative: the 1e-9 to which attested values are kept.
constexpr double agreement = 1e-9;

// Starting shape of the search, near the paper's optima (tab:CPNC): l = L1/L2, l4 = L4/L1,
// mu = m/M, and K = (l + 1)/mu_b (eq:kMkD).
constexpr double start_l = 4.7, start_l4 = 0.87, start_mu = 0.016, start_K = 100;

std::string value_text(double value, const char* unit) { return format_significant(value, 6) + " " + unit; }

// One quantity known from several sources: they must agree.
struct Known {
  std::optional<double> value;
  std::string source;  // e.g. "L1 = 8 m" or "Lb - L2 = 8.2 m"

  void add(double v, const std::string& how) {
    if (value && std::abs(v - *value) > agreement * std::abs(*value))
      throw Error(ErrorKind::usage, "the attested values conflict: " + source + ", but " + how + "; give only one of them, or values that agree");
    if (!value) value = v, source = how;
  }
};

// The resolved subset: what is fixed, and what the search chooses.
struct Plan {
  double theta_i_deg = standard_theta_i_deg, F = standard_F;
  std::optional<double> L1, L2, Lb, L4, M, m;
  std::optional<double> l;  // attested beam ratio, when neither section is known
  std::optional<double> mb, D;  // attested beam
  std::optional<double> projectile_diameter;
  Material material;
  EngineParts parts;
};

// The beam of an engine: mb attested; or from an attested D by eq:BeamMass; or D from the
// allowed bending (eq:bend_L2) and then mb.
void set_beam(Engine& e, const Plan& p) {
  const double Lb = e.L1 + e.L2;
  if (p.mb) {
    e.mb = *p.mb;
    e.D = p.D.value_or(beam_diameter(e.mb, Lb, p.material));
    return;
  }
  e.D = p.D ? *p.D : bending_diameter(e.M, e.L2, p.material);
  e.mb = beam_mass(e.D, Lb, p.material);
}

// The engine at log coordinates x of the free quantities, in the order of start().
Engine build(const Plan& p, const std::vector<double>& x) {
  std::size_t k = 0;
  auto next = [&] { return std::exp(x.at(k++)); };
  Engine e;
  e.theta_i_deg = p.theta_i_deg;
  e.material = p.material;
  e.parts = p.parts;
  e.projectile_diameter = p.projectile_diameter;
  if (p.L1 && p.L2) {
    e.L1 = *p.L1, e.L2 = *p.L2;
  } else if (p.L1) {
    e.L1 = *p.L1, e.L2 = e.L1 / next();
  } else if (p.L2) {
    e.L2 = *p.L2, e.L1 = e.L2 * next();
  } else if (p.Lb) {
    const double l = next();
    e.L1 = *p.Lb * l / (l + 1), e.L2 = *p.Lb / (l + 1);
  } else {
    e.L2 = next();
    e.L1 = e.L2 * (p.l ? *p.l : next());
  }
  e.L3 = counterweight_arm(e.L1, e.L2, e.theta_i_deg, p.F);
  e.L4 = p.L4 ? *p.L4 : e.L1 * next();
  e.M = p.M ? *p.M : next();
  e.m = p.m ? *p.m : e.M * next();
  set_beam(e, p);
  return e;
}

// The start of the search in the coordinates of build(), and the names of what it chooses.
std::vector<double> start(const Plan& p, std::vector<std::string>& chosen) {
  std::vector<double> x;
  double L2 = p.L2.value_or(0);
  if (p.L1 && p.L2) {
  } else if (p.L1) {
    x.push_back(std::log(start_l)), chosen.push_back("L2"), L2 = *p.L1 / start_l;
  } else if (p.L2) {
    x.push_back(std::log(start_l)), chosen.push_back("L1");
  } else if (p.Lb) {
    x.push_back(std::log(start_l)), chosen.insert(chosen.end(), {"L1", "L2"}), L2 = *p.Lb / (start_l + 1);
  } else {
    // The size from the counterweight by eq:ExtraScalings, else 1 m.
    L2 = p.M ? short_arm_for(*p.M, start_K, p.material) : 1.0;
    x.push_back(std::log(L2)), chosen.insert(chosen.end(), {"L1", "L2"});
    if (!p.l) x.push_back(std::log(start_l));
  }
  if (!p.L4) x.push_back(std::log(start_l4)), chosen.push_back("L4");
  if (!p.M) {
    const double M = p.m ? *p.m / start_mu : extra_scalings(start_K, L2, p.material).M;
    x.push_back(std::log(M)), chosen.push_back("M");
  }
  if (!p.m) x.push_back(std::log(start_mu)), chosen.push_back("m");
  return x;
}

double objective_of(const Verification& v, const ReleaseCriterion& criterion) {
  switch (criterion.release) {
    case Release::range: return v.capacity.R;
    case Release::efficiency: return v.eps;
    case Release::quality: break;
  }
  return v.Q;
}

// Each attested value, positive (mb may be 0; theta_i is checked with its range), of ordinary
// size; its key is listed in out.attested.
void check_attested(const Attested& a, Completion& out) {
  for (const auto& [value, name] : {std::pair{a.Lb, "Lb"},
                                    {a.L1, "L1"},
                                    {a.L2, "L2"},
                                    {a.H, "H"},
                                    {a.L4, "L4"},
                                    {a.M, "M"},
                                    {a.m, "m"},
                                    {a.mb, "mb"},
                                    {a.D, "D"},
                                    {a.l, "l"},
                                    {a.theta_i_deg, "theta_i"},
                                    {a.F, "F"},
                                    {a.drop, "drop"}}) {
    if (!value) continue;
    const std::string key(name);
    if (key == "mb" && !(*value >= 0)) throw Error(ErrorKind::bad_number, "{{mb}} = " + format_significant(*value, 6) + " must not be negative");
    if (key != "mb" && key != "theta_i" && !(*value > 0))
      throw Error(ErrorKind::bad_number,
                  "{{" + key + "}} = " + format_significant(*value, 6) + " must be positive; give the attested value, or leave it out");
    // Of ordinary size, as an engine's own values are (check_engine): lengths and l from 1e-6
    // to 1e6, masses from 1e-9 to 1e12 kg, so that every value derived from them is finite.
    if (key == "M" || key == "m" || (key == "mb" && *value > 0))
      check_ordinary(*value, 1e-9, 1e12, key, "kg", "attested mass");
    else if (key == "l" || key == "F")
      check_ordinary(*value, 1e-6, 1e6, key, "", "attested ratio");
    else if (key != "theta_i" && key != "mb")
      check_ordinary(*value, 1e-6, 1e6, key, "m", "attested length");
    out.attested.push_back(key);
  }
}

// The beam's length and where it comes from.
struct BeamLength {
  std::optional<double> value;  // [m]
  std::string source;
};

// The beam's length: attested, or, with mb and D attested, from eq:BeamMass, which ties them.
BeamLength beam_length_of(const Attested& a, const Material& material, Completion& out) {
  BeamLength beam{a.Lb, a.Lb ? "Lb = " + value_text(*a.Lb, "m") : std::string()};
  std::optional<double>& beam_length = beam.value;
  std::string& beam_source = beam.source;
  if (a.mb && a.D && *a.mb > 0) {
    const double from_beam = *a.mb / beam_mass(*a.D, 1, material);  // mb over the mass of a metre of it
    if (beam_length && std::abs(from_beam - *beam_length) > agreement * *beam_length)
      throw Error(ErrorKind::usage,
                  "the attested values conflict: mb = " + value_text(*a.mb, "kg") + " and D = " + value_text(*a.D, "m") + " make a beam " +
                      value_text(from_beam, "m") + " long by eq:BeamMass with wood of " + format_significant(material.wood_density, 4) +
                      " kg/m3, but " + beam_source + "; drop one of them, or give {{wood_density}}");
    if (!beam_length) {
      beam_length = from_beam, beam_source = "Lb = mb/(rho_d (pi/4) D^2) = " + value_text(from_beam, "m");
      if (!(from_beam >= 1e-6 && from_beam <= 1e6))
        throw Error(ErrorKind::bad_number,
                    "{{mb}} = " + value_text(*a.mb, "kg") + " and {{D}} = " + value_text(*a.D, "m") + " make a beam " + value_text(from_beam, "m") +
                        " long by eq:BeamMass, beyond the ordinary lengths 1e-06 to 1e+06 m; check both");
      out.implied.push_back("Lb (from mb and D, eq:BeamMass)");
    }
  }
  return beam;
}

// The arms and theta_i from what is attested: L1 from itself, or from Lb - L2, before H (with H
// it fixes theta_i, or H fixes L1); L2 from itself, the drop, l or Lb - L1; F its standard
// unless attested. What is implied, and from what, is listed in out.implied.
void find_arms_and_angle(const Attested& a, const BeamLength& beam, Plan& p, Completion& out) {
  const std::optional<double>& beam_length = beam.value;
  const std::string& beam_source = beam.source;
  Known L1, L2;
  bool theta_from_H = false;
  if (a.L1) L1.add(*a.L1, "L1 = " + value_text(*a.L1, "m"));
  if (beam_length && a.L2) {
    if (!(*beam_length > *a.L2))
      throw Error(ErrorKind::usage, "the attested values conflict: " + beam_source + " is not longer than L2 = " + value_text(*a.L2, "m"));
    L1.add(*beam_length - *a.L2, "Lb - L2 = " + value_text(*beam_length - *a.L2, "m"));
  }
  if (a.theta_i_deg) {
    if (!(*a.theta_i_deg > 0 && *a.theta_i_deg < 90))
      throw Error(ErrorKind::bad_number, "{{theta_i_deg}} = " + format_significant(*a.theta_i_deg, 6) + " must lie between 0 and 90 degrees");
    p.theta_i_deg = *a.theta_i_deg;
  } else if (a.H && L1.value) {
    theta_from_H = true;
    if (!(*a.H < *L1.value))
      throw Error(
          ErrorKind::usage,
          "the attested values conflict: the pivot height H = " + value_text(*a.H, "m") + " is not below the long arm's length, " + L1.source);
    p.theta_i_deg = degrees(std::acos(*a.H / *L1.value));
    out.implied.push_back("theta_i (from H and L1)");
  }
  if (a.H)
    L1.add(*a.H / std::cos(radians(p.theta_i_deg)),
           "H / cos(theta_i) = " + value_text(*a.H / std::cos(radians(p.theta_i_deg)), "m") +
               (a.theta_i_deg ? "" : " with the standard theta_i = 30 deg"));
  // The hinged counterweight hangs from the short arm's end, which falls L2 (1 + cos theta_i)
  // to its lowest point (eq:DU); the drop gives L2, and with the beam's length L1.
  if (a.drop) {
    const double fall = 1 + std::cos(radians(p.theta_i_deg));  // per L2, scaled
    L2.add(
        *a.drop / fall,
        "drop/(1 + cos theta_i) = " + value_text(*a.drop / fall, "m") + (a.theta_i_deg || theta_from_H ? "" : " with the standard theta_i = 30 deg"));
    if (beam_length && !L1.value) {
      if (!(*beam_length > *L2.value))
        throw Error(ErrorKind::usage, "the attested values conflict: " + beam_source + " is not longer than " + L2.source);
      L1.add(*beam_length - *L2.value, "Lb - L2 = " + value_text(*beam_length - *L2.value, "m") + " (L2 from " + L2.source + ")");
    }
  }
  if (a.l && beam_length) L1.add(*beam_length * *a.l / (*a.l + 1), "Lb l/(l + 1) = " + value_text(*beam_length * *a.l / (*a.l + 1), "m"));
  if (a.L2) L2.add(*a.L2, "L2 = " + value_text(*a.L2, "m"));
  if (a.l && L1.value) L2.add(*L1.value / *a.l, "L1/l = " + value_text(*L1.value / *a.l, "m"));
  if (a.l && L2.value && !L1.value) L1.add(*L2.value * *a.l, "l L2 = " + value_text(*L2.value * *a.l, "m"));
  if (beam_length && L1.value) {
    if (!(*beam_length > *L1.value))
      throw Error(ErrorKind::usage, "the attested values conflict: " + beam_source + " is not longer than " + L1.source);
    L2.add(*beam_length - *L1.value, "Lb - L1 = " + value_text(*beam_length - *L1.value, "m") + " (L1 from " + L1.source + ")");
  }
  p.L1 = L1.value, p.L2 = L2.value, p.l = a.l;
  if (p.L1 && !a.L1) out.implied.push_back("L1 (" + L1.source + ")");
  if (p.L2 && !a.L2) out.implied.push_back("L2 (" + L2.source + ")");
  if (!a.theta_i_deg && !theta_from_H) out.implied.push_back("theta_i = 30 deg (the paper's standard)");
  p.F = a.F.value_or(standard_F);
  if (!a.F) out.implied.push_back("F = 2/3 (the paper's standard)");
}

// The beam: eq:BeamMass ties D, mb and Lb with the wood's density. And what the search needs to
// find a size: a length, and M or m (both to maximise the range).
void check_beam_and_size(const Attested& a, const std::optional<double>& beam_length, const Plan& p, const ReleaseCriterion& criterion,
                         Completion& out) {
  if (a.mb && a.D && p.L1 && p.L2) {
    const double from_D = beam_mass(*a.D, *p.L1 + *p.L2, p.material);
    if (std::abs(from_D - *a.mb) > agreement * *a.mb)
      throw Error(ErrorKind::usage,
                  "the attested values conflict: mb = " + value_text(*a.mb, "kg") + ", but D = " + value_text(*a.D, "m") +
                      " gives mb = " + value_text(from_D, "kg") + " by eq:BeamMass with wood of " + format_significant(p.material.wood_density, 4) +
                      " kg/m3; drop one of them, or give {{wood_density}}");
  }
  if (!a.mb)
    out.implied.push_back(a.D ? "mb (from D, eq:BeamMass)"
                              : "D and mb (from beta2 = " + format_fraction(p.material.beta2) + " and the wood, eq:bend_L2 and eq:BeamMass)");
  // Q does not fix the size: without a length it grows as the engine shrinks, and without M or
  // m as the counterweight grows against the beam.
  if (!(beam_length || a.L1 || a.L2 || a.H || a.L4 || a.drop) || !(a.M || a.m))
    throw Error(ErrorKind::usage,
                "complete needs an attested length (Lb, L1, L2, H, L4 or the drop, or mb with D) and the counterweight M or the stone m: "
                "without them the best engine has no size, e.g. {{Lb}} 9.5m {{m}} 50kg");
  if (criterion.release == Release::range && (!a.M || !a.m))
    throw Error(ErrorKind::usage,
                "the range grows without bound with a heavier counterweight or a lighter stone: give M and m "
                "for {{quality}} range, or maximise Q (the default)");
}

// The search over the values not attested (start and build): the engine whose shot maximises
// the criterion among those that work, shot again under the request's own settings.
void search_engine(const Plan& p, const CompletionRequest& request, Completion& out) {
  const ReleaseCriterion& criterion = request.settings.criterion;
  const std::vector<double> x0 = start(p, out.chosen);
  double best = -1;
  // The search's shots with the default stepper at a tolerance of 1e-8, whatever the request's
  // integrator: their Q is within 1e-9 of the default's (docs/work_precision.csv), far below the
  // change of Q across the final simplex, 1e-5 in log coordinates, and a third faster
  // (bench-completion). The winner is shot again under the request's own settings.
  ShotSettings search = request.settings;
  search.integrator = IntegratorSettings{};
  search.integrator.rtol = search.integrator.atol = 1e-8;
  search.integrator.max_energy_drift = 1e-6;
  search.loads = false;
  // Q and eps are properties of the release, which the air after it does not change: unless the
  // air acts before the release too, or the range in air is maximised, the trial engines fly in
  // vacuum, and only the winner through the request's air. In air that no engine can fly (a
  // headwind that blows every projectile back) the search then costs what it does in vacuum.
  if (criterion.release != Release::range && !search.drag_in_sling) search.air.reset();
  // An engine works when its shot runs and the model holds up to the release (no warning: the
  // sling pulls, the counterweight and the tip stay above the base); else it costs 0, worse
  // than any that works, and the last reason is kept for the message.
  std::optional<Error> last_failure;
  bool only_integration_failed = true;  // every engine tried failed in its integration
  // A search none of whose engines has worked sees a flat cost and wanders blind. When the first
  // blind_trials all fail in air while one of them works in vacuum, it is the air that no engine
  // of these values flies in (a headwind that blows every projectile back): the search stops
  // there, and the simplex's remaining steps cost nothing.
  const int blind_trials = 4 * static_cast<int>(x0.size() + 1);
  std::vector<std::vector<double>> tried;
  bool blind_in_air = false;
  const auto works_in_vacuum = [&](const std::vector<double>& x) {
    ShotSettings vacuum = search;
    vacuum.air.reset(), vacuum.drag_in_sling = false;
    try {
      return verify_engine(build(p, x), vacuum).warnings.empty();
    } catch (const Error&) {
      return false;
    }
  };
  auto cost = [&](const std::vector<double>& x) {
    if (blind_in_air) return 0.0;
    if (!(best > 0) && search.air && out.simulations < blind_trials) tried.push_back(x);
    if (!(best > 0) && search.air && out.simulations == blind_trials) {
      blind_in_air = std::any_of(tried.begin(), tried.end(), works_in_vacuum);
      if (blind_in_air) return 0.0;
    }
    ++out.simulations;
    try {
      const Engine e = build(p, x);
      const Verification v = verify_engine(e, search);  // checks the engine first
      if (!v.warnings.empty()) throw Error(ErrorKind::out_of_range, v.warnings.front());
      const double objective = objective_of(v, criterion);
      if (objective > best) best = objective, out.engine = e, out.verification = v;
      return -objective;
    } catch (const Error& e) {
      last_failure = e;
      only_integration_failed = only_integration_failed && integration_failed(e);
      return 0.0;
    }
  };
  if (x0.empty()) {
    const Engine e = build(p, x0);
    out.engine = e, out.verification = verify_engine(e, request.settings), out.simulations = 1;
  } else {
    cost(x0);
    minimize_simplex(cost, x0, 0.1, 1e-5, 600);
    if (blind_in_air)
      throw Error(ErrorKind::out_of_range,
                  "in " + describe_air(*search.air, 0) + " none of the " + std::to_string(out.simulations) +
                      " engines tried with these attested values works, where one of them works in vacuum" +
                      (last_failure ? " (the last tried: " + last_failure->named_message() + ")" : "") +
                      "; give less drag or a weaker headwind ({{wind}})");
    if (!(best > 0))
      throw Error(last_failure && only_integration_failed ? ErrorKind::numerical : ErrorKind::out_of_range,
                  "no choice of " + join(out.chosen, ", ") + " gives a working engine with these attested values" +
                      (last_failure ? " (the last tried: " + last_failure->named_message() + ")" : "") + "; check them, or attest fewer");
    out.verification = verify_engine(out.engine, request.settings);
    ++out.simulations;
  }
}

// The calculator's optimum for the same capacity, in vacuum at the base's level (section 6).
void add_calculator(const Plan& p, const CompletionRequest& request, Completion& out) {
  ShotSettings paper;
  paper.integrator = request.settings.integrator;
  const Verification vacuum = verify_engine(out.engine, paper);
  DesignRequest same;
  same.first = {Quantity::R, vacuum.capacity.R};
  same.second = {Quantity::T, vacuum.capacity.T};
  same.theta_i_deg = out.engine.theta_i_deg;
  same.F = p.F;
  same.material = p.material;
  try {
    out.calculator = design_optimal_engine(builtin_scaling_table(), same);
  } catch (const Error& e) {
    out.calculator_note = e.named_message();  // names kept for the program
  }
}

}  // namespace

Completion complete_engine(const CompletionRequest& request) {
  check_shot_settings(request.settings);
  check_material(request.material);
  const Attested& a = request.attested;
  Completion out;
  check_attested(a, out);
  Plan p;
  p.material = request.material;
  p.parts = request.parts;
  p.projectile_diameter = request.projectile_diameter;
  if (p.projectile_diameter) {  // a size beside a density is refused before the search, which would take it for a failed engine
    Engine ball;
    ball.m = 1, ball.projectile_diameter = p.projectile_diameter;
    settings_for(ball, request.settings);
  }
  if (p.parts.beam_cm || p.parts.D_tip)
    throw Error(ErrorKind::usage,
                "complete builds a uniform beam from the attested values; a beam as built ({{beam_cm}}, {{D_tip}}) is checked "
                "by a shot of the whole engine instead");
  const BeamLength beam = beam_length_of(a, p.material, out);
  p.L4 = a.L4, p.M = a.M, p.m = a.m, p.mb = a.mb, p.D = a.D, p.Lb = beam.value;
  find_arms_and_angle(a, beam, p, out);
  check_beam_and_size(a, beam.value, p, request.settings.criterion, out);
  search_engine(p, request, out);
  add_calculator(p, request, out);
  return out;
}

}  // namespace trebuchet
