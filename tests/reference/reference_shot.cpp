#include "reference_shot.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

namespace reference {
namespace {

using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
using Vector6 = std::array<double, 6>;  // theta, psi, phi, then their rates
constexpr int force_count = 4;  // F_S_perp, |F_R|, F_Rh, -F_Rh
using Forces = std::array<double, force_count>;

// A point of the engine as a sum of pendulum arms, each length (sin a, -cos a) with
// a = q[angle] + offset: it hangs straight down at a = 0.
struct Arm {
  int angle;
  double length, offset;
};

struct Params {
  double l, l4, L, mu, mu_b, inertia, theta_i, energy_drop;
  std::array<Arm, 2> counterweight, projectile;
  std::array<Arm, 1> beam_centre;
};

Params params_of(const Design& d) {
  Params p;
  p.l = d.l, p.l4 = d.l4, p.mu = d.mu, p.mu_b = d.mu_b;
  p.theta_i = d.theta_i_deg * M_PI / 180;
  p.L = d.F * d.l * std::cos(p.theta_i) - 1;  // L2 + L3 = F H with H = L1 cos theta_i
  // A uniform beam from the hinge (-1) to the spigot (l), mass mu_b, turning about the pivot.
  p.inertia = d.mu_b / (d.l + 1) * (d.l * d.l * d.l + 1) / 3;
  // The counterweight falls by (1 + cos theta_i) L2 in all, the beam's centre, (l - 1)/2 out
  // on the long arm, rises by (l - 1)/2 (1 + cos theta_i): eq:DU.
  p.energy_drop = (1 - d.mu_b * (d.l - 1) / 2) * (1 + std::cos(p.theta_i));
  // theta: the long arm from the downward vertical; the hinge sits opposite, 1 from the pivot.
  p.counterweight = {{{0, -1, 0}, {1, p.L, 0}}};
  // The sling leaves the spigot along -(cos phi, sin phi): horizontal, toward the target, at rest.
  p.projectile = {{{0, d.l, 0}, {2, d.l * d.l4, -M_PI / 2}}};
  p.beam_centre = {{{0, (d.l - 1) / 2, 0}}};
  return p;
}

template <class S>
using Vec2 = Eigen::Matrix<S, 2, 1>;

template <class S>
struct Point {
  Vec2<S> position, velocity;
  Vec2<S> bias;  // its acceleration when every angular acceleration is zero
  Eigen::Matrix<S, 2, 3> jacobian;  // d position / d (theta, psi, phi)
};

template <class S, std::size_t N>
Point<S> point_of(const std::array<Arm, N>& arms, const S* y) {
  Point<S> out;
  out.position.setZero(), out.bias.setZero(), out.jacobian.setZero();
  for (const Arm& arm : arms) {
    using std::cos;
    using std::sin;
    const S a = y[arm.angle] + arm.offset, rate = y[3 + arm.angle];
    const Vec2<S> along(sin(a), -cos(a)), turning(cos(a), sin(a));
    out.position += arm.length * along;
    out.jacobian.col(arm.angle) += arm.length * turning;
    out.bias -= arm.length * rate * rate * along;
  }
  const Eigen::Matrix<S, 3, 1> rates(y[3], y[4], y[5]);
  out.velocity = out.jacobian * rates;
  return out;
}

template <class S>
struct Motion {
  Eigen::Matrix<S, 3, 1> acceleration;  // theta'', psi'', phi''
  S normal;  // the trough's push on the projectile (phase I)
  std::array<S, force_count> forces;
  Point<S> projectile;
};

// Lagrange's equations for point masses at positions r(q) and the beam turning about the
// pivot: (sum m J^T J + I_P) q'' = sum m J^T (g - J' q'). In the trough the projectile's height
// is held by the multiplier, the normal force N: the rows [J_y, 0] (q'', N) = -J'_y q'.
template <class S>
Motion<S> motion(const Params& p, bool trough, const S* y) {
  const Point<S> cw = point_of(p.counterweight, y), pr = point_of(p.projectile, y), cm = point_of(p.beam_centre, y);
  const Vec2<S> up(S(0), S(1));
  Eigen::Matrix<S, 3, 3> mass = cw.jacobian.transpose() * cw.jacobian + p.mu * pr.jacobian.transpose() * pr.jacobian;
  mass(0, 0) += p.inertia;
  const Eigen::Matrix<S, 3, 1> generalised = -cw.jacobian.transpose() * (up + cw.bias) - p.mu * pr.jacobian.transpose() * (up + pr.bias) -
      p.mu_b * cm.jacobian.transpose() * up;
  Motion<S> m;
  m.projectile = pr;
  if (trough) {
    Eigen::Matrix<S, 4, 4> system;
    system.setZero();
    system.template topLeftCorner<3, 3>() = mass;
    system.template block<3, 1>(0, 3) = -pr.jacobian.row(1).transpose();
    system.template block<1, 3>(3, 0) = pr.jacobian.row(1);
    Eigen::Matrix<S, 4, 1> rhs;
    rhs << generalised, -pr.bias(1);
    const Eigen::Matrix<S, 4, 1> x = system.partialPivLu().solve(rhs);
    m.acceleration = x.template head<3>();
    m.normal = x(3);
  } else {
    m.acceleration = mass.partialPivLu().solve(generalised);
    m.normal = S(0);
  }
  const Vec2<S> a_cw = cw.jacobian * m.acceleration + cw.bias, a_pr = pr.jacobian * m.acceleration + pr.bias,
                a_cm = cm.jacobian * m.acceleration + cm.bias;
  // Newton for the projectile: the sling's pull is what weight and trough leave of mu a.
  const Vec2<S> sling = p.mu * (a_pr + up) - m.normal * up;
  using std::cos;
  using std::sin;
  const Vec2<S> spigot_turning(cos(y[0]), sin(y[0]));
  // Newton for the whole engine: the frame's push at the pivot, weight and trough give sum m a.
  const Vec2<S> reaction = a_cw + p.mu * a_pr + p.mu_b * a_cm + (1 + p.mu + p.mu_b) * up - m.normal * up;
  m.forces = {sling.dot(spigot_turning), reaction.norm(), reaction(0), -reaction(0)};
  return m;
}

// eq:Q at a state with the running extremes of eq:F; -infinity where the projectile would not
// fly toward the target (-x) from above the base.
template <class S>
S quality(const Params& p, const Point<S>& pr, const std::array<S, force_count>& extremes) {
  using std::pow;
  using std::sqrt;
  const S height = p.l * std::cos(p.theta_i) + pr.position(1);
  if (!(pr.velocity(0) < 0 && height >= 0)) return S(-std::numeric_limits<double>::infinity());
  const S flight = pr.velocity(1) + sqrt(pr.velocity(1) * pr.velocity(1) + 2 * height);
  const S rho = -(pr.position(0) + pr.velocity(0) * flight);
  const S eps = p.mu * (pr.velocity.squaredNorm() / 2 + height) / p.energy_drop;
  const S sling = extremes[0] / p.mu;
  const S factor = pow(sling * sling * extremes[1] * (extremes[2] + extremes[3]), 0.25);
  return rho / p.l * p.mu * eps / factor;
}

int equations(double, const double y[], double dydt[], void* params) {
  const auto* flow = static_cast<const std::pair<const Params*, bool>*>(params);
  const Motion<double> m = motion(*flow->first, flow->second, y);
  for (int i = 0; i < 3; ++i) dydt[i] = y[3 + i], dydt[3 + i] = m.acceleration(i);
  return GSL_SUCCESS;
}

using Driver = std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)>;

// One phase, integrated by rk8pd at rtol 1e-14: a grid walk, and evaluations anew from a stored state.
class Flow {
 public:
  Flow(const Params& p, bool trough)
      : context_(&p, trough),
        system_{equations, nullptr, 6, &context_},
        walk_(make(), gsl_odeiv2_driver_free),
        jump_(make(), gsl_odeiv2_driver_free) {}
  void walk(double& t, Vector6& y, double t1) { apply(walk_.get(), t, y, t1); }
  Vector6 at(double t0, Vector6 y, double t1) {
    if (t1 <= t0) return y;
    gsl_odeiv2_driver_reset_hstart(jump_.get(), t1 - t0);
    apply(jump_.get(), t0, y, t1);
    return y;
  }
  Motion<double> motion_at(const Vector6& y) const { return motion(*context_.first, context_.second, y.data()); }
  Vector6 rates(const Vector6& y) {
    Vector6 dy;
    equations(0, y.data(), dy.data(), &context_);
    return dy;
  }

