#include "trebuchet/air.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <memory>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"
#include "gsl_errors.hpp"
#include "solve_1d.hpp"

namespace trebuchet {
namespace {

struct FlightParameters {
  Drag drag;
  double g;
  long evaluations = 0;  // of flight_rhs, against max_flight_evaluations
};

// A flight takes about 410 evaluations of its equations (320 stepping, 95 for its end);
// one that needs 20000 is in an air so dense that its drag makes the equations stiff,
// and would take minutes in an explicit stepper: it is given up as one that never lands.
constexpr long max_flight_evaluations = 20000;

// The projectile's velocity through the air u = v - wind (the target lies toward -x), its speed
// and Cd there.
struct Airflow {
  double ux, uy, speed, cd;
};
Airflow airflow(const FlightParameters& p, const double y[]) {
  const double ux = y[2] + p.drag.wind, uy = y[3];
  const double speed = std::sqrt(ux * ux + uy * uy);
  return {ux, uy, speed, p.drag.coefficient_at(speed)};
}

// dx/dt = v, dv/dt = -g y^ - Cd (rho A / 2m) |u| u.
void flight_equations(const FlightParameters& p, const double y[], const Airflow& a, double dydt[]) {
  const double k = a.cd * p.drag.per_length * a.speed;
  dydt[0] = y[2];
  dydt[1] = y[3];
  dydt[2] = -k * a.ux;
  dydt[3] = -p.g - k * a.uy;
}

int flight_rhs(double, const double y[], double dydt[], void* params) {
  auto& p = *static_cast<FlightParameters*>(params);
  if (++p.evaluations > max_flight_evaluations) return GSL_EBADFUNC;
  flight_equations(p, y, airflow(p, y), dydt);
  return GSL_SUCCESS;
}

struct DriverDeleter {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

}  // namespace

const std::vector<ProjectileMaterial>& projectile_materials() {
  // The elements' densities at room temperature are those of the CRC Handbook of Chemistry and
  // Physics (iron 7.87 g/cm^3, lead 11.34 g/cm^3). Stone: limestone and sandstone lie near
  // 2300-2600 kg/m^3, granite near 2700; 2500 is the tool's long-standing default. Fired clay:
  // solid fired-clay brick lies between about 1600 and 1900 kg/m^3 (civiltoday.com, "Density of
  // Brick", after simetric.co.uk: common red brick 1900), so a clay ball about 1800.
  static const std::vector<ProjectileMaterial> materials = {
      {"stone", 2500, "stone, 2500 kg/m3 (limestone, sandstone; granite is nearer 2700)"},
      {"iron", 7870, "iron, 7870 kg/m3 (CRC Handbook)"},
      {"lead", 11340, "lead, 11340 kg/m3 (CRC Handbook)"},
      {"clay", 1800, "fired clay, about 1800 kg/m3 (solid brick lies between 1600 and 1900)"},
  };
  return materials;
}

const ProjectileMaterial* find_projectile_material(const std::string& name) {
  for (const ProjectileMaterial& m : projectile_materials())
    if (name == m.name) return &m;
  return nullptr;
}

double sphere_diameter(double mass, double density) { return std::cbrt(6 * mass / (M_PI * density)); }

double sphere_density(double mass, double diameter) { return mass / (M_PI / 6 * diameter * diameter * diameter); }

double drag_coefficient_of(double re) {
  if (!(re > 0)) return 0;
  // F. A. Morrison, An Introduction to Fluid Mechanics (Cambridge University Press, 2013), as
  // given in her note "Data Correlation for Drag Coefficient for Sphere" (Michigan Technological
  // University, 10 November 2016): a fit to the standard drag curve of a smooth sphere, with
  // the drag crisis near Re = 3e5, not recommended above Re = 1e6 (max_fitted_reynolds). Its
  // last term, 0.25 (Re/1e6)/(1 + Re/1e6), levels off; the note's 2010 version ends instead in
  // Re^0.8/461000, which keeps rising (docs/verifier.md, "Air").
  const double a = re / 5, b = re / 263000, c = re / 1e6;
  return 24 / re + 2.6 * a / (1 + std::pow(a, 1.52)) + 0.411 * std::pow(b, -7.94) / (1 + std::pow(b, -8)) + 0.25 * c / (1 + c);
}

double drag_coefficient_slope_of(double re) {
  if (!(re > 0)) return 0;
  // Term by term: d/dx [x/(1 + x^p)] = (1 + (1 - p) x^p)/(1 + x^p)^2; the third term,
  // x^-7.94/(1 + x^-8) = x^0.06/(1 + x^8), has the slope x^-0.94 (0.06 - 7.94 x^8)/(1 + x^8)^2,
  // written in x^-8 above x = 1 so that neither power overflows; each x is Re over its scale.
  const double a = re / 5, b = re / 263000, c = re / 1e6;
  const double ap = std::pow(a, 1.52);
  double third = 0;
  if (b < 1) {
    const double b8 = std::pow(b, 8);
    third = std::pow(b, -0.94) * (0.06 - 7.94 * b8) / ((1 + b8) * (1 + b8));
  } else {
    const double br = std::pow(b, -8);
    third = std::pow(b, -8.94) * (0.06 * br - 7.94) / ((1 + br) * (1 + br));
  }
  return -24 / (re * re) + 2.6 / 5 * (1 - 0.52 * ap) / ((1 + ap) * (1 + ap)) + 0.411 / 263000 * third + 0.25 / 1e6 / ((1 + c) * (1 + c));
}

void check_air(const Air& air) {
  // From thin air to far denser than water, from cork to beyond osmium, winds far past any
  // storm's: beyond them the flight is no longer a flight.
  check_ordinary(air.density, 1e-6, 1e4, "air_density", "kg/m3", "density of the air");
  check_ordinary(air.projectile_density, 1, 1e5, "projectile", "kg/m3", "projectile's density");
  if (air.drag_coefficient) check_ordinary(*air.drag_coefficient, 1e-3, 1e2, "cd", "", "drag coefficient");
  check_ordinary(air.wind, -1e3, 1e3, "wind", "m/s", "wind's speed (against the throw when negative)");
}

Drag drag_of(const Air& air, double mass) {
  const double d = sphere_diameter(mass, air.projectile_density);
  Drag drag;
  drag.per_length = air.density * (M_PI * d * d / 4) / (2 * mass);
  drag.drag_coefficient = air.drag_coefficient;
  drag.reynolds_per_speed = air.density * d / air.viscosity;
  drag.wind = air.wind;
  return drag;
}

Drag scaled(const Drag& drag, double L2, double g) {
  const double speed_unit = std::sqrt(g * L2);  // section 3
  Drag out = drag;
  out.per_length = drag.per_length * L2;
  out.reynolds_per_speed = drag.reynolds_per_speed * speed_unit;
  out.wind = drag.wind / speed_unit;
  return out;
}

namespace {

// A flight's integrator over its equations (and their tangent, FlightTangent), and where it comes
// down: adaptive steps until the height (y[1]) falls through -drop on the way down, within 128
// times the flight in vacuum, then the root within that step.
class Flight {
 public:
  Flight(gsl_odeiv2_system& system, double scale)
      : system_(system), scale_(scale), driver_(gsl_odeiv2_driver_alloc_y_new(&system, gsl_odeiv2_step_rk8pd, scale / 256, 1e-13, 1e-13)) {}

