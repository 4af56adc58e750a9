#include "ocp/transcription/mesh_refinement.hpp"

#include <algorithm>
#include <cmath>

#include "ocp/transcription/collocation_interpolation.hpp"

namespace gaitopt::ocp {

int schemeOrder(Scheme scheme) {
  return scheme == Scheme::kHermiteSimpson ? 4 : 2;
}

Eigen::VectorXd segmentErrors(const PhaseLayout& l, const PointFunction& dynamics,
                              const Eigen::VectorXd& decision, int samples) {
  return segmentErrors(
      l, dynamics, l.durationAt(decision),
      [&](double t) { return interpolatePoint(l, decision, t); }, samples);
}

Eigen::VectorXd segmentErrors(const PhaseLayout& l, const PointFunction& dynamics, double duration,
                              const std::function<Eigen::VectorXd(double)>& point_at, int samples) {
  Eigen::VectorXd errors(l.segments);
  Eigen::VectorXd f(dynamics.rows());
  for (int k = 0; k < l.segments; ++k) {
    const double t0 = duration * l.fraction(k), h = duration * l.segmentFraction(k);
    double integral = 0;
    for (int j = 0; j <= samples; ++j) {
      // Sample a hair inside the segment so its own polynomial is read at both ends.
      const double s = std::clamp(static_cast<double>(j) / samples, 1e-9, 1 - 1e-9);
      dynamics.evaluate(point_at(t0 + s * h), f);
      const double weight = (j == 0 || j == samples) ? 0.5 : 1.0;
      integral += weight * f.cwiseAbs().maxCoeff();
    }
    errors(k) = integral * h / samples;
  }
  return errors;
}

std::vector<double> refinedMesh(const PhaseLayout& l, const Eigen::VectorXd& errors,
                                double tolerance) {
  std::vector<double> mesh{0.0};
  const double exponent = 1.0 / (schemeOrder(l.scheme) + 1);
  for (int k = 0; k < l.segments; ++k) {
    int parts = 1;
    if (errors(k) > tolerance)
      parts =
          std::clamp(static_cast<int>(std::ceil(std::pow(errors(k) / tolerance, exponent))), 2, 4);
    for (int j = 1; j <= parts; ++j)
      mesh.push_back(l.fraction(k) + l.segmentFraction(k) * j / parts);
  }
  mesh.back() = 1.0;  // exact, whatever the rounding
  return mesh;
}

}  // namespace gaitopt::ocp