 private:
  gsl_odeiv2_driver* make() { return gsl_odeiv2_driver_alloc_y_new(&system_, gsl_odeiv2_step_rk8pd, 1e-4, 1e-15, 1e-14); }
  static void apply(gsl_odeiv2_driver* d, double& t, Vector6& y, double t1) {
    if (gsl_odeiv2_driver_apply(d, &t, t1, y.data()) != GSL_SUCCESS) throw std::runtime_error("reference: integrator failure");
  }
  std::pair<const Params*, bool> context_;
  gsl_odeiv2_system system_;
  Driver walk_, jump_;
};

struct Sample {
  double t;
  Vector6 y;
  Forces f;
};

// The grid spacing (scaled time) and the bisection depth.
constexpr double grid = 2e-3;
constexpr int bisections = 80;

class Reference {
 public:
  explicit Reference(const Design& d) : p_(params_of(d)), trough_(p_, true), lifted_(p_, false) {}

  // The motion up to where Q has fallen to half its best, and the running extremes of eq:F.
  void run() {
    run_phase_one();
    run_phase_two();
    refine_peaks();
    build_running();
  }

 private:
  Sample sample(Flow& flow, double t, const Vector6& y) const {
    const Motion<double> m = flow.motion_at(y);
    return {t, y, m.forces};
  }

