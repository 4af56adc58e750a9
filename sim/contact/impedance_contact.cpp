#include "sim/contact/impedance_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace gaitopt::sim {
namespace {

void require(bool ok, const char* name, const char* expected, double value) {
  if (ok) return;
  std::ostringstream msg;
  msg << "ImpedanceGround." << name << ": expected " << expected << ", got " << value;
  throw std::invalid_argument(msg.str());
}

}  // namespace

void validateImpedanceGround(const ImpedanceGround& g) {
  // The negated comparisons also reject NaN; isfinite rejects infinity.
  const auto positive = [](double v) { return std::isfinite(v) && v > 0; };
  const auto non_negative = [](double v) { return std::isfinite(v) && v >= 0; };
  require(positive(g.stiffness), "stiffness", "a positive finite number [N/m^n]", g.stiffness);
  require(non_negative(g.damping), "damping", "a finite number >= 0 [N s/m^(n+1)]", g.damping);
  require(std::isfinite(g.exponent) && g.exponent >= 1, "exponent", "a finite number >= 1",
          g.exponent);
  require(positive(g.tangential_stiffness), "tangential_stiffness",
          "a positive finite number [N/m]", g.tangential_stiffness);
  require(non_negative(g.tangential_damping), "tangential_damping", "a finite number >= 0 [N s/m]",
          g.tangential_damping);
  require(non_negative(g.friction), "friction", "a finite number >= 0", g.friction);
  require(non_negative(g.pad_thickness), "pad_thickness", "a finite number >= 0 [m]",
          g.pad_thickness);
}

double huntCrossleyNormalForce(const ImpedanceGround& g, double penetration,
                               double penetration_rate) {
  if (penetration <= 0) return 0;
  const double dn = std::pow(penetration, g.exponent);
  if (g.pad_thickness <= 0) return std::max(0.0, dn * (g.stiffness + g.damping * penetration_rate));
  // Addi & Rodic (60): stiffening towards the pad's thickness (held at 99.9 % of it, where the
  // factor is 2.6e7), damping only while compressing.
  const double squeeze = std::min(penetration / g.pad_thickness, 0.999);
  const double t = std::tan(std::numbers::pi * squeeze / 2);
  const double stiffening = 1 + 0.1 * t * t * t;
  const double damping = penetration_rate > 0 ? g.damping * penetration_rate : 0.0;
  return stiffening * dn * (g.stiffness + damping);
}

ImpedanceContactForce impedanceContactForce(const ImpedanceGround& g,
                                            const ContactPointMotion& motion, double anchor) {
  const double fn = huntCrossleyNormalForce(g, motion.penetration, motion.penetration_rate);
  const double limit = g.friction * fn;
  const double trial = -g.tangential_stiffness * (motion.tangential_position - anchor) -
                       g.tangential_damping * motion.tangential_velocity;
  if (std::abs(trial) <= limit) return {fn, trial, anchor, false};
  const double ft = std::copysign(limit, trial);
  return {fn, ft, motion.tangential_position + ft / g.tangential_stiffness, true};
}

}  // namespace gaitopt::sim
