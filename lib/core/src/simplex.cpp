#include "simplex.hpp"

#include <gsl/gsl_multimin.h>

#include <memory>

#include "gsl_errors.hpp"

namespace trebuchet {
namespace {

using Function = std::function<double(const std::vector<double>&)>;

double call(const gsl_vector* x, void* params) {
  std::vector<double> point(x->size);
  for (std::size_t k = 0; k < x->size; ++k) point[k] = gsl_vector_get(x, k);
  return (*static_cast<const Function*>(params))(point);
}

}  // namespace

int minimize_simplex(const Function& f, const std::vector<double>& x0, double step, double size, int max_iterations) {
  use_gsl_return_codes();
  const std::size_t n = x0.size();
  gsl_multimin_function function{call, n, const_cast<Function*>(&f)};
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> x(gsl_vector_alloc(n), gsl_vector_free), steps(gsl_vector_alloc(n), gsl_vector_free);
  for (std::size_t k = 0; k < n; ++k) gsl_vector_set(x.get(), k, x0[k]);
  gsl_vector_set_all(steps.get(), step);
  std::unique_ptr<gsl_multimin_fminimizer, decltype(&gsl_multimin_fminimizer_free)> minimizer(
      gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, n), gsl_multimin_fminimizer_free);
  gsl_multimin_fminimizer_set(minimizer.get(), &function, x.get(), steps.get());
  int iterations = 0;
  for (; iterations < max_iterations; ++iterations) {
    if (gsl_multimin_fminimizer_iterate(minimizer.get()) != GSL_SUCCESS) break;
    if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(minimizer.get()), size) == GSL_SUCCESS) break;
  }
  return iterations;
}

}  // namespace trebuchet
