#pragma once
/// @file relabel.hpp
/// Stance/swing relabelling at the end of a step (Mu 2.38, corrected): the chain is reversed,
/// leg links turn by pi, the torso keeps its angle (the printed Pi has pi in the torso entry,
/// which would flip the torso upside down; docs/derivations.md#relabelling). Rates are reversed
/// without sign change. The new origin is the old swing tip E.
#include <cmath>
#include <numbers>

#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// Wraps x into [centre - pi, centre + pi).
template <class S>
S wrapAngle(const S& x, double centre) {
  using std::floor;
  const double two_pi = 2 * std::numbers::pi;
  return x - two_pi * floor((x - centre + std::numbers::pi) / two_pi);
}

/// theta^+ = T theta^- + Pi (2.38, corrected), wrapped so that stance-leg and torso angles lie
/// in [-pi, pi) and swing-leg angles in [0, 2 pi); relabel(relabel(theta)) = theta on that range.
template <class S>
Vec<S> relabelAngles(const Model& model, const Vec<S>& theta) {
  const int n = model.nLinks();
  Vec<S> out(n);
  for (int i = 0; i < n; ++i) {
    const bool torso = model.torso() && *model.torso() == i;
    const bool swing = i >= n - model.legLinks();
    const S turned = theta(n - 1 - i) + (torso ? 0.0 : std::numbers::pi);
    out(i) = wrapAngle(turned, swing ? std::numbers::pi : 0.0);
  }
  return out;
}

/// dtheta^+ = T dtheta^- (2.38): the reversed order, same signs.
template <class S>
Vec<S> relabelRates(const Vec<S>& dtheta) {
  return dtheta.reverse();
}

}  // namespace gaitopt::dynamics
