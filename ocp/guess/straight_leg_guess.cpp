#include "ocp/guess/straight_leg_guess.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/ground.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::ocp {

VecD straightLegTouchdown(const dynamics::Model& model, double step_length) {
  const int n = model.nLinks();
  const double leg = model.link(0).length;  // relabelling swaps the legs: they are equal
  if (!(step_length < 2 * leg))
    throw std::domain_error(
        fmt::format("a step of {:g} m is beyond legs of {:g} m", step_length, leg));
  const double lean = std::asin(step_length / (2 * leg));
  VecD theta(n);
  theta(0) = lean;                         // stance leg, tip at B
  theta(n - 1) = std::numbers::pi - lean;  // swing leg, from the hip down to E = (L, 0)
  if (model.torso()) theta(*model.torso()) = model.slope();  // upright in the world
  return theta;
}

gaits::Trajectory straightLegGuess(const dynamics::Model& model, const OcpConfig& config) {
  if (model.legLinks() != 1)
    throw std::invalid_argument(
        fmt::format("the straight-leg guess serves legs of one link; robot '{}' has {} per leg",
                    model.name(), model.legLinks()));
  if (config.phases.size() != 1)
    throw std::invalid_argument("the straight-leg guess builds steps without a DSP");
  const VecD end = straightLegTouchdown(model, config.step_length);
  const VecD start = dynamics::relabelAngles<double>(model, end);
  const double duration = config.phases.front().duration;
  const VecD rate = (end - start) / duration;
  const VecD zero = VecD::Zero(model.nLinks());
  const int samples = static_cast<int>(std::ceil(duration * 1000));
  std::vector<gaits::Knot> knots;
  for (int k = 0; k <= samples; ++k) {
    gaits::Knot knot;
    knot.t = duration * k / samples;
    knot.theta = start + rate * knot.t;
    knot.dtheta = rate;
    knot.ddtheta = zero;
    knot.tau = dynamics::sspInverseDynamics(model, knot.theta, rate, zero);
    knot.force_stance = dynamics::stanceForce<double>(model, knot.theta, rate, zero, Vec2d::Zero());
    knots.push_back(std::move(knot));
  }
  return gaits::Trajectory(model.name(), config.step_length, std::move(knots));
}

}  // namespace gaitopt::ocp
