// Minimisation in a few dimensions with GSL's Nelder-Mead simplex (nmsimplex2), shared by the
// optimizer and the completion of attested engines.
#pragma once

#include <functional>
#include <vector>

namespace trebuchet {

/// Minimises f from x0 with initial steps `step` in every coordinate, until the simplex is
/// smaller than `size` (gsl_multimin_test_size) or after `max_iterations`. Returns the
/// iterations; f sees every point tried, so the caller keeps what it needs of the best.
int minimize_simplex(const std::function<double(const std::vector<double>&)>& f, const std::vector<double>& x0, double step, double size,
                     int max_iterations);

}  // namespace trebuchet
