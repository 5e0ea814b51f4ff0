#include "solve_1d.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "trebuchet/error.hpp"
#include "trebuchet/format.hpp"

namespace trebuchet {
namespace {

constexpr int max_iterations = 200;

gsl_function wrap(const std::function<double(double)>& f) {
  return {[](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
          const_cast<std::function<double(double)>*>(&f)};
}

// GSL solvers freed however the search ends, a throwing callback included.
using RootSolver = std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)>;
using Minimizer = std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)>;

}  // namespace

double find_root(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel) {
  gsl_function g = wrap(f);
  const RootSolver solver(gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  if (gsl_root_fsolver_set(solver.get(), &g, lo, hi) != GSL_SUCCESS)
    throw Error(ErrorKind::numerical, "a root search was given [" + format_number(lo) + ", " + format_number(hi) +
                                          "], where the function does not change sign (an internal bracketing error)");
  double root = hi;
  for (int k = 0; k < max_iterations; ++k) {
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
    root = gsl_root_fsolver_root(solver.get());
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()), gsl_root_fsolver_x_upper(solver.get()), epsabs,
                               epsrel) != GSL_CONTINUE)
      break;
  }
  return root;
}

double find_maximum(const std::function<double(double)>& f, double lo, double guess, double hi, double epsabs) {
  const std::function<double(double)> negated = [&](double x) { return -f(x); };
  gsl_function g = wrap(negated);
  const Minimizer owner(gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent), gsl_min_fminimizer_free);
  gsl_min_fminimizer* minimizer = owner.get();
  double x = guess;
  if (gsl_min_fminimizer_set(minimizer, &g, guess, lo, hi) == GSL_SUCCESS) {
    // Values of f near a smooth maximum differ by round-off closer than ~sqrt(epsilon) |x|.
    const double resolution = 1e-8 * std::max(std::abs(lo), std::abs(hi));
    for (int k = 0; k < max_iterations; ++k) {
      gsl_min_fminimizer_iterate(minimizer);
      x = gsl_min_fminimizer_x_minimum(minimizer);
      if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(minimizer), gsl_min_fminimizer_x_upper(minimizer),
                                std::max(epsabs, resolution), 0) != GSL_CONTINUE)
        break;
    }
  }
  return x;
}

double find_argmax(const std::function<double(double)>& f, double lo, double guess, double hi, double slope_step,
                   double epsabs) {
  const auto slope = [&](double x) { return f(x + slope_step) - f(x - slope_step); };
  const double inner_lo = lo + slope_step, inner_hi = hi - slope_step;
  if (inner_lo < inner_hi && slope(inner_lo) > 0 && slope(inner_hi) < 0) return find_root(slope, inner_lo, inner_hi, epsabs, 0);
  return find_maximum(f, lo, guess, hi, epsabs);
}

}  // namespace trebuchet
