#pragma once
/// @file phase.hpp
/// One phase of the gait's step as an object: which support it is, where its collocation
/// points sit in the decision vector and what each point holds.
#include <string>

#include "gaits/trajectory/trajectory.hpp"
#include "ocp/transcription/collocation.hpp"
#include "ocp/transcription/point_layout.hpp"

namespace gaitopt::ocp {

struct Phase {
  gaits::Phase kind = gaits::Phase::kSsp;
  PhaseLayout layout;  ///< the collocation points in the decision vector
  PointLayout point;   ///< the variables of each point
  /// A double support collocated in reduced coordinates, its leading tip pinned at position
  /// and velocity level at every point (dsp_chart.hpp).
  bool reduced_coordinates = false;
  /// The phase's name when it is one of several of its kind (another step or a model variant,
  /// ocp/shape/gait_shape.hpp); empty: "ssp" or "dsp".
  std::string label;

  bool doubleSupport() const { return kind == gaits::Phase::kDsp; }
  /// The label, else "ssp" or "dsp": the prefix of the phase's set and block names, and its tag
  /// in the NLP.
  std::string name() const {
    if (!label.empty()) return label;
    return doubleSupport() ? "dsp" : "ssp";
  }
  /// Decision-vector indices of `slice` of point p (p < 0 counts from the end).
  std::vector<int> indices(int p, const Slice& slice) const {
    return slice.indices(layout.pointOffset(p < 0 ? layout.points() + p : p));
  }
};

}  // namespace gaitopt::ocp
