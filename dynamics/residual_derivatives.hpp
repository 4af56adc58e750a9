#pragma once
/// @file residual_derivatives.hpp
/// Exact first and second derivatives of the SSP and DSP dynamics residuals (sspResidual,
/// dspResidual), analytic from the closed form of Mu (2.8): every term of D ddtheta + H dtheta
/// + G is p_ij times cos or sin of (theta_i - theta_j) times at most one rate product, so its
/// derivatives are short closed forms, cheaper than automatic differentiation and exact.
/// The templated residuals are instantiated with Eigen's AutoDiffScalar in the tests as a second,
/// independent check; other constraints of the OCP use that path.
///
/// Variable layout z = [theta (n), dtheta (n), ddtheta (n), tau (n), lambda (2, DSP only)].
#include <Eigen/Core>

#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// A point of the dynamics: the arguments of the residual.
struct DynamicsPoint {
  VecD theta, dtheta, ddtheta, tau;
  Vec2d lambda = Vec2d::Zero();  ///< ground force at E (DSP only) [N]
};

/// Number of residual rows and variables for a phase.
int residualRows(const Model& model, bool dsp);
int residualCols(const Model& model, bool dsp);

/// Residual value (n rows SSP, n + 2 rows DSP).
Eigen::VectorXd residual(const Model& model, const DynamicsPoint& x, bool dsp);

/// Jacobian d residual / d z, dense (rows x cols).
Eigen::MatrixXd residualJacobian(const Model& model, const DynamicsPoint& x, bool dsp);

/// Hessian of sigma^T residual with respect to z (cols x cols, symmetric).
Eigen::MatrixXd residualHessian(const Model& model, const DynamicsPoint& x, bool dsp,
                                const Eigen::VectorXd& sigma);

}  // namespace gaitopt::dynamics
