#pragma once
/// The numeric Lagrangian: D, H dtheta and G obtained by finite differences of the kinetic and
/// potential energies of energy.hpp (which are written from CoM velocities, not from Mu 2.8).
/// K is exactly quadratic in dtheta, so D and dK/d(dtheta) come from polarisation identities
/// (exact up to rounding); derivatives in theta use Richardson-extrapolated central differences
/// (error O(h^4)).
#include <functional>

#include "dynamics/energy.hpp"

namespace gaitopt::test {

/// d/dx f at 0 along one direction, Richardson extrapolation of central differences.
inline double richardson(const std::function<double(double)>& f, double h = 1e-3) {
  auto central = [&](double s) { return (f(s) - f(-s)) / (2 * s); };
  return (4 * central(h / 2) - central(h)) / 3;
}

inline MatD numericMassMatrix(const dynamics::Model& m, const VecD& theta) {
  const int n = m.nLinks();
  auto k = [&](const VecD& v) { return dynamics::kineticEnergy<double>(m, theta, v); };
  MatD d(n, n);
  for (int i = 0; i < n; ++i) {
    const VecD ei = VecD::Unit(n, i);
    d(i, i) = 2 * k(ei);
    for (int j = 0; j < i; ++j) {
      const VecD ej = VecD::Unit(n, j);
      d(i, j) = d(j, i) = k(ei + ej) - k(ei) - k(ej);
    }
  }
  return d;
}

/// dK/d(dtheta) = D dtheta, by polarisation (exact for a quadratic form).
inline VecD numericMomentum(const dynamics::Model& m, const VecD& theta, const VecD& dtheta) {
  const int n = m.nLinks();
  VecD p(n);
  for (int i = 0; i < n; ++i) {
    const VecD ei = VecD::Unit(n, i);
    p(i) = 0.5 * (dynamics::kineticEnergy<double>(m, theta, dtheta + ei) -
                  dynamics::kineticEnergy<double>(m, theta, dtheta - ei));
  }
  return p;
}

inline VecD numericGravity(const dynamics::Model& m, const VecD& theta) {
  const int n = m.nLinks();
  VecD g(n);
  for (int i = 0; i < n; ++i)
    g(i) = richardson([&](double s) {
      return dynamics::potentialEnergy<double>(m, VecD(theta + s * VecD::Unit(n, i)));
    });
  return g;
}

/// H dtheta = d/dt(dK/d dtheta) - D ddtheta - dK/dtheta = Ddot dtheta - dK/dtheta.
inline VecD numericCoriolis(const dynamics::Model& m, const VecD& theta, const VecD& dtheta) {
  const int n = m.nLinks();
  VecD h(n);
  for (int i = 0; i < n; ++i) {
    const double ddot_dth = richardson(
        [&](double s) { return numericMomentum(m, VecD(theta + s * dtheta), dtheta)(i); });
    const double dk_dth = richardson([&](double s) {
      return dynamics::kineticEnergy<double>(m, VecD(theta + s * VecD::Unit(n, i)), dtheta);
    });
    h(i) = ddot_dth - dk_dth;
  }
  return h;
}

}  // namespace gaitopt::test
