// The cost of a given release against the optimal shot it reproduces, and of design in air
// (issue 35): for three engines, the median wall time of the optimal shot and of the same shot
// released by time, by velocity angle and by pin angle at the optimum's own values, with their
// ratios; then the median time of fit and optimize through standard air beside vacuum.
// Usage: bench-release [seconds per point]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "engines.hpp"
#include "timing.hpp"
#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/verification.hpp"

using namespace trebuchet;
using namespace trebuchet::bench;

int main(int argc, char** argv) {
  const double budget = argc > 1 ? std::atof(argv[1]) : 1.0;
  ShotSettings range;
  range.criterion.release = Release::range;
  const struct {
    const char* name;
    Engine engine;
    ShotSettings settings;
  } cases[] = {{"Ca, Q optimum", testing::alcala_ca(), ShotSettings{}},
               {"Denny, range optimum", testing::denny_standard(), range},
               {"laboratory engine, Q optimum", testing::laboratory_engine(), ShotSettings{}}};
  std::printf("engine,release,median_s,ratio_to_optimum\n");
  for (const auto& c : cases) {
    ShotSettings optimum = c.settings;
    optimum.loads = false;  // the shot alone, as searches and Monte Carlo samples run it
    const Verification v = verify_engine(c.engine, optimum);
    const double base = median_seconds([&] { verify_engine(c.engine, optimum); }, budget);
    std::printf("%s,optimum,%.4e,1\n", c.name, base);
    const std::pair<ReleaseBy, double> given[] = {
        {ReleaseBy::time, v.t_release}, {ReleaseBy::velocity_angle, v.A_deg}, {ReleaseBy::pin_angle, v.pin_angle_deg}};
    const char* names[] = {"time", "velocity_angle", "pin_angle"};
    for (int k = 0; k < 3; ++k) {
      ShotSettings s = optimum;
      s.release_at = SetRelease{given[k].first, given[k].second};
      const double seconds = median_seconds([&] { verify_engine(c.engine, s); }, budget);
      std::printf("%s,%s,%.4e,%.3f\n", c.name, names[k], seconds, seconds / base);
    }
  }
  // Design in air: fit (R = 150 m, T = 40 kJ from row Ca's shape) and optimize (R = 150 m, m = 50 kg).
  ShotSettings air;
  air.air = Air{};
  std::printf("\ndesign,medium,median_s\n");
  for (const auto& [medium, settings] : {std::pair{"vacuum", ShotSettings{}}, std::pair{"air", air}}) {
    const double fit = median_seconds([&] { fit_capacity(scaled_design(testing::alcala_ca()), {150, 40e3, 0}, Material{}, settings); }, budget);
    OptimizeRequest request;
    request.capacity = {150, 0, 0};
    request.projectile_mass = 50;
    request.settings = settings;
    const double optimize_s = median_seconds([&] { optimize(request); }, budget);
    std::printf("fit R 150 m T 40 kJ,%s,%.4e\noptimize R 150 m m 50 kg,%s,%.4e\n", medium, fit, medium, optimize_s);
  }
  return 0;
}
