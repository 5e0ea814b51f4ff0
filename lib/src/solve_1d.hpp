// One-dimensional root finding and maximisation with GSL's Brent methods.
#pragma once

#include <functional>

namespace trebuchet {

/// A root of f in [lo, hi], where f(lo) and f(hi) must differ in sign (Error(numerical) if not);
/// stops when the bracket is narrower than epsabs + epsrel |x| (gsl_root_test_interval).
double find_root(const std::function<double(double)>& f, double lo, double hi, double epsabs, double epsrel);

/// The maximum of f on [lo, hi] from an interior guess with f(guess) > f(lo), f(hi), by Brent's
/// minimiser on -f, to epsabs but no closer than 1e-8 |x|: near a smooth maximum, values of f
/// differ by round-off only. Good for the maximum's value. Returns the guess when GSL finds no
/// bracket (the maximum sits on it within round-off).
double find_maximum(const std::function<double(double)>& f, double lo, double guess, double hi, double epsabs);

/// Where the maximum lies, to epsabs: the root of the central difference
/// f(x + slope_step) - f(x - slope_step) when it changes sign across [lo + slope_step,
/// hi - slope_step] (a root is found to round-off), else find_maximum. Truncation moves the
/// root by O(slope_step^2), round-off by O(machine epsilon / slope_step), relative to f.
double find_argmax(const std::function<double(double)>& f, double lo, double guess, double hi, double slope_step,
                   double epsabs);

}  // namespace trebuchet
