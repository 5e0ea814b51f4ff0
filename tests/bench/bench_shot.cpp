// Work-precision of the verifier: for three designs, every GSL odeiv2 stepper the shot can use,
// at tolerances 1e-3 ... 1e-13, the median wall time of a verified shot and its error in R, T,
// eps and Q against a reference. Also the calculator and the optimizer as points, and the cost of a shot against
// the stiffness l. Writes CSV to stdout; scripts/work-precision.sh turns it into docs/ charts.
// Usage: bench-shot [seconds_per_point]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "trebuchet/calculator.hpp"
#include "trebuchet/capacity_fit.hpp"
#include "engines.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/app/input/names.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/verification.hpp"
#include "timing.hpp"

using namespace trebuchet;
using namespace trebuchet::bench;

namespace {

struct Design {
  std::string name;
  Engine engine;
  ReleaseCriterion criterion;
};

Design large_eff_17() {  // tab:Large_Eff l = 17, fitted to (450 m, 232 kJ), released at max eps
  ShotSettings settings;
  settings.criterion.release = Release::efficiency;
  const ScaledDesign shape{17, 0.673 / 0.800, 14.7 / 270000, 0, 30, 1};
  return {"large_eff_l17", fit_capacity(shape, {450, 232e3}, Material{}, settings).engine, settings.criterion};
}

ShotSettings settings_for(const Design& d, Stepper stepper, double tol) {
  ShotSettings s;
  s.criterion = d.criterion;
  s.integrator.stepper = stepper;
  s.integrator.rtol = tol;
  s.integrator.atol = tol / 10;
  s.integrator.max_energy_drift = 1;  // the chart shows the error itself; the monitor is tested elsewhere
  return s;
}

double relative(double value, double reference) { return std::abs(value / reference - 1); }

void work_precision(const Design& d, double budget) {
  const Verification ref = verify_engine(d.engine, settings_for(d, Stepper::rk8pd, 1e-13));
  const Verification check = verify_engine(d.engine, settings_for(d, Stepper::rkck, 1e-13));
  std::fprintf(stderr, "%s: reference rk8pd 1e-13, cross-check rkck 1e-13: R %.1e T %.1e eps %.1e Q %.1e\n", d.name.c_str(),
               relative(check.capacity.R, ref.capacity.R), relative(check.capacity.T, ref.capacity.T), relative(check.eps, ref.eps),
               relative(check.Q, ref.Q));
  std::printf("reference,%s,rkck,1e-13,,%.3e,%.3e,%.3e,%.3e,,cross-check\n", d.name.c_str(), relative(check.capacity.R, ref.capacity.R),
              relative(check.capacity.T, ref.capacity.T), relative(check.eps, ref.eps), relative(check.Q, ref.Q));
  // The defaults themselves (rtol = atol = 1e-11, off the grid below, where atol = rtol/10).
  ShotSettings defaults;
  defaults.criterion = d.criterion;
  const Verification v = verify_engine(d.engine, defaults);
  const double seconds = median_seconds([&] { verify_engine(d.engine, defaults); }, budget);
  std::printf("default,%s,rk8pd,default,%.4e,%.3e,%.3e,%.3e,%.3e,%.2e,\n", d.name.c_str(), seconds, relative(v.capacity.R, ref.capacity.R),
              relative(v.capacity.T, ref.capacity.T), relative(v.eps, ref.eps), relative(v.Q, ref.Q), v.energy_drift);
  for (Stepper stepper : all_steppers) {
    for (int e = 3; e <= 13; ++e) {
      const double tol = std::pow(10.0, -e);
      const ShotSettings s = settings_for(d, stepper, tol);
      try {
        const Verification v = verify_engine(d.engine, s);
        const double seconds = median_seconds([&] { verify_engine(d.engine, s); }, budget);
        std::printf("shot,%s,%s,%.0e,%.4e,%.3e,%.3e,%.3e,%.3e,%.2e,\n", d.name.c_str(), stepper_name(stepper).c_str(), tol, seconds,
                    relative(v.capacity.R, ref.capacity.R), relative(v.capacity.T, ref.capacity.T), relative(v.eps, ref.eps), relative(v.Q, ref.Q),
                    v.energy_drift);
      } catch (const Error& error) {
        std::string reason = error.what();
        reason = reason.substr(0, reason.find(';'));
        std::printf("shot,%s,%s,%.0e,,,,,,,%s\n", d.name.c_str(), stepper_name(stepper).c_str(), tol, reason.c_str());
      }
      std::fflush(stdout);
    }
  }
}

// The calculator as a point: its time per design, and its error as the deviation of the
// verified capacity and Q from what it predicted.
void calculator_point(const char* name, double R, double T, double budget) {
  DesignRequest request;
  request.first = {Quantity::R, R};
  request.second = {Quantity::T, T};
  const ScalingTable& table = builtin_scaling_table();
  const OptimalEngine design = design_optimal_engine(table, request);
  const double seconds = median_seconds(
                             [&] {
                               for (int k = 0; k < 1000; ++k) design_optimal_engine(table, request);
                             },
                             budget) /
      1000;
  const Verification v = verify_engine(design.engine, ShotSettings{});
  std::printf("calculator,%s,tab:CPNC,,%.4e,%.3e,%.3e,,,,\n", name, seconds, relative(v.capacity.R, R), relative(v.capacity.T, T));
}

// The ab-initio optimum as a point: the wall time of one optimisation for the capacity, and
// its error as the deviation of the verified capacity from the requested one.
void optimizer_point(const char* name, double R, double T, double F, double budget) {
  OptimizeRequest request;
  request.capacity = {R, T};
  request.F = F;
  const Optimum best = optimize(request).front();
  const double seconds = median_seconds([&] { optimize(request); }, budget);
  const Verification fresh = verify_engine(best.fit.engine, ShotSettings{});
  std::printf("optimizer,%s,nmsimplex2,,%.4e,%.3e,%.3e,,,%d,Q=%.5g\n", name, seconds, relative(fresh.capacity.R, R), relative(fresh.capacity.T, T),
              best.simulations, best.objective);
}

// Cost against stiffness: the small-l4 shape of tab:Large_Eff with l from 4 to 60, at default
// settings. Appendix B: the beam rings at omega = {L/(L+1) I_P}^(-1/2) (scaled).
void stiffness(double budget) {
  for (double l : {4.0, 6.0, 10.0, 17.0, 25.0, 35.0, 45.0, 60.0}) {
    ShotSettings s;
    s.criterion.release = Release::efficiency;
    const ScaledDesign e{l, 0.673 / 0.800, 14.7 / 270000, 3.85e-4, 30, 1};
    try {
      const ShotResult r = simulate_shot(e, s.criterion, s.integrator);
      const double seconds = median_seconds([&] { simulate_shot(e, s.criterion, s.integrator); }, budget);
      const double omega = 1 / std::sqrt(e.L() / (e.L() + 1) * e.beam_inertia());
      std::printf("stiffness,l=%g,rk8pd,default,%.4e,,,,,%ld,omega=%.4g t_release=%.4g\n", l, seconds, r.steps, omega, r.release.t);
    } catch (const Error& error) {
      std::printf("stiffness,l=%g,rk8pd,default,,,,,,,%s\n", l, error.what());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const double budget = argc > 1 ? std::atof(argv[1]) : 0.2;
  std::printf("kind,design,method,tolerance,seconds,err_R,err_T,err_eps,err_Q,energy_drift_or_steps,note\n");
  calculator_point("alcala_ca capacity 150m 40.45kJ", 150, 40454.8, budget);
  calculator_point("denny capacity 425m 224kJ", 425, 224e3, budget);
  optimizer_point("alcala_ca capacity 150m 40.45kJ", 150, 40454.8, 2.0 / 3, budget);
  optimizer_point("denny capacity 425m 224kJ", 425, 224e3, 2.0 / 3, budget);
  work_precision({"alcala_ca", testing::alcala_ca(), ReleaseCriterion{}}, budget);
  work_precision({"denny_standard", testing::denny_standard(), ReleaseCriterion{}}, budget);
  work_precision(large_eff_17(), budget);
  stiffness(budget);
}
