// One-dimensional root finding with GSL's Brent method, and peaks as roots of a slope.
#pragma once

#include <functional>
#include <optional>
#include <utility>

namespace trebuchet {

/// A point of a function of one variable.
struct Point {
  double x, f;
};

/// The vertex of the parabola through three points (in increasing x) with the middle one highest:
/// where it peaks, and its value; the middle point when they are not concave.
Point parabola_vertex(Point a, Point b, Point c);

/// A root of f in [lo, hi], by Brent's method, when f(lo) and f(hi) differ in sign; stops when
/// the bracket is narrower than epsabs + epsrel |x| (gsl_root_test_interval).
std::optional<double> root_between(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel);

/// A root of f in [lo, hi] by Newton's method (GSL's fdfsolver) from `guess`, where `fdf` gives f
/// and its derivative at once and f changes sign over the bracket: stops when a step is below
/// epsrel |x|. Where a step leaves the bracket, or the iteration does not settle, Brent's method
/// on f over the bracket (root_between) finds it instead.
double newton_root(const std::function<std::pair<double, double>(double)>& fdf, double lo, double guess, double hi, double epsrel);

/// As root_between, where a change of sign is certain: Error(numerical) if there is none.
double find_root(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel);

/// Where f peaks in [lo, hi], near `estimate` (within a tenth of the bracket, say): the root of
/// the central difference f(x + slope_step) - f(x - slope_step), to epsabs, searched first
/// within (hi - lo)/20 of the estimate, then in the whole bracket; the estimate when the slope
/// does not change sign. The root is found to round-off, where comparing values near a smooth
/// maximum cannot place it closer than ~1e-8 relative; truncation moves it by O(slope_step^2).
double peak_between(const std::function<double(double)>& f, double lo, double estimate, double hi, double slope_step, double epsabs);

}  // namespace trebuchet
