#include "gaits/polynomial/polynomial.hpp"

#include <Eigen/LU>

namespace gaitopt::gaits {

double Polynomial::operator()(double t, int order) const {
  // Horner on the differentiated coefficients: d^r/dt^r t^k = k!/(k-r)! t^(k-r).
  double value = 0;
  for (Eigen::Index k = c_.size() - 1; k >= order; --k) {
    double factor = 1;
    for (int r = 0; r < order; ++r) factor *= static_cast<double>(k - r);
    value = value * t + factor * c_(k);
  }
  return value;
}

Polynomial hermiteCubic(double x0, double v0, double x1, double v1, double duration) {
  const double dx = x1 - x0;
  const double t = duration;
  Eigen::Vector4d c;
  c << x0, v0, (3 * dx - (2 * v0 + v1) * t) / (t * t), (-2 * dx + (v0 + v1) * t) / (t * t * t);
  return Polynomial(c);
}

Polynomial quinticThrough(const Eigen::Vector3d& times, const Eigen::Vector3d& values,
                          const Eigen::Vector3d& slopes) {
  Eigen::Matrix<double, 6, 6> a = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> b;
  for (int i = 0; i < 3; ++i) {
    const double t = times(i);
    for (int k = 0; k < 6; ++k) {
      a(2 * i, k) = std::pow(t, k);
      a(2 * i + 1, k) = k == 0 ? 0.0 : k * std::pow(t, k - 1);
    }
    b(2 * i) = values(i);
    b(2 * i + 1) = slopes(i);
  }
  return Polynomial(a.fullPivLu().solve(b));
}

}  // namespace gaitopt::gaits
