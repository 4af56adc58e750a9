#pragma once
/// @file contact_functions.hpp
/// Path functions of a collocation point v = [theta, dtheta, ddtheta, tau (, lambda)] that
/// keep the contacts physical (DESIGN.md sec. 6), as templated functors for
/// AutoDiffPointFunction. Every row is >= 0 when the condition holds.
#include "dynamics/floating_base.hpp"
#include "dynamics/ground.hpp"

namespace gaitopt::ocp {

/// Unilateral contact and Coulomb friction at B (and E in the DSP), then the ZMP inside the
/// support [-heel, toe] (SSP) or [-heel, step_length + toe] (DSP) when the ankle is actuated:
///   F_By, mu F_By - F_Bx, mu F_By + F_Bx (, F_Ey, mu F_Ey - F_Ex, mu F_Ey + F_Ex)
///   (, M + heel Fy, hi Fy - M) with M = x_zmp Fy = step_length F_Ey - tau0, Fy = F_By + F_Ey.
/// F_B comes from total linear momentum (ground.hpp), F_E = lambda.
struct GroundContact {
  const dynamics::Model* model;
  bool dsp;
  bool zmp;
  double step_length;

  int rows() const { return (dsp ? 6 : 3) + (zmp ? 2 : 0); }

  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& v) const {
    const int n = model->nLinks();
    const Vec<S> th = v.head(n), dth = v.segment(n, n), ddth = v.segment(2 * n, n);
    const Vec2<S> f_e = dsp ? Vec2<S>(v.segment(4 * n, 2)) : Vec2<S>(S(0.0), S(0.0));
    const Vec2<S> f_b = dynamics::stanceForce<S>(*model, th, dth, ddth, f_e);
    const double mu = model->friction();
    dynamics::VecX<S> g(rows());
    g.head(3) << f_b(1), mu * f_b(1) - f_b(0), mu * f_b(1) + f_b(0);
    if (dsp) g.segment(3, 3) << f_e(1), mu * f_e(1) - f_e(0), mu * f_e(1) + f_e(0);
    if (zmp) {
      const S fy = f_b(1) + f_e(1);
      const S moment = step_length * f_e(1) - v(3 * n);  // x_zmp * Fy about B
      const double hi = (dsp ? step_length : 0.0) + model->foot().toe;
      g.tail(2) << moment + model->foot().heel * fy, hi * fy - moment;
    }
    return g;
  }
};

/// Swing-tip height above the ground [m] (>= clearance).
struct SwingHeight {
  const dynamics::Model* model;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& v) const {
    const Vec<S> th = v.head(model->nLinks());
    dynamics::VecX<S> g(1);
    g(0) = dynamics::swingTip<S>(*model, th)(1);
    return g;
  }
};

}  // namespace gaitopt::ocp