  // The state at time t integrated afresh from (t0, y0), so that a root search sees one smooth
  // function, as a shot's events do (shot.cpp).
  bool integrate(double t0, const double* y0, double t, double* y) {
    for (std::size_t k = 0; k < system_.dimension; ++k) y[k] = y0[k];
    gsl_odeiv2_driver_reset(driver_.get());
    double time = t0;
    return t <= t0 || gsl_odeiv2_driver_apply(driver_.get(), &time, t, y) == GSL_SUCCESS;
  }

  // The same within a step the flight took from (t0, y0): a step no longer than one the
  // tolerance accepted is tried first as one step, so a root's state costs one step.
  bool integrate_within_step(double t0, const double* y0, double t, double* y) {
    for (std::size_t k = 0; k < system_.dimension; ++k) y[k] = y0[k];
    if (t <= t0) return true;
    gsl_odeiv2_driver_reset_hstart(driver_.get(), t - t0);
    double time = t0;
    return gsl_odeiv2_driver_apply(driver_.get(), &time, t, y) == GSL_SUCCESS;
  }

  // The time the flight from y0 comes down through -drop, with the state there in `end`.
  std::optional<double> land(const double* y0, double drop, double* end) {
    const std::size_t n = system_.dimension;
    double a[8], b[8];
    for (std::size_t k = 0; k < n; ++k) b[k] = y0[k];
    double t_b = 0, h = scale_ / 256;
    while (t_b < 128 * scale_) {
      double t_a = t_b;
      for (std::size_t k = 0; k < n; ++k) a[k] = b[k];
      if (gsl_odeiv2_evolve_apply(driver_->e, driver_->c, driver_->s, &system_, &t_b, 128 * scale_, &h, b) != GSL_SUCCESS) return std::nullopt;
      // Down through the level within this step; a flight that never rose to it (a target above
      // its apex in air) never comes down there. A step may pass over the apex, rising below the
      // level and falling below it again: the flight then reaches the level if its apex, the root
      // of the vertical speed within the step, lies above it, and comes down through it after.
      if (b[1] <= -drop && b[3] < 0) {
        if (!(a[1] > -drop)) {
          if (!(a[3] > 0)) return std::nullopt;
          double top[8];
          const double t_top = find_root(
              [&](double t) {
                integrate_within_step(t_a, a, t, top);
                return top[3];
              },
              t_a, t_b, 0, 1e-15);
          integrate_within_step(t_a, a, t_top, top);
          if (!(top[1] > -drop)) return std::nullopt;
          t_a = t_top;
          for (std::size_t k = 0; k < n; ++k) a[k] = top[k];
        }
        // Newton's method on the height, whose derivative is the vertical speed, from the step's
        // end, each state one step from the step's start: 95 evaluations of the equations, where
        // Brent's bracketing over states integrated from the driver's last step size took 150.
        const double t_end = newton_root(
            [&](double t) {
              integrate_within_step(t_a, a, t, end);
              return std::pair{end[1] + drop, end[3]};
            },
            t_a, t_b - (b[1] + drop) / b[3], t_b, 1e-15);
        integrate_within_step(t_a, a, t_end, end);
        return t_end;
      }
    }
    return std::nullopt;
  }

