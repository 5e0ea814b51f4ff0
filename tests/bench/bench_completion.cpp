// complete against its target (issue 21): at most 10 ms a completion, so that a Monte Carlo
// band of 1000 samples takes at most 5 s on two cores. For each attested subset, the median
// wall time of complete_engine() over repeated runs, its shots, and the Q and free values it
// finds (to compare one build with another). Prints CSV.
// Usage: bench-completion [seconds per case]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "timing.hpp"
#include "trebuchet/completion.hpp"

using namespace trebuchet;
using namespace trebuchet::bench;

namespace {

struct Case {
  std::string name;
  CompletionRequest request;
};

CompletionRequest attested(const Attested& a, Release release = Release::quality, bool air = false) {
  CompletionRequest request;
  request.attested = a;
  request.settings.criterion.release = release;
  if (air) request.settings.air = Air{};
  return request;
}

}  // namespace

int main(int argc, char** argv) {
  const double budget = argc > 1 ? std::atof(argv[1]) : 1.0;
  // Subsets a historian gives (docs/historians.md): a beam and a stone or a counterweight, the
  // sections and the counterweight, a pivot height, a sling; in air; the range with M and m.
  auto subset = [](auto set) {
    Attested a;
    set(a);
    return a;
  };
  const std::vector<Case> cases = {
      {"Lb m", attested(subset([](Attested& a) { a.Lb = 9.5, a.m = 50; }))},
      {"Lb M", attested(subset([](Attested& a) { a.Lb = 9.5, a.M = 5000; }))},
      {"L1 L2 M", attested(subset([](Attested& a) { a.L1 = 6, a.L2 = 1.5, a.M = 10000; }))},
      {"H m", attested(subset([](Attested& a) { a.H = 5, a.m = 60; }))},
      {"L4 M m", attested(subset([](Attested& a) { a.L4 = 5, a.M = 8000, a.m = 80; }))},
      {"Lb mb M theta 40", attested(subset([](Attested& a) { a.Lb = 12, a.M = 10000, a.mb = 1000, a.theta_i_deg = 40; }))},
      {"Lb m air", attested(subset([](Attested& a) { a.Lb = 9.5, a.m = 50; }), Release::quality, true)},
      {"Lb M m range", attested(subset([](Attested& a) { a.Lb = 9.5, a.M = 5000, a.m = 50; }), Release::range)},
  };
  std::printf("case,median_ms,shots,Q,L1_m,L2_m,L4_m,M_kg,m_kg\n");
  std::vector<double> all;
  for (const Case& c : cases) {
    Completion completion;
    const double seconds = median_seconds([&] { completion = complete_engine(c.request); }, budget);
    all.push_back(seconds);
    const Engine& e = completion.engine;
    std::printf("%s,%.3f,%d,%.10g,%.6g,%.6g,%.6g,%.6g,%.6g\n", c.name.c_str(), 1e3 * seconds, completion.simulations, completion.verification.Q, e.L1,
                e.L2, e.L4, e.M, e.m);
  }
  std::printf("# median of the cases' medians: %.3f ms\n", 1e3 * median(all));
}
