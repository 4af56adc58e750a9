#include "ocp/transcription/collocation_interpolation.hpp"

#include <algorithm>
#include <array>

namespace gaitopt::ocp {

SegmentBasis lagrangeDoubleIntegral(Scheme scheme, double s) {
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s;
  if (scheme == Scheme::kTrapezoidal) return {s2 / 2 - s3 / 6, s3 / 6, 0};
  return {s4 / 6 - s3 / 2 + s2 / 2, 2 * s3 / 3 - s4 / 3, s4 / 6 - s3 / 6};
}

SegmentBasis lagrangeBasis(Scheme scheme, double s) {
  if (scheme == Scheme::kTrapezoidal) return {1 - s, s, 0};
  return {(2 * s - 1) * (s - 1), 4 * s * (1 - s), s * (2 * s - 1)};
}

SegmentBasis lagrangeBasisIntegral(Scheme scheme, double s) {
  if (scheme == Scheme::kTrapezoidal) return {s - s * s / 2, s * s / 2, 0};
  const double s2 = s * s, s3 = s2 * s;
  return {2 * s3 / 3 - 3 * s2 / 2 + s, 2 * s2 - 4 * s3 / 3, 2 * s3 / 3 - s2 / 2};
}

int segmentAt(const PhaseLayout& layout, double t, double total) {
  const double s = t / total;
  int k = 0;
  while (k + 1 < layout.segments && layout.fraction(k + 1) <= s) ++k;
  return k;
}

namespace {

/// Where phase time t falls: the points first .. first + count - 1 of its segment, the
/// segment's length h and the local time s = (t - t_k) / h in [0, 1].
struct SegmentPlace {
  int first = 0, count = 0;
  double h = 0, s = 0;
};

SegmentPlace placeOf(const PhaseLayout& l, const Eigen::VectorXd& decision, double t) {
  const double total = l.durationAt(decision);
  const int k = segmentAt(l, t, total);
  const double h = total * l.segmentFraction(k);
  return {k * l.pointsPerSegment(), l.pointsPerSegment() + 1, h,
          std::clamp((t - total * l.fraction(k)) / h, 0.0, 1.0)};
}

}  // namespace

Eigen::VectorXd interpolatePoint(const PhaseLayout& l, const Eigen::VectorXd& decision, double t) {
  const SegmentPlace p = placeOf(l, decision, t);
  const SegmentBasis value = lagrangeBasis(l.scheme, p.s),
                     integral = lagrangeBasisIntegral(l.scheme, p.s);
  Eigen::VectorXd point = Eigen::VectorXd::Zero(l.pointSize());
  for (int j = 0; j < p.count; ++j)
    point += value[static_cast<size_t>(j)] * l.point(decision, p.first + j);
  for (int i = 0; i < l.nx; ++i) {  // x = x_k + integral of the interpolated xdot
    double x = decision(l.x(p.first, i));
    for (int j = 0; j < p.count; ++j)
      x += p.h * integral[static_cast<size_t>(j)] * decision(l.xdot(p.first + j, i));
    point(i) = x;
  }
  return point;
}

Eigen::VectorXd exportPoint(const PhaseLayout& l, const Eigen::VectorXd& decision, double t) {
  Eigen::VectorXd point = interpolatePoint(l, decision, t);
  if (l.nq == 0) return point;
  const SegmentPlace p = placeOf(l, decision, t);
  const SegmentBasis twice = lagrangeDoubleIntegral(l.scheme, p.s);
  for (int i = 0; i < l.nq; ++i) {  // q = q_k + v_k (t - t_k) + double integral of a
    double q = decision(l.x(p.first, i)) + p.h * p.s * decision(l.x(p.first, l.nq + i));
    for (int j = 0; j < p.count; ++j)
      q += p.h * p.h * twice[static_cast<size_t>(j)] * decision(l.xdot(p.first + j, l.nq + i));
    point(i) = q;
  }
  return point;
}

}  // namespace gaitopt::ocp
