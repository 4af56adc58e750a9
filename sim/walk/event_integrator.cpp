#include "sim/walk/event_integrator.hpp"

#include <algorithm>

namespace gaitopt::sim {
namespace {

/// The first event with g <= 0 whose value was > 0 before, or -1.
int firedEvent(const Eigen::VectorXd& before, const Eigen::VectorXd& after) {
  for (int i = 0; i < after.size(); ++i)
    if (before(i) > 0 && after(i) <= 0) return i;
  return -1;
}

}  // namespace

Eigen::VectorXd rk4Step(const Rhs& f, double t, const Eigen::VectorXd& x, double h) {
  const Eigen::VectorXd k1 = f(t, x);
  const Eigen::VectorXd k2 = f(t + h / 2, x + h / 2 * k1);
  const Eigen::VectorXd k3 = f(t + h / 2, x + h / 2 * k2);
  const Eigen::VectorXd k4 = f(t + h, x + h * k3);
  return x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
}

EventIntegration integrateToEvent(const Rhs& f, const Events& g, double t0,
                                  const Eigen::VectorXd& x0, double t_end,
                                  const EventIntegratorOptions& o, const StepObserver& observe,
                                  const StepCheck& check) {
  double t = t0;
  Eigen::VectorXd x = x0, g_now = g(t0, x0);
  // The step to (t_next, x_next) refused by the check: "" when it may be taken.
  const auto refused = [&](double t_next, const Eigen::VectorXd& x_next) {
    return check ? check(t, x, t_next, x_next) : std::string();
  };
  // A remainder below the event tolerance counts as arrived (no endless sliver steps).
  while (t_end - t > o.time_tolerance) {
    const double h = std::min(o.step, t_end - t);
    const Eigen::VectorXd x_next = rk4Step(f, t, x, h);
    const Eigen::VectorXd g_next = g(t + h, x_next);
    if (firedEvent(g_now, g_next) < 0) {
      if (std::string why = refused(t + h, x_next); !why.empty()) return {t, x, -1, why};
      t += h;
      x = x_next;
      g_now = g_next;
      if (observe) observe(t, x);
      continue;
    }
    // Bisection on the step length: [lo, hi] brackets the first crossing.
    double lo = 0, hi = h;
    while (hi - lo > o.time_tolerance) {
      const double mid = (lo + hi) / 2;
      if (firedEvent(g_now, g(t + mid, rk4Step(f, t, x, mid))) >= 0)
        hi = mid;
      else
        lo = mid;
    }
    EventIntegration end{t + hi, rk4Step(f, t, x, hi), -1, ""};
    // A step that blew up fires events with its garbage (a hip 4 km below the ground), and the
    // bisection then ends on the blow-up, not on an event of the walk.
    if (std::string why = refused(end.t, end.x); !why.empty()) return {t, x, -1, why};
    end.event = firedEvent(g_now, g(end.t, end.x));
    if (observe) observe(end.t, end.x);
    return end;
  }
  return {t, x, -1, ""};
}

}  // namespace gaitopt::sim
