#pragma once
/// @file gait_shape.hpp
/// The shape of a gait problem as data (docs/design.md#the-problems-shape), in the spirit of
/// FATROP's stage-wise OCP and Drake's MultipleShooting: a list of phases, each a collocated
/// mesh with its dynamics (single or double support on one model), joined by transitions
/// (continuity, relabelling into the next step or back to the first, a boundary condition tying
/// a variant to the nominal), repeated for N steps and K model variants. shape_builder.hpp
/// assembles the flat NLP from it; nothing else decides what the problem holds.
#include <memory>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::ocp {

/// One phase of the shape.
struct PhaseSpec {
  /// Prefix of the phase's sets and blocks and its tag in the NLP: "ssp" and "dsp" for the
  /// nominal's first step, then e.g. "step2_ssp", "variant1_dsp", "variant1_step2_ssp".
  std::string label;
  /// The prefix the phase's copy adds to the names of its touchdown and transitions ("" for
  /// the nominal's first step).
  std::string copy;
  gaits::Phase kind = gaits::Phase::kSsp;
  PhaseConfig mesh;  ///< duration (and its bounds when free), segments, mesh fractions
  int step = 0;
  int variant = 0;         ///< its model is GaitShape::models[variant]; 0 the nominal
  bool touchdown = false;  ///< the phase ends in the touchdown (touchdown.hpp)
  /// The phase (an index into GaitShape::phases) whose duration this one takes, or -1 for its
  /// own: a variant lives on the nominal's clock.
  int shares_duration = -1;
  /// The nominal phase whose reference drives this one's torques by the feedback law, or -1.
  int feedback_from = -1;
  bool cost = true;  ///< carries the running cost (the nominal only; a variant its spread)
};

enum class TransitionKind {
  kContinuity,    ///< `to` starts in the state `from` ends in (after its touchdown)
  kRelabel,       ///< `to` starts in `from`'s end state relabelled (Mu 2.38): a new step
  kSameStart,     ///< `to` starts in `from`'s start state (a variant from the nominal's start)
  kEndNear,       ///< `to`'s end state within `value` of `from`'s (Euclidean, rad and rad/s)
  kStepDuration,  ///< the durations of the phases from .. to sum to `value` [s]
};

struct TransitionSpec {
  std::string name;  ///< the name of its constraint set
  TransitionKind kind = TransitionKind::kContinuity;
  int from = 0, to = 0;  ///< phases (indices into GaitShape::phases)
  double value = 0;
};

struct GaitShape {
  std::vector<PhaseSpec> phases;  ///< in the order the builder emits them
  /// Each is emitted after the later of its two phases (and that phase's touchdown), in this
  /// order.
  std::vector<TransitionSpec> transitions;
  /// Per variant; [0] the nominal the caller owns, the others held here.
  std::vector<std::shared_ptr<const dynamics::Model>> models;
  /// Per variant, the model its computed-torque law computes with (VariantConfig).
  std::vector<std::shared_ptr<const dynamics::Model>> controllers;
  FeedbackGains feedback;
  double spread = 0;  ///< weight of each variant phase's spread cost (variant_sets.hpp)
  int steps = 1;
  int variants = 1;

  /// The phase of `variant`'s step `step` of kind `kind`, or -1.
  int find(int step, int variant, gaits::Phase kind) const;
};

/// The shape `config` asks for on `model` (which must outlive the problem): its phases (SSP,
/// optionally a DSP) with the touchdown after the SSP, repeated for config.shape.steps steps
/// joined by relabelling and closed by periodicity; then each variant of config.shape.variants
/// as a copy on its perturbed model that starts at the nominal's start, shares its durations,
/// takes its torques from the feedback law and ends near the nominal's end.
GaitShape describeGait(const dynamics::Model& model, const OcpConfig& config);

}  // namespace gaitopt::ocp
