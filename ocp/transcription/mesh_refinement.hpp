#pragma once
/// @file mesh_refinement.hpp
/// Error estimate and mesh update of one phase, independent of the robot (Betts 2010, sec. 4.7;
/// Kelly, SIAM Review 2017, sec. 5.3). Between its points a solution follows the scheme's
/// polynomials (collocation_interpolation.hpp); the implicit dynamics F(x, xdot, u, z) = 0 hold
/// at the points only. The error of segment k is the integral of the worst row of |F| over it,
///   eta_k = int_{t_k}^{t_k+1} ||F(interpolated point)||_inf dt,
/// for the biped a generalised-momentum defect [N m s]: the impulse the polynomials miss.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "ocp/transcription/collocation.hpp"
#include "ocp/transcription/point_function.hpp"

namespace gaitopt::ocp {

/// eta_k of every segment, by the composite trapezoid rule on `samples` sub-intervals.
Eigen::VectorXd segmentErrors(const PhaseLayout& layout, const PointFunction& dynamics,
                              const Eigen::VectorXd& decision, int samples = 8);

/// The same along another reading of the solution between its points: `point_at(t)` gives the
/// point variables at phase time t of a phase of duration `duration` (a double support in
/// reduced coordinates is read on its chart, dsp_chart_export.hpp).
Eigen::VectorXd segmentErrors(const PhaseLayout& layout, const PointFunction& dynamics,
                              double duration,
                              const std::function<Eigen::VectorXd(double)>& point_at,
                              int samples = 8);

/// The mesh fractions after splitting each segment with eta_k > tolerance into m equal parts,
/// m = ceil((eta_k / tolerance)^(1 / (order + 1))) within [2, 4]: the local error of a scheme
/// of order p shrinks like h^(p+1). Segments within tolerance are kept.
std::vector<double> refinedMesh(const PhaseLayout& layout, const Eigen::VectorXd& errors,
                                double tolerance);

/// Order of the scheme's global error: 2 (trapezoidal), 4 (Hermite-Simpson).
int schemeOrder(Scheme scheme);

}  // namespace gaitopt::ocp
