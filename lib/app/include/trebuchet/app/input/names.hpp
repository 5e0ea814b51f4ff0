// The names by which users and files choose the library's options: the release criterion
// (--quality, and "quality" in sweep parts), the machine (--machine) and the stepper (--stepper). Kept apart from the
// physics, which knows only the enums.
#pragma once

#include <string>
#include <string_view>

#include "trebuchet/design.hpp"
#include "trebuchet/integrator.hpp"
#include "trebuchet/quality.hpp"
#include "trebuchet/app/input/units.hpp"

namespace trebuchet {

/// "Q", "eps" or "range".
std::string release_name(Release release);

/// "time", "velocity_angle" or "pin_angle": how a given release is set.
std::string release_by_name(ReleaseBy by);

/// The release criterion of a name; Error(usage) names `option`, the text and the choices.
Release parse_release(std::string_view name, std::string_view option);

/// Whether the range runs from the release point: "pivot" (the paper's) or "release" (Denny's);
/// Error(usage) names `option`, the text and the choices.
bool parse_range_from(std::string_view name, std::string_view option);

/// "hinged", "fixed" or "floating-arm" (design.hpp, MachineKind).
std::string machine_name(MachineKind machine);

/// The machine in words, for titles: "engine" for the paper's, "fixed-counterweight engine",
/// "floating-arm engine".
std::string machine_words(MachineKind machine);

/// "hinged, fixed or floating-arm", for messages and help.
std::string machine_names();

/// The machine of a name ("floating_arm" too); Error(usage) names `option`, the text and the
/// choices, and says so of the whipper, which is not built yet.
MachineKind parse_machine(std::string_view name, std::string_view option);

/// A contest's objective: true for "eps" (the efficiency), false for "range"; Error(usage)
/// names `option`, the text and the choices.
bool parse_efficiency_objective(std::string_view name, std::string_view option);

/// "si" or "imperial"; Error(usage) names `option` and the choices.
UnitSystem parse_unit_system(std::string_view name, std::string_view option);

/// "rk8pd", ...: GSL's own names of its odeiv2 steppers.
std::string stepper_name(Stepper stepper);

/// "rk2, rk4, ... or msbdf", for messages and help.
std::string stepper_names();

/// The stepper of a name; Error(usage) names `option`, the text and the choices.
Stepper parse_stepper(std::string_view name, std::string_view option);

}  // namespace trebuchet
