// The projectile's flight through air, when a scene asks for it (--air): quadratic drag on a
// sphere, as the paper's discussion of tab:Denny (section 6.3) assumes, integrated with GSL
// odeiv2 to the target level. Vacuum stays the default everywhere else.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "trebuchet/drag.hpp"
#include "trebuchet/dynamics.hpp"

namespace trebuchet {

/// The air and the projectile's make. Defaults: a stone sphere in still air at sea level.
struct Air {
  double density = 1.2;  ///< of the air [kg/m^3]
  std::optional<double> drag_coefficient = 0.47;  ///< Cd of a sphere; nullopt: Cd(Re), drag_coefficient_of
  double projectile_density = 2500;  ///< stone [kg/m^3] (projectile_materials)
  double viscosity = 1.81e-5;  ///< dynamic viscosity of air at 15 degC [Pa s], for Re
  double wind = 0;  ///< horizontal wind toward the target (against it: < 0) [m/s]
};

/// A projectile's material by name, for its density: it sets the sphere's diameter, and with it
/// the drag in air (drag_of).
struct ProjectileMaterial {
  const char* name;
  double density;  ///< [kg/m^3]
  const char* words;  ///< what it is, and where the density comes from
};

/// stone (granite and limestone, about 2500 kg/m^3, the default), iron (cast, 7870), lead (11340)
/// and fired clay (about 1800), in that order; air.cpp gives each its source.
const std::vector<ProjectileMaterial>& projectile_materials();

/// The material named `name` ("stone", "iron", "lead", "clay"), or none.
const ProjectileMaterial* find_projectile_material(const std::string& name);

/// Refuses (Error(bad_number), naming {{air_density}}, {{projectile}}, {{cd}} or {{wind}}) air
/// or a projectile outside the ordinary: air 1e-6 to 1e4 kg/m^3, projectile 1 to 1e5 kg/m^3,
/// Cd 1e-3 to 100, wind up to 1000 m/s either way.
void check_air(const Air& air);

/// The diameter of a sphere of `mass` [kg] and `density` [kg/m^3] [m].
double sphere_diameter(double mass, double density);

/// The density of a sphere of `mass` [kg] and `diameter` [m]: the mass over its volume [kg/m^3].
double sphere_density(double mass, double diameter);

/// The drag on a projectile of `mass` [kg] in SI units.
Drag drag_of(const Air& air, double mass);

/// The same drag in the scaled units of an engine with short arm L2 [m] under g [m/s^2].
Drag scaled(const Drag& drag, double L2, double g);

/// Where a flight ends. Positions are relative to the pivot, as in the shot: x > 0 behind it,
/// the target toward -x.
struct FlightEnd {
  double range = 0;  ///< -x at the end: from the pivot toward the target
  double time = 0;  ///< of flight
  Vec2 velocity;  ///< at the end
};

/// The flight from `position` with `velocity` until it comes down through the level `drop`
/// below the start (drop 0: back at the release height, Denny's range), under gravity g and
/// the drag, in the units of both. nullopt when it never comes down there (it climbs past the
/// time limit), the integrator fails, or the flight needs 20 times the work of an ordinary one
/// (a drag so strong that the equations turn stiff: an air of 10^4 kg/m^3 with Cd 100, say). With `path`, the flight's positions at `path_points`
/// equal steps of time from the start to the end are appended to it (for pictures).
std::optional<FlightEnd> fly(Vec2 position, Vec2 velocity, double drop, const Drag& drag, double g, std::vector<Vec2>* path = nullptr,
                             int path_points = 101);

/// How a flight's start moves with a parameter (a release's time): the derivatives of its
/// position, its velocity and its drop, in the flight's units.
struct FlightTangent {
  Vec2 position, velocity;
  double drop = 0;
};

/// Where the flight of fly(position, velocity, drop, drag, g) ends, its range (-x, as
/// FlightEnd's), and the rate at which that changes as the start moves along `tangent`: the
/// flight's sensitivities (its variational equations) integrated beside it, the end's time moved
/// with the level. The range is its own integration's (of eight equations, whose steps differ
/// from fly's by round-off), and the tangent's position.y is not read: the flight's heights are
/// taken from its start, so a change of the start's height is a change of `drop`. nullopt where
/// fly's is.
struct RangeRate {
  double range = 0, rate = 0;
};
std::optional<RangeRate> range_rate(Vec2 position, Vec2 velocity, double drop, const FlightTangent& tangent, const Drag& drag, double g);

/// "air (Cd 0.47, air 1.2 kg/m3, a sphere of 2500 kg/m3, d = 0.43 m, no wind)" for outputs; the
/// diameter only for a mass > 0.
/// Which of an air's values a Monte Carlo run draws from a spread: described as drawn, not as the
/// value of its first sample. `projectile`: the sphere's density, which follows its given
/// diameter and its mass where either is drawn (or chosen, by a completion).
struct AirDrawn {
  bool cd = false, density = false, wind = false, projectile = false;
};
std::string describe_air(const Air& air, double mass, AirDrawn drawn = {});

}  // namespace trebuchet