 private:
  gsl_odeiv2_system& system_;
  double scale_;
  std::unique_ptr<gsl_odeiv2_driver, DriverDeleter> driver_;
};

// The flight in vacuum sets the scale of time; drag only shortens it.
double flight_scale(Vec2 velocity, double drop, double g) {
  const double vacuum_time = (velocity.y + std::sqrt(velocity.y * velocity.y + 2 * g * std::max(drop, 0.0))) / g;
  return std::max(vacuum_time, 1e-6);
}

// The flight's equations (flight_rhs) and their tangent w = (dx, dy, dvx, dvy) along a change of
// the start: dw/dt = J w, J the equations' Jacobian. The drag's acceleration -k(s) u, s = |u|,
// k = Cd(s) per_length s, has the Jacobian -(k I + k'(s) u u^T / s) in the velocity.
int flight_tangent_rhs(double, const double y[], double dydt[], void* params) {
  auto& p = *static_cast<FlightParameters*>(params);
  if (++p.evaluations > max_flight_evaluations) return GSL_EBADFUNC;
  const Airflow a = airflow(p, y);
  flight_equations(p, y, a, dydt);
  const double k = a.cd * p.drag.per_length * a.speed;
  const double k_slope = p.drag.per_length * (a.cd + a.speed * p.drag.coefficient_slope_at(a.speed));
  const double along = a.speed > 0 ? k_slope * (a.ux * y[6] + a.uy * y[7]) / a.speed : 0;
  dydt[4] = y[6];
  dydt[5] = y[7];
  dydt[6] = -k * y[6] - along * a.ux;
  dydt[7] = -k * y[7] - along * a.uy;
  return GSL_SUCCESS;
}

}  // namespace

std::optional<FlightEnd> fly(Vec2 position, Vec2 velocity, double drop, const Drag& drag, double g, std::vector<Vec2>* path, int path_points) {
  use_gsl_return_codes();
  FlightParameters parameters{drag, g};
  gsl_odeiv2_system system{flight_rhs, nullptr, 4, &parameters};
  Flight flight(system, flight_scale(velocity, drop, g));
  const double y0[4] = {position.x, 0, velocity.x, velocity.y};
  double end[4];
  const auto t_end = flight.land(y0, drop, end);
  if (!t_end) return std::nullopt;
  for (int k = 0; path && k < path_points; ++k) {
    parameters.evaluations = 0;  // each point of the picture's path is a flight of its own
    double at[4];
    flight.integrate(0, y0, *t_end * k / (path_points - 1), at);
    path->push_back({at[0], at[1]});
  }
  return FlightEnd{-end[0], *t_end, {end[2], end[3]}};
}

std::optional<RangeRate> range_rate(Vec2 position, Vec2 velocity, double drop, const FlightTangent& tangent, const Drag& drag, double g) {
  use_gsl_return_codes();
  FlightParameters parameters{drag, g};
  gsl_odeiv2_system system{flight_tangent_rhs, nullptr, 8, &parameters};
  Flight flight(system, flight_scale(velocity, drop, g));
  // The start's height is the flight's origin: its change is the level's, -tangent.drop.
  const double y0[8] = {position.x, 0, velocity.x, velocity.y, tangent.position.x, 0, tangent.velocity.x, tangent.velocity.y};
  double end[8];
  if (!flight.land(y0, drop, end)) return std::nullopt;
  // The end's time moves so that y + w_y dt stays on the level: dt = (-drop' - w_y)/v_y.
  const double dt = (-tangent.drop - end[5]) / end[3];
  return RangeRate{-end[0], -(end[4] + end[2] * dt)};
}

std::string describe_air(const Air& air, double mass, AirDrawn drawn) {
  std::string text = "air (";
  text += drawn.cd           ? std::string("Cd drawn")
      : air.drag_coefficient ? "Cd " + format_significant(*air.drag_coefficient, 3)
                             : std::string("Cd(Re) of a smooth sphere");
  text += drawn.density ? std::string(", air density drawn") : ", air " + format_significant(air.density, 3) + " kg/m3";
  if (drawn.projectile) {
    text += ", a sphere of the given diameter, its density following its mass, ";
  } else {
    text += ", a sphere of " + format_significant(air.projectile_density, 5) + " kg/m3, ";
    if (mass > 0) text += "d = " + format_significant(sphere_diameter(mass, air.projectile_density), 3) + " m, ";
  }
  text += drawn.wind  ? std::string("wind drawn")
      : air.wind == 0 ? std::string("no wind")
                      : "wind " + format_significant(air.wind, 3) + " m/s toward the target";
  return text + ")";
}

}  // namespace trebuchet
