#pragma once
/// @file resimulation.hpp
/// The accuracy of a collocated gait measured by an independent re-simulation of its torques
/// (chain_simulation.hpp, adaptive RKF 7(8)) (docs/design.md#the-verification-ladder, rung 3). The
/// integrator shares nothing with the transcription but the dynamics functions, so the measured
/// error is the collocation's discretisation error (Betts 2010, sec. 4.7; Kelly 2017, sec. 4):
/// trapezoidal O(h^2), Hermite-Simpson O(h^4) at the end of the phase. Header-only, like
/// chain_simulation.hpp: its users link Boost::boost.
#include <algorithm>
#include <functional>
#include <utility>

#include "ocp/problem/gait_problem.hpp"
#include "ocp/transcription/chain_simulation.hpp"
#include "ocp/transcription/collocation_interpolation.hpp"

namespace gaitopt::ocp {

/// Difference between a re-simulated state and the solution's, max over the links.
struct StateError {
  double angle = 0;  ///< max |theta_sim - theta_sol| [rad]
  double rate = 0;   ///< max |dtheta_sim - dtheta_sol| [rad/s]
};

/// The SSP's torques as the collocation scheme interpolates them between its points
/// (collocation_interpolation.hpp: linear for trapezoidal, quadratic for Hermite-Simpson).
inline std::function<VecD(double)> sspTorque(const GaitProblem& problem, const Eigen::VectorXd& x) {
  const PhaseLayout& l = problem.ssp.layout;
  const Slice u = problem.ssp.point.u;
  return [&l, &x, u](double t) -> VecD {
    const Eigen::VectorXd point = interpolatePoint(l, x, t);
    return u.of(point);
  };
}

/// A state (theta, dtheta) [rad, rad/s].
using ChainState = std::pair<VecD, VecD>;

/// Integrates SSP segment `seg` of the solution `x` from `start` (the state at the segment's
/// start) under `torque` (sspTorque); returns the state at the segment's end. One integration
/// per segment, because the interpolated torques have a kink at every segment boundary, which
/// an adaptive step controller crossing it handles erratically (measured on RABBIT: end errors
/// that changed by 2x and more between tolerances 1e-11 and 1e-13).
inline ChainState simulateSegment(const GaitProblem& problem, const dynamics::Model& model,
                                  const Eigen::VectorXd& x,
                                  const std::function<VecD(double)>& torque, int seg,
                                  const ChainState& start, double tolerance) {
  const PhaseLayout& l = problem.ssp.layout;
  const int per = l.pointsPerSegment();
  const double total = l.durationAt(x);
  const double t0 = l.time(per * seg, total), h = l.time(per * (seg + 1), total) - t0;
  ChainState end = start;
  simulateSsp(
      model, start.first, start.second, [&](double t) { return torque(t0 + t); }, {0.0, h},
      tolerance,
      [&](double t, const VecD& theta, const VecD& dtheta) {
        if (t > 0) end = {theta, dtheta};
      });
  return end;
}

/// The state of SSP point p of the solution `x`.
inline ChainState sspPointState(const GaitProblem& problem, const Eigen::VectorXd& x, int p) {
  const Eigen::VectorXd v = problem.ssp.layout.point(x, p);
  const PointLayout& l = problem.ssp.point;
  return {l.q.of(v), l.v.of(v)};
}

inline StateError difference(const ChainState& a, const ChainState& b) {
  return {(a.first - b.first).cwiseAbs().maxCoeff(), (a.second - b.second).cwiseAbs().maxCoeff()};
}

/// Re-simulates the whole SSP of the solution `x` open loop, from its first point's state under
/// its interpolated torques, and compares the state at the end of the SSP (the strike state)
/// with the solution's last SSP point. Global error: local errors amplified by the unstable
/// single support, so only meaningful where that amplification is moderate (RABBIT: yes).
inline StateError sspEndStateError(const GaitProblem& problem, const dynamics::Model& model,
                                   const Eigen::VectorXd& x, double tolerance = 1e-12) {
  const auto torque = sspTorque(problem, x);
  ChainState state = sspPointState(problem, x, 0);
  for (int seg = 0; seg < problem.ssp.layout.segments; ++seg) {
    state = simulateSegment(problem, model, x, torque, seg, state, tolerance);
  }
  return difference(state, sspPointState(problem, x, problem.ssp.layout.points() - 1));
}

/// Re-simulates every SSP segment from the solution's state at its start and compares with the
/// state at its end; the worst over the segments. Local error (h^{p+1} per segment), free of the
/// open-loop amplification that swamps sspEndStateError on unstable gaits (five-link robot).
inline StateError sspSegmentError(const GaitProblem& problem, const dynamics::Model& model,
                                  const Eigen::VectorXd& x, double tolerance = 1e-12) {
  const int per = problem.ssp.layout.pointsPerSegment();
  const auto torque = sspTorque(problem, x);
  StateError worst;
  for (int seg = 0; seg < problem.ssp.layout.segments; ++seg) {
    const ChainState end = simulateSegment(problem, model, x, torque, seg,
                                           sspPointState(problem, x, per * seg), tolerance);
    const StateError e = difference(end, sspPointState(problem, x, per * (seg + 1)));
    worst = {std::max(worst.angle, e.angle), std::max(worst.rate, e.rate)};
  }
  return worst;
}

}  // namespace gaitopt::ocp
