#include "sim/controllers/tracking_law.hpp"

#include <stdexcept>

namespace gaitopt::sim {
namespace {

void requirePositive(double value, const char* name) {
  if (!(value > 0)) throw std::invalid_argument(std::string(name) + " must be positive");
}

}  // namespace

PdLaw::PdLaw(double kp, double kd) : kp_(kp), kd_(kd) {
  requirePositive(kp, "kp");
  requirePositive(kd, "kd");
}

Eigen::VectorXd PdLaw::correction(const Eigen::VectorXd& e, const Eigen::VectorXd& edot) const {
  return kp_ * e + kd_ * edot;
}

SlidingModeLaw::SlidingModeLaw(double lambda, double gain, double boundary)
    : lambda_(lambda), gain_(gain), boundary_(boundary) {
  requirePositive(lambda, "sliding-mode lambda");
  requirePositive(gain, "sliding-mode gain");
  requirePositive(boundary, "sliding-mode boundary layer");
}

Eigen::VectorXd SlidingModeLaw::correction(const Eigen::VectorXd& e,
                                           const Eigen::VectorXd& edot) const {
  const Eigen::VectorXd s = edot + lambda_ * e;  // sliding surface (Mu 4.3)
  const Eigen::VectorXd sat = (s / boundary_).cwiseMax(-1.0).cwiseMin(1.0);
  return lambda_ * edot + gain_ * sat;
}

std::unique_ptr<TrackingLaw> makeTrackingLaw(const std::string& name, const TrackingGains& g) {
  if (name == "computed_torque") return std::make_unique<PdLaw>(g.kp, g.kd);
  if (name == "sliding_mode")
    return std::make_unique<SlidingModeLaw>(g.lambda, g.switching, g.boundary);
  throw std::invalid_argument("unknown controller '" + name +
                              "' (expected computed_torque or sliding_mode)");
}

}  // namespace gaitopt::sim
