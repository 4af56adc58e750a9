#include "sim/controllers/tracking_law.hpp"

#include <stdexcept>
#include <string>

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

}  // namespace gaitopt::sim
