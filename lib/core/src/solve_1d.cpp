#include "solve_1d.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <tuple>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {

Point parabola_vertex(Point a, Point b, Point c) {
  const double d0 = (b.f - a.f) / (b.x - a.x), d1 = (c.f - b.f) / (c.x - b.x);
  const double curvature = (d1 - d0) / (c.x - a.x);  // half the second derivative
  if (!(curvature < 0)) return b;
  const double slope_mid = d0 + curvature * (b.x - a.x);  // derivative at b
  return {b.x - slope_mid / (2 * curvature), b.f - slope_mid * slope_mid / (4 * curvature)};
}
namespace {

constexpr int max_iterations = 200;

gsl_function wrap(const std::function<double(double)>& f) {
  return {[](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
          const_cast<std::function<double(double)>*>(&f)};
}

// GSL solvers freed however the search ends, a throwing callback included.
using RootSolver = std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)>;

}  // namespace

std::optional<double> root_between(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel) {
  gsl_function g = wrap(f);
  const RootSolver solver(gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  if (gsl_root_fsolver_set(solver.get(), &g, lo, hi) != GSL_SUCCESS) return std::nullopt;  // no change of sign
  double root = hi;
  for (int k = 0; k < max_iterations; ++k) {
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
    root = gsl_root_fsolver_root(solver.get());
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()), epsabs, epsrel) != GSL_CONTINUE) break;
  }
  return root;
}

double newton_root(const std::function<std::pair<double, double>(double)>& fdf, double lo, double guess, double hi, double epsrel) {
  using Fdf = std::function<std::pair<double, double>(double)>;
  gsl_function_fdf g;
  g.f = [](double x, void* p) { return (*static_cast<const Fdf*>(p))(x).first; };
  g.df = [](double x, void* p) { return (*static_cast<const Fdf*>(p))(x).second; };
  g.fdf = [](double x, void* p, double* f, double* df) { std::tie(*f, *df) = (*static_cast<const Fdf*>(p))(x); };
  g.params = const_cast<Fdf*>(&fdf);
  const std::unique_ptr<gsl_root_fdfsolver, decltype(&gsl_root_fdfsolver_free)> solver(gsl_root_fdfsolver_alloc(gsl_root_fdfsolver_newton),
                                                                                       gsl_root_fdfsolver_free);
  double x = std::clamp(guess, lo, hi);
  if (gsl_root_fdfsolver_set(solver.get(), &g, x) == GSL_SUCCESS)
    for (int k = 0; k < 20; ++k) {
      const double before = x;
      if (gsl_root_fdfsolver_iterate(solver.get()) != GSL_SUCCESS) break;
      x = gsl_root_fdfsolver_root(solver.get());
      if (!(x >= lo && x <= hi)) break;
      if (gsl_root_test_delta(x, before, 0, epsrel) == GSL_SUCCESS) return x;
    }
  return find_root([&](double t) { return fdf(t).first; }, lo, hi, 0, epsrel);
}

double find_root(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel) {
  if (const auto root = root_between(f, lo, hi, epsabs, epsrel)) return *root;
  throw Error(ErrorKind::numerical,
              "a root search was given [" + format_number(lo) + ", " + format_number(hi) +
                  "], where the function does not change sign (an internal bracketing error)");
}

double peak_between(const std::function<double(double)>& f, double lo, double estimate, double hi, double slope_step, double epsabs) {
  const auto slope = [&](double x) { return f(x + slope_step) - f(x - slope_step); };
  const double inner_lo = lo + slope_step, inner_hi = hi - slope_step, near = (hi - lo) / 20;
  if (const auto root = root_between(slope, std::max(inner_lo, estimate - near), std::min(inner_hi, estimate + near), epsabs, 0)) return *root;
  return root_between(slope, inner_lo, inner_hi, epsabs, 0).value_or(estimate);
}

}  // namespace trebuchet
