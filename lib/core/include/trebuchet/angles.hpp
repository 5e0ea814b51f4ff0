// Degrees to radians and back: the one conversion of angles in the library.
#pragma once

#include <cmath>

namespace trebuchet {

inline double radians(double degrees) { return degrees * M_PI / 180.0; }
inline double degrees(double radians) { return radians * 180 / M_PI; }

}  // namespace trebuchet
