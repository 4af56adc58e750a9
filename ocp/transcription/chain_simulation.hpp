#pragma once
/// @file chain_simulation.hpp
/// Forward simulation of the chain in single support (D ddtheta + N = M^T tau(t), Mu 2.7) or
/// double support (the KKT solve of 2.11) with an adaptive 7(8) Runge-Kutta-Fehlberg integrator
/// from Boost.Odeint: the independent re-simulation that tests and benchmarks hold designed and
/// optimal gaits to. Depends on dynamics/ only; header-only so the library does not depend on
/// Boost (its users, tests and benchmarks, link Boost::boost).
#include <functional>
#include <utility>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::ocp {

/// Called at each requested time with the simulated state [rad, rad/s].
using ChainObserver = std::function<void(double t, const VecD& theta, const VecD& dtheta)>;

/// Integrates the chain from (theta0, dtheta0) under joint torques torque(t) [N m] (n), pinned at
/// B (dsp false) or at both tips (dsp true), reporting the state at each of `times` (increasing,
/// starting at the initial time). `tolerance` is odeint's absolute and relative error bound.
inline void simulateChain(const dynamics::Model& model, bool dsp, const VecD& theta0,
                          const VecD& dtheta0, const std::function<VecD(double)>& torque,
                          const std::vector<double>& times, double tolerance,
                          const ChainObserver& observe) {
  const int n = model.nLinks();
  using State = std::vector<double>;
  auto split = [n](const State& x) {
    return std::pair<VecD, VecD>(Eigen::Map<const Eigen::VectorXd>(x.data(), n),
                                 Eigen::Map<const Eigen::VectorXd>(x.data() + n, n));
  };
  auto rhs = [&](const State& x, State& dx, double t) {
    const auto [th, dth] = split(x);
    const VecD dd = dsp ? dynamics::dspForwardDynamics(model, th, dth, torque(t)).ddtheta
                        : dynamics::sspForwardDynamics(model, th, dth, torque(t));
    for (int i = 0; i < n; ++i) {
      dx[static_cast<size_t>(i)] = dth(i);
      dx[static_cast<size_t>(n + i)] = dd(i);
    }
  };
  State x(theta0.data(), theta0.data() + n);
  x.insert(x.end(), dtheta0.data(), dtheta0.data() + n);
  namespace ode = boost::numeric::odeint;
  ode::integrate_times(
      ode::make_controlled(tolerance, tolerance, ode::runge_kutta_fehlberg78<State>()), rhs, x,
      times, 1e-4, [&](const State& s, double t) {
        const auto [th, dth] = split(s);
        observe(t, th, dth);
      });
}

/// simulateChain in single support.
inline void simulateSsp(const dynamics::Model& model, const VecD& theta0, const VecD& dtheta0,
                        const std::function<VecD(double)>& torque, const std::vector<double>& times,
                        double tolerance, const ChainObserver& observe) {
  simulateChain(model, false, theta0, dtheta0, torque, times, tolerance, observe);
}

}  // namespace gaitopt::ocp
