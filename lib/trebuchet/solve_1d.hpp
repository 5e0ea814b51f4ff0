// One-dimensional root finding and maximisation with GSL's Brent methods.
#pragma once

#include <functional>

namespace trebuchet {

/// A root of f in [lo, hi], where f(lo) and f(hi) differ in sign; stops when the bracket is
/// narrower than epsabs + epsrel |x| (gsl_root_test_interval).
double find_root(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel);

/// The maximum of f on [lo, hi] from an interior guess with f(guess) > f(lo), f(hi); returns
/// the guess when GSL finds no such bracket (the maximum sits on it within round-off).
double find_maximum(const std::function<double(double)>& f, double lo, double guess, double hi, double epsabs);

}  // namespace trebuchet