  // Phase I to lift-off, where the trough's push N turns negative: bisection on N.
  void run_phase_one() {
    double t = 0;
    Vector6 y{p_.theta_i, 0, 0, 0, 0, 0};
    one_.push_back(sample(trough_, t, y));
    while (true) {
      double t1 = t;
      Vector6 y1 = y;
      trough_.walk(t1, y1, t + grid);
      if (trough_.motion_at(y1).normal <= 0) {
        double a = t, b = t1;
        for (int k = 0; k < bisections; ++k) {
          const double mid = (a + b) / 2;
          (trough_.motion_at(trough_.at(t, y, mid)).normal <= 0 ? b : a) = mid;
        }
        t_liftoff_ = b;
        one_.push_back(sample(trough_, b, trough_.at(t, y, b)));
        return;
      }
      t = t1, y = y1;
      one_.push_back(sample(trough_, t, y));
      if (y[0] > M_PI || t > 200) throw std::runtime_error("reference: no lift-off");
    }
  }

  // Phase II on the grid until Q (with the sampled extremes) has fallen to half its best.
  void run_phase_two() {
    double t = t_liftoff_;
    Vector6 y = one_.back().y;
    two_.push_back(sample(lifted_, t, y));
    Forces extremes{};
    for (const Sample& s : one_) grow(extremes, s.f);
    double best = -1;
    while (true) {
      lifted_.walk(t, y, t + grid);
      two_.push_back(sample(lifted_, t, y));
      grow(extremes, two_.back().f);
      const double q = quality(p_, lifted_.motion_at(y).projectile, extremes);
      best = std::max(best, q);
      if ((best > 0 && q < best / 2) || y[0] > p_.theta_i + 2 * M_PI || t > 200) break;
    }
    if (!(best > 0)) throw std::runtime_error("reference: no forward release");
    for (const Sample& s : one_) timeline_.push_back({s.t, s.f});
    for (std::size_t i = 1; i < two_.size(); ++i) timeline_.push_back({two_[i].t, two_[i].f});
  }

  static void grow(Forces& extremes, const Forces& f) {
    for (int k = 0; k < force_count; ++k) extremes[k] = std::max(extremes[k], f[k]);
  }

  // The exact state at t, integrated anew from the last grid sample at or before it.
  Vector6 state_at(double t) {
    std::vector<Sample>& samples = t <= t_liftoff_ ? one_ : two_;
    Flow& flow = t <= t_liftoff_ ? trough_ : lifted_;
    auto after = std::upper_bound(samples.begin(), samples.end(), t, [](double v, const Sample& s) { return v < s.t; });
    const Sample& base = *(after == samples.begin() ? after : after - 1);
    return flow.at(base.t, base.y, t);
  }
  Forces forces_at(double t) {
    Flow& flow = t <= t_liftoff_ ? trough_ : lifted_;
    return flow.motion_at(state_at(t)).forces;
  }

