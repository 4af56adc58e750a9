#pragma once
/// @file event_integrator.hpp
/// Fixed-step classical Runge-Kutta (RK4) integration of xdot = f(t, x) that stops at the first
/// zero of any event function g_i(t, x) (an event fires when g_i goes from > 0 to <= 0). The
/// crossing is located by bisection on the length of the last step, to `time_tolerance`: the
/// switching time comes from root finding, not from the step size.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace gaitopt::sim {

using Rhs = std::function<Eigen::VectorXd(double t, const Eigen::VectorXd& x)>;
/// All event functions at once, one value per event.
using Events = std::function<Eigen::VectorXd(double t, const Eigen::VectorXd& x)>;
/// Called after every accepted step (and at the event), e.g. to log.
using StepObserver = std::function<void(double t, const Eigen::VectorXd& x)>;
/// Why the step from (t, x) to (t_next, x_next) must not be accepted, "" when it may: a step
/// that diverged, whose end state is garbage no event or log should see.
using StepCheck = std::function<std::string(double t, const Eigen::VectorXd& x, double t_next,
                                            const Eigen::VectorXd& x_next)>;

struct EventIntegration {
  double t = 0;
  Eigen::VectorXd x;
  int event = -1;  ///< index of the event that fired, -1 if t_end was reached first
  /// The check's reason when it refused a step; (t, x) is then the last accepted state.
  std::string failure;
};

struct EventIntegratorOptions {
  double step = 5e-4;             ///< RK4 step [s]
  double time_tolerance = 1e-10;  ///< event location [s]
};

/// Integrates from (t0, x0) until an event fires, t_end, or `check` refuses a step (the step
/// that ends at an event included; that step's end is then neither observed nor returned).
EventIntegration integrateToEvent(const Rhs& f, const Events& g, double t0,
                                  const Eigen::VectorXd& x0, double t_end,
                                  const EventIntegratorOptions& options,
                                  const StepObserver& observe = {}, const StepCheck& check = {});

/// One RK4 step of length h.
Eigen::VectorXd rk4Step(const Rhs& f, double t, const Eigen::VectorXd& x, double h);

}  // namespace gaitopt::sim
