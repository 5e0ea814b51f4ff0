// Designs the Alcala la Vieja engine (150 m, 50 kg stones) through the installed library and
// verifies it ab initio: prints the calculator's T and the shot's R.
#include <cstdio>

#include "trebuchet.hpp"

int main() {
  using namespace trebuchet;
  DesignRequest request;
  request.first = {Quantity::R, 150};
  request.second = {Quantity::m, 50};
  const OptimalEngine design = design_optimal_engine(builtin_scaling_table(), request);
  const Verification shot = verify_engine(design.engine, ShotSettings{});
  std::printf("T = %.1f kJ, R = %.1f m\n", design.capacity.T / 1e3, shot.capacity.R);
  return 0;
}