  // Where a force peaks between grid points: golden section on the solution. A sampled peak
  // more than 1e-3 below the running maximum cannot raise it: between grid points 2e-3 apart a
  // force exceeds its samples by f'' grid^2/8, ~1e-5 of it for the fastest ringing seen (omega ~ 10).
  void refine_peaks() {
    Forces running{};
    for (std::size_t i = 1; i + 1 < timeline_.size(); ++i) {
      grow(running, timeline_[i - 1].f);
      for (int k = 0; k < force_count; ++k) {
        const double before = timeline_[i - 1].f[k], here = timeline_[i].f[k], after = timeline_[i + 1].f[k];
        if (!(here > before && here >= after && here > (1 - 1e-3) * running[k])) continue;
        double a = timeline_[i - 1].t, b = timeline_[i + 1].t;
        const double golden = (std::sqrt(5.0) - 1) / 2;
        double x1 = b - golden * (b - a), x2 = a + golden * (b - a);
        double f1 = forces_at(x1)[k], f2 = forces_at(x2)[k];
        while (b - a > 1e-10) {
          if (f1 < f2) {
            a = x1, x1 = x2, f1 = f2, x2 = a + golden * (b - a), f2 = forces_at(x2)[k];
          } else {
            b = x2, x2 = x1, f2 = f1, x1 = b - golden * (b - a), f1 = forces_at(x1)[k];
          }
        }
        const double t_peak = f1 > f2 ? x1 : x2;
        peaks_.push_back({t_peak, k, std::max(f1, f2)});
      }
    }
    std::sort(peaks_.begin(), peaks_.end(), [](const Peak& x, const Peak& y) { return x.t < y.t; });
  }

  // The running maxima of the forces over the timeline and the refined peaks, in time order:
  // running_[i] holds the maxima over every mark up to and including the i-th.
  void build_running() {
    std::vector<Mark> marks(timeline_);
    for (const Peak& peak : peaks_) {
      Forces f{};
      f[peak.force] = peak.value;
      marks.push_back({peak.t, f});
    }
    std::stable_sort(marks.begin(), marks.end(), [](const Mark& x, const Mark& y) { return x.t < y.t; });
    Forces running{};  // 0: the engine at rest before the shot
    for (const Mark& mark : marks) {
      grow(running, mark.f);
      running_.push_back({mark.t, running});
    }
  }

  // The running maximum of force k over [0, t]: 0 (the engine at rest before the shot), the
  // grid samples and the refined peaks up to t, and the force at t itself.
  double extreme_at(int k, double t, double now) const {
    const auto after = std::upper_bound(running_.begin(), running_.end(), t, [](double v, const Mark& m) { return v < m.t; });
    return std::max({0.0, now, after == running_.begin() ? 0.0 : (after - 1)->f[k]});
  }

  struct Evaluation {
    Vector6 y;
    Motion<double> m;
    std::array<double, force_count> extremes;
    double q;
  };
  Evaluation evaluate(double t) {
    Evaluation e{state_at(t), {}, {}, 0};
    e.m = lifted_.motion_at(e.y);
    for (int k = 0; k < force_count; ++k) e.extremes[k] = extreme_at(k, t, e.m.forces[k]);
    e.q = quality(p_, e.m.projectile, e.extremes);
    return e;
  }

  // dQ/dt on a smooth piece, by automatic differentiation along the flow: a growing extreme
  // follows its force, the others are constant.
  double slope_at(double t) {
    const Evaluation e = evaluate(t);
    const Vector6 rates = lifted_.rates(e.y);
    std::array<AD, 6> y;
    for (int i = 0; i < 6; ++i) y[i] = AD(e.y[i], Eigen::Matrix<double, 1, 1>(rates[i]));
    const Motion<AD> m = motion(p_, false, y.data());
    std::array<AD, force_count> extremes;
    for (int k = 0; k < force_count; ++k)
      extremes[k] = e.m.forces[k] >= e.extremes[k] ? m.forces[k] : AD(e.extremes[k], Eigen::Matrix<double, 1, 1>(0.0));
    return quality(p_, m.projectile, extremes).derivatives()(0);
  }

