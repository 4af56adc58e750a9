#pragma once
/// @file tracking_law.hpp
/// The outer loop of a tracking controller: the acceleration to add to the reference's, from
/// the tracking error e = y_ref - y and its rate (in whatever coordinates y the phase tracks:
/// relative joint angles in single support, hip position and torso angle in double support).
///   PD (computed torque): v = Kp e + Kd edot.
///   Sliding mode (Mu 2004 ch. 4, eqs. 4.3-4.8): s = edot + Lambda e,
///     v = Lambda edot + K sat(s / phi): the equivalent control that keeps s = 0 plus a
///     switching term, smoothed in a boundary layer of width phi against chattering.
#include <Eigen/Core>

namespace gaitopt::sim {

/// Gains of both laws, defaults tuned on the five-link gaits (natural frequency 20 rad/s).
struct TrackingGains {
  double kp = 400, kd = 40;                           ///< PD [1/s^2], [1/s]
  double lambda = 20, switching = 5, boundary = 0.1;  ///< sliding mode
};

class TrackingLaw {
 public:
  virtual ~TrackingLaw() = default;
  virtual Eigen::VectorXd correction(const Eigen::VectorXd& e,
                                     const Eigen::VectorXd& edot) const = 0;
};

class PdLaw : public TrackingLaw {
 public:
  /// @throws std::invalid_argument unless kp, kd > 0.
  PdLaw(double kp, double kd);
  explicit PdLaw(const TrackingGains& g) : PdLaw(g.kp, g.kd) {}
  Eigen::VectorXd correction(const Eigen::VectorXd& e, const Eigen::VectorXd& edot) const override;

 private:
  double kp_, kd_;
};

class SlidingModeLaw : public TrackingLaw {
 public:
  /// @throws std::invalid_argument unless lambda, gain, boundary > 0.
  SlidingModeLaw(double lambda, double gain, double boundary);
  explicit SlidingModeLaw(const TrackingGains& g)
      : SlidingModeLaw(g.lambda, g.switching, g.boundary) {}
  Eigen::VectorXd correction(const Eigen::VectorXd& e, const Eigen::VectorXd& edot) const override;

 private:
  double lambda_, gain_, boundary_;
};

}  // namespace gaitopt::sim
