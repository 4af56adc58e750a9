#pragma once
/// @file hzd_virtual_constraints.hpp
/// Virtual constraints of hybrid zero dynamics (Westervelt, Grizzle et al. 2003, "Hybrid zero
/// dynamics of planar biped walkers", IEEE TAC 48(1)): the actuated joints q_a = (q_1 .. q_n-1)
/// (relative angles, joint_coordinates.hpp) as functions h_d of a phase variable
/// phi = c . theta that grows monotonically over single support. For a leg of k links c = 1/k
/// on each stance-leg link: the mean stance-leg angle, which for a leg of two equal links
/// (RABBIT) is exactly the angle of the line from the stance tip to the hip.
///
/// h_d is a quintic Hermite spline in phi on nodes evenly spaced over [phi+, phi-], with the
/// gait's q_a, dq_a/dphi and d2q_a/dphi2 at every node (gaits::Trajectory's interpolation, with
/// phi in the role of time): Kelly's optimum is not a low-degree polynomial of phi (the least-
/// squares Bezier fits of Westervelt 2003 sec. V leave 0.07 rad at degree 6 and 0.015 rad at
/// degree 10), while 40 nodes reproduce it to 1e-4 rad. The end nodes make the zero dynamics
/// manifold Z = {y = 0, ydot = 0} invariant under impact (Westervelt 2003 sec. V-C): at phi- the
/// gait's touchdown posture and slope; at phi+ their relabelled impact image. The gait's own
/// start state, equal to that image up to the OCP's tolerance, is not imposed.
#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "sim/controllers/reference.hpp"

namespace gaitopt::sim {

class VirtualConstraints {
 public:
  /// Fits h_d to the single support of `ref` with `nodes` spline nodes.
  /// @throws std::invalid_argument when nodes < 2, a joint between links is unactuated, or
  ///   c . dtheta <= 0 somewhere (the phase variable must grow monotonically).
  VirtualConstraints(const dynamics::Model& model, const Reference& ref, int nodes = 40);

  /// h_d and its first two derivatives in phi at phase phi (extrapolated outside the step).
  struct Value {
    VecD h, dh, ddh;
  };
  Value at(double phi) const;

  const VecD& phaseWeights() const { return c_; }  ///< c of phi = c . theta
  double phase(const VecD& theta) const { return c_.dot(theta); }
  double phaseStart() const { return phi_plus_; }  ///< phi+ after the impact
  double phaseEnd() const { return phi_minus_; }   ///< phi- at touchdown
  int outputs() const { return static_cast<int>(c_.size()) - 1; }

  /// y = q_a - h_d(phi) and ydot.
  VecD output(const VecD& theta) const;
  VecD outputRate(const VecD& theta, const VecD& dtheta) const;

  /// The posture on Z at phase phi (absolute angles) and its tangent dtheta/dphi.
  VecD posture(double phi) const;
  VecD tangent(double phi) const;

  /// The impact the fit made Z invariant under: true for a single impact (only the leading tip
  /// struck), false for a double one; chosen as the gait's own touchdown admits (impact.hpp).
  bool singleImpact() const { return single_impact_; }
  /// max |q_a - h_d(phi)| over 201 knots of the reference, evenly spaced in time [rad].
  double fitError() const { return fit_error_; }

 private:
  VecD absoluteFromActuated(double phi, const VecD& qa) const;
  gaits::Knot node(const dynamics::Model& model, const gaits::Knot& k) const;

  VecD c_;
  Eigen::RowVectorXd w_;  ///< phi = w . q in joint coordinates (w = c^T M^-1)
  double phi_plus_ = 0, phi_minus_ = 0;
  gaits::Trajectory spline_;  ///< h_d: "t" is phi, "theta" q_a and its phi-derivatives
  bool single_impact_ = true;
  double fit_error_ = 0;
};

/// The post-impact state (relabelled) of a touchdown at (theta, dtheta) by the given impact.
struct ImpactImage {
  VecD theta, dtheta;
};
ImpactImage hzdImpact(const dynamics::Model& model, const VecD& theta, const VecD& dtheta,
                      bool single);

}  // namespace gaitopt::sim
