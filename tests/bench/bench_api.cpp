// The native side of the browser page's benchmark (tests/web/bench.mjs): the median time of one
// request through trebuchet::api, the C++ the page calls, for the Alcalá la Vieja Ca design
// (150 m, 50 kg, theta_i 30 deg, F 2/3).
// Usage: bench-api [repeats]   prints: design_us shot_us shot_with_series_us
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "trebuchet/app/api/api.hpp"
#include "bench/timing.hpp"

using namespace trebuchet::bench;

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 301;
  const nlohmann::json request = {{"R", "150m"}, {"m", "50kg"}, {"theta_i_deg", 30}, {"F", "2/3"}};
  const nlohmann::json design = trebuchet::api::design(request);
  auto median_us = [&](auto work) {
    std::vector<double> times;
    for (int k = 0; k < repeats; ++k) {
      const auto start = Clock::now();
      work();
      times.push_back(1e6 * seconds_since(start));
    }
    return median(times);
  };
  const double design_us = median_us([&] { trebuchet::api::design(request); });
  const double shot_us = median_us([&] { trebuchet::api::shot({{"design", design}}); });
  const double series_us = median_us([&] { trebuchet::api::shot({{"design", design}, {"series", true}}); });
  std::printf("%.1f %.1f %.1f\n", design_us, shot_us, series_us);
}
