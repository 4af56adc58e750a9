#pragma once
/// @file point_layout.hpp
/// Named layouts of the gait problem's variables, in the spirit of ifopt's variable sets and
/// Drake's state(i): where each quantity sits in one collocation point (PointLayout) and in the
/// touchdown's impact block (ImpactLayout). Every constraint, cost and the result writer index
/// through these types; no other file computes offsets such as 3 n + 2 (README "Variable
/// layouts" gives the grep that checks it).
#include <vector>

namespace gaitopt::ocp {

/// A named contiguous range [start, start + size) of a vector.
struct Slice {
  int start = 0;
  int size = 0;

  /// The position of element i of the slice in the vector.
  int operator[](int i) const { return start + i; }
  /// The slice's elements of `vec` (an Eigen vector, or a block of one; not a temporary).
  template <class V>
  auto of(V&& vec) const {
    return vec.segment(start, size);
  }
  /// The positions of the slice in a vector whose element 0 sits at `base`.
  std::vector<int> indices(int base = 0) const {
    std::vector<int> idx(static_cast<size_t>(size));
    for (int i = 0; i < size; ++i) idx[static_cast<size_t>(i)] = base + start + i;
    return idx;
  }
};

/// One collocation point of a biped phase (the second-order form of collocation.hpp), dim
/// size():
///   q = theta (n) [rad], v = dtheta (n) [rad/s], a = ddtheta (n) [rad/s^2], u = tau (n) [N m],
/// then the algebraic variables z:
///   lambda = F_E (2) [N]  the swing-tip force, double support only (Mu 2.11),
///   s+ (n), s- (n) [W]   positive and negative joint power, only when the cost needs them.
/// A state (q, v) on its own (strike, relabelling) uses the first stateSize() positions.
struct PointLayout {
  int n = 0;  ///< links
  Slice q, v, a, u, lambda, work_plus, work_minus;

  /// @param contact_force  the point carries the swing-tip force (double support)
  /// @param work_slacks    the point carries s+ and s- (absolute-work costs)
  static PointLayout biped(int n_links, bool contact_force, bool work_slacks) {
    PointLayout l;
    l.n = n_links;
    l.q = {0, n_links};
    l.v = {l.q.start + n_links, n_links};
    l.a = {l.v.start + n_links, n_links};
    l.u = {l.a.start + n_links, n_links};
    l.lambda = {l.u.start + n_links, contact_force ? 2 : 0};
    l.work_plus = {l.lambda.start + l.lambda.size, work_slacks ? n_links : 0};
    l.work_minus = {l.work_plus.start + l.work_plus.size, l.work_plus.size};
    return l;
  }
  bool hasContactForce() const { return lambda.size > 0; }
  bool hasWorkSlacks() const { return work_plus.size > 0; }
  int stateSize() const { return q.size + v.size; }
  /// (q, v, a), contiguous: the arguments of accelerations of points of the chain.
  Slice motion() const { return {q.start, a.start + a.size - q.start}; }
  int algebraicSize() const { return lambda.size + work_plus.size + work_minus.size; }
  int size() const { return u.start + u.size + algebraicSize(); }
};

/// The touchdown's impact variables (Mu 2.57-2.62), dim size():
///   qdot+ = (base velocity (2) [m/s], dtheta+ (n) [rad/s]): the rates right after the strike,
///   P_E (2) [N s]: the impulse on the leading (new stance) tip,
///   P_B (2) [N s]: the impulse on the trailing tip, double impact only.
struct ImpactLayout {
  int offset = 0;  ///< first variable of the block in the decision vector
  Slice base_velocity, rates_after, impulse_leading, impulse_trailing;

  static ImpactLayout rigid(int n_links, bool double_impact, int offset = 0) {
    ImpactLayout l;
    l.offset = offset;
    l.base_velocity = {0, 2};
    l.rates_after = {2, n_links};
    l.impulse_leading = {2 + n_links, 2};
    l.impulse_trailing = {l.impulse_leading.start + 2, double_impact ? 2 : 0};
    return l;
  }
  bool doubleImpact() const { return impulse_trailing.size > 0; }
  /// qdot+ = (base velocity, dtheta+).
  Slice qdotPlus() const { return {base_velocity.start, base_velocity.size + rates_after.size}; }
  /// (P_E[, P_B]): the impulses, P_B for a double impact only.
  Slice impulses() const {
    return {impulse_leading.start, impulse_leading.size + impulse_trailing.size};
  }
  int size() const { return impulse_trailing.start + impulse_trailing.size; }
  /// The whole block.
  Slice all() const { return {0, size()}; }
  /// Where `slice` of the block sits in the decision vector.
  Slice inDecision(const Slice& slice) const { return {offset + slice.start, slice.size}; }
};

}  // namespace gaitopt::ocp
