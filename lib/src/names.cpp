#include "trebuchet/names.hpp"

#include "trebuchet/error.hpp"

namespace trebuchet {

std::string release_name(Release release) {
  switch (release) {
    case Release::quality: return "Q";
    case Release::efficiency: return "eps";
    case Release::range: return "range";
  }
  return "?";
}

Release parse_release(std::string_view name, std::string_view option) {
  for (Release r : {Release::quality, Release::efficiency, Release::range})
    if (name == release_name(r)) return r;
  throw Error(ErrorKind::usage, std::string(option) + ": '" + std::string(name) +
                                    "' is not a release criterion; use Q (eq:Q, eq:Q_n with --n), eps or range");
}

std::string stepper_name(Stepper stepper) {
  switch (stepper) {
    case Stepper::rk2: return "rk2";
    case Stepper::rk4: return "rk4";
    case Stepper::rkf45: return "rkf45";
    case Stepper::rkck: return "rkck";
    case Stepper::rk8pd: return "rk8pd";
    case Stepper::msadams: return "msadams";
    case Stepper::rk1imp: return "rk1imp";
    case Stepper::rk2imp: return "rk2imp";
    case Stepper::rk4imp: return "rk4imp";
    case Stepper::bsimp: return "bsimp";
    case Stepper::msbdf: return "msbdf";
  }
  return "?";
}

std::string stepper_names() {
  std::string list;
  for (std::size_t k = 0; k < all_steppers.size(); ++k)
    list += (k == 0 ? "" : k + 1 == all_steppers.size() ? " or " : ", ") + stepper_name(all_steppers[k]);
  return list;
}

Stepper parse_stepper(std::string_view name, std::string_view option) {
  for (Stepper s : all_steppers)
    if (name == stepper_name(s)) return s;
  throw Error(ErrorKind::usage, std::string(option) + ": '" + std::string(name) + "' is not a stepper; use " + stepper_names());
}

}  // namespace trebuchet