 public:
  // The release, sought over the whole of phase II, independently of where any sample is
  // highest (issue 26): every onset of growth of a running extreme (a force below its extreme at
  // one grid point that passes it by the next, or at a refined peak between them; bisection on
  // force - extreme), and on each smooth piece between onsets every maximum where dQ/dt, scanned
  // at every grid point, falls through zero (bisection on its sign). The best candidate wins.
  Shot release() {
    std::vector<std::pair<double, int>> onsets;
    for (std::size_t j = 1; j < two_.size(); ++j) {
      const double a = two_[j - 1].t, b = two_[j].t;
      for (int k = 0; k < force_count; ++k) {
        const double start = extreme_at(k, a, 0);
        if (!(two_[j - 1].f[k] < start)) continue;
        double right = two_[j].f[k] > start ? b : -1;
        for (const Peak& peak : peaks_)
          if (peak.force == k && peak.t > a && peak.t <= b && peak.value > start) right = right < 0 ? peak.t : std::min(right, peak.t);
        if (right < 0) continue;
        double x = a, z = right;
        for (int n = 0; n < bisections; ++n) {
          const double mid = (x + z) / 2;
          (forces_at(mid)[k] > start ? z : x) = mid;
        }
        onsets.push_back({z, k});
      }
    }
    std::sort(onsets.begin(), onsets.end());
    std::vector<double> ends{t_liftoff_};
    for (const auto& onset : onsets) ends.push_back(onset.first);
    ends.push_back(two_.back().t);
    std::vector<double> candidates(ends);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
      const double a = ends[i], b = ends[i + 1];
      std::vector<double> scan{a + (b - a) * 1e-6};
      for (const Sample& s : two_)
        if (s.t > scan.front() && s.t < b - (b - a) * 1e-6) scan.push_back(s.t);
      scan.push_back(b - (b - a) * 1e-6);
      double previous = slope_at(scan.front());
      for (std::size_t j = 1; j < scan.size(); ++j) {
        const double sj = slope_at(scan[j]);
        if (previous > 0 && sj <= 0) {
          double x = scan[j - 1], z = scan[j];
          for (int n = 0; n < bisections; ++n) {
            const double mid = (x + z) / 2;
            (slope_at(mid) > 0 ? x : z) = mid;
          }
          candidates.push_back((x + z) / 2);
        }
        previous = sj;
      }
    }
    double t_release = t_liftoff_;
    Evaluation at = evaluate(t_liftoff_);
    for (double t : candidates) {
      const Evaluation e = evaluate(t);
      if (e.q > at.q) t_release = t, at = e;
    }
    Shot shot = figures(t_release, at);
    for (const auto& onset : onsets)
      if (onset.first == t_release) shot.onset = onset.second;
    return shot;
  }

  // The release where the projectile's velocity angle above the horizontal toward the target,
  // atan2(vy, -vx), falling, first reaches alpha after lift-off: the grid interval where it
  // passes alpha (unwrapped from one grid point to the next), then bisection on it.
  Shot release_at_velocity_angle(double alpha) {
    const auto angle_at = [&](double t, double near) {
      const Vec2<double> v = lifted_.motion_at(state_at(t)).projectile.velocity;
      return near + std::remainder(std::atan2(v(1), -v(0)) - near, 2 * M_PI);
    };
    double previous = angle_at(two_.front().t, M_PI / 2);
    for (std::size_t j = 1; j < two_.size(); ++j) {
      const double here = angle_at(two_[j].t, previous);
      if (previous > alpha && !(here > alpha)) {
        double x = two_[j - 1].t, z = two_[j].t;
        for (int n = 0; n < bisections; ++n) {
          const double mid = (x + z) / 2;
          (angle_at(mid, previous) > alpha ? x : z) = mid;
        }
        return figures(z, evaluate(z));
      }
      previous = here;
    }
    throw std::runtime_error("reference: the velocity angle is not reached before Q falls to half its best");
  }

 private:
  Shot figures(double t_release, const Evaluation& at) const {
    Shot shot{};
    shot.t_liftoff = t_liftoff_, shot.t_release = t_release;
    const Point<double>& pr = at.m.projectile;
    shot.height = p_.l * std::cos(p_.theta_i) + pr.position(1);
    shot.speed = pr.velocity.norm();
    const double flight = pr.velocity(1) + std::sqrt(pr.velocity(1) * pr.velocity(1) + 2 * shot.height);
    shot.rho = -(pr.position(0) + pr.velocity(0) * flight);
    shot.tau_e = p_.mu * (shot.speed * shot.speed / 2 + shot.height);
    shot.eps = shot.tau_e / p_.energy_drop;
    shot.Q = at.q;
    return shot;
  }

  struct Peak {
    double t;
    int force;
    double value;
  };
  struct Mark {
    double t;
    Forces f;
  };
  Params p_;
  Flow trough_, lifted_;
  std::vector<Sample> one_, two_;
  std::vector<Mark> timeline_, running_;
  std::vector<Peak> peaks_;
  double t_liftoff_ = 0;
};

}  // namespace

Shot shoot(const Design& design) {
  gsl_set_error_handler_off();
  Reference reference(design);
  reference.run();
  return reference.release();
}

Shot shoot_at_velocity_angle(const Design& design, double angle_deg) {
  gsl_set_error_handler_off();
  Reference reference(design);
  reference.run();
  return reference.release_at_velocity_angle(angle_deg * M_PI / 180);
}

}  // namespace reference
