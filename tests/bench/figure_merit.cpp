// fig:Merit_Ms remade (issue 13, section 6): Q/Q_max for 10^3 random designs (l, l4, mu_b) around
// the optimum for (240 m, 26 kJ), theta_i = 30 deg, F = 1, each fitted to that capacity, in a
// wide box and a narrow one, projected on l, l4 and mu_b. A quadratic form fitted to the narrow
// box (Eigen, least squares) gives the principal axes of Q's curvature (SelfAdjointEigenSolver);
// section 6 says the axis of largest curvature lies very close to l4. The coordinates are
// relative, u = design/optimum - 1, so that no parameter's unit weighs in the curvature.
// Usage: figure-merit OUTDIR   (writes OUTDIR/merit.gp and its data; prints the axes)
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "trebuchet/capacity_fit.hpp"
#include "trebuchet/error.hpp"
#include "trebuchet/optimizer.hpp"
#include "trebuchet/parallel.hpp"

using namespace trebuchet;

namespace {

struct Sample {
  double u[3];  // relative offsets of l, l4, mu_b from the optimum
  double q = 0;  // Q/Q_max; 0: no design delivers the capacity
};

std::vector<Sample> sample_box(const ScaledDesign& best, const Capacity& capacity, double Q_max, const double half_width[3], unsigned seed) {
  std::mt19937_64 random(seed);
  std::vector<Sample> samples(1000);
  for (Sample& s : samples)
    for (int k = 0; k < 3; ++k) s.u[k] = std::uniform_real_distribution<double>(-half_width[k], half_width[k])(random);
  for_each_index(samples.size(), 2, [&](std::size_t i) {
    ScaledDesign d = best;
    d.l *= 1 + samples[i].u[0], d.l4 *= 1 + samples[i].u[1], d.mu_b *= 1 + samples[i].u[2];
    try {
      samples[i].q = fit_capacity(d, capacity, Material{}, ShotSettings{}).verification.Q / Q_max;
    } catch (const Error&) {
      samples[i].q = 0;
    }
  });
  return samples;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: figure-merit OUTDIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  OptimizeRequest request;
  request.capacity = {240, 26e3};
  request.F = 1;
  const Optimum best = best_optimum(optimize(request));
  const ScaledDesign& d = best.fit.design;
  const double wide[3] = {0.4, 0.3, 0.6}, narrow[3] = {0.05, 0.03, 0.08};
  const std::vector<Sample> wide_samples = sample_box(d, request.capacity, best.objective, wide, 1);
  const std::vector<Sample> narrow_samples = sample_box(d, request.capacity, best.objective, narrow, 2);

  // Q/Q_max = c + g.u + u^T A u / 2 over the narrow box: ten coefficients by least squares.
  std::vector<const Sample*> used;
  for (const Sample& s : narrow_samples)
    if (s.q > 0) used.push_back(&s);
  Eigen::MatrixXd basis(used.size(), 10);
  Eigen::VectorXd values(used.size());
  for (std::size_t i = 0; i < used.size(); ++i) {
    const double* u = used[i]->u;
    basis.row(i) << 1, u[0], u[1], u[2], u[0] * u[0] / 2, u[1] * u[1] / 2, u[2] * u[2] / 2, u[0] * u[1], u[0] * u[2], u[1] * u[2];
    values(i) = used[i]->q;
  }
  const Eigen::VectorXd c = basis.colPivHouseholderQr().solve(values);
  Eigen::Matrix3d A;
  A << c(4), c(7), c(8), c(7), c(5), c(9), c(8), c(9), c(6);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(A);
  // The most negative eigenvalue is the direction Q falls fastest in.
  const Eigen::Vector3d steepest = axes.eigenvectors().col(0);
  const double angle_to_l4 = std::acos(std::min(1.0, std::abs(steepest(1)))) * 180 / M_PI;
  const double residual = std::sqrt((basis * c - values).squaredNorm() / used.size());
  std::printf("optimum for (240 m, 26 kJ), theta_i 30 deg, F 1: l %.4f, l4 %.4f, mu_b %.5f, Q %.4f %%\n", d.l, d.l4, d.mu_b, 100 * best.objective);
  std::printf("quadratic form over the narrow box (%zu designs, rms residual %.1e of Q_max):\n", used.size(), residual);
  for (int k = 0; k < 3; ++k)
    std::printf("  curvature %.3g along (l, l4, mu_b) = (%+.3f, %+.3f, %+.3f)\n", axes.eigenvalues()(k), axes.eigenvectors()(0, k),
                axes.eigenvectors()(1, k), axes.eigenvectors()(2, k));
  std::printf("the axis of largest curvature is %.1f deg from l4\n", angle_to_l4);

  // The data and the script: upper row the narrow box, lower row the wide one (as the paper).
  for (const auto& [name, samples] : {std::pair<const char*, const std::vector<Sample>*>{"merit_narrow.dat", &narrow_samples},
                                      std::pair<const char*, const std::vector<Sample>*>{"merit_wide.dat", &wide_samples}}) {
    std::ofstream out(dir + "/" + name);
    for (const Sample& s : *samples)
      if (s.q > 0) out << d.l * (1 + s.u[0]) << " " << d.l4 * (1 + s.u[1]) << " " << d.mu_b * (1 + s.u[2]) << " " << 100 * s.q << "\n";
  }
  std::ofstream gp(dir + "/merit.gp");
  gp << "# Made by figure-merit (tests/bench/figure_merit.cpp) for scripts/figures.sh.\nset encoding utf8\n"
     << "set terminal svg size 1100,750 dynamic font 'sans,12'\nset output '" << dir << "/merit.svg'\nset grid\nunset key\n"
     << "set multiplot layout 2,3 title \"fig:Merit_Ms: Q/Q_max of 10^3 designs fitted to (240 m, 26 kJ), θi = 30°, F = 1\\n"
     << "upper: a narrow box about the optimum; lower: a wide one. The axis of largest curvature is " << std::lround(angle_to_l4 * 10) / 10.0
     << "° from l_4\" noenhanced\n";
  const char* labels[3] = {"l = L_1/L_2", "l_4 = L_4/L_1", "μ_b = m_b/M"};
  for (const char* file : {"merit_narrow.dat", "merit_wide.dat"})
    for (int k = 0; k < 3; ++k)
      gp << (k == 2 ? "set xtics rotate by -30\n" : "set xtics norotate\n") << "set xlabel '" << labels[k] << "'\nset ylabel 'Q/Q_{max} [%]'\nplot '"
         << dir << "/" << file << "' using " << k + 1 << ":4 with points pt 7 ps 0.3 lc rgb '#1f5fbf'\n";
  gp << "unset multiplot\n";
}
