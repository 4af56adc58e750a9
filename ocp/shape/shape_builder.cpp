#include "ocp/shape/shape_builder.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "ocp/problem/gait_links.hpp"
#include "ocp/shape/computed_torque_law.hpp"
#include "ocp/shape/phase_builder.hpp"
#include "ocp/shape/variant_sets.hpp"
#include "ocp/transcription/autodiff_constraint.hpp"

namespace gaitopt::ocp {
namespace {

/// y = (a, b) -> b - a: one block of variables continues into another.
struct Continuity {
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const auto half = y.size() / 2;
    return y.tail(half) - y.head(half);
  }
};

/// The config each variant's sets read, the nominal's first: a copy with scaled lengths steps
/// step_length times its length_scale, since the reference's angles put its tip there; a probe
/// (variant_contact: false) has no contact rows.
std::vector<OcpConfig> variantConfigs(const OcpConfig& config) {
  std::vector<OcpConfig> configs{config};
  for (const VariantConfig& v : config.shape.variants) {
    OcpConfig& copy = configs.emplace_back(config);
    copy.step_length *= v.length_scale;
    if (!config.shape.contact) copy.ground_contact = false;  // its forces, ZMP and impulses
  }
  return configs;
}

/// y = free durations: their sum plus the fixed ones equals the step duration.
struct DurationSum {
  double fixed;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    return dynamics::VecX<S>::Constant(1, y.sum() + fixed);
  }
};

class Builder {
 public:
  Builder(GaitProblem& p, const GaitShape& shape, const OcpConfig& config,
          const std::vector<gaits::Trajectory>& guesses)
      : p_(p), shape_(shape), configs_(variantConfigs(config)), guesses_(guesses) {}

  void emitPhase(int i) {
    const PhaseSpec& spec = shape_.phases[static_cast<size_t>(i)];
    const dynamics::Model& model = *shape_.models[static_cast<size_t>(spec.variant)];
    open();
    std::optional<int> shared;
    if (spec.shares_duration >= 0) shared = built(spec.shares_duration).layout.duration_index;
    const auto& guess = guesses_[guesses_.size() == 1 ? 0 : static_cast<size_t>(spec.step)];
    const OcpConfig& config = configs_[static_cast<size_t>(spec.variant)];
    BuiltPhase b{addPhaseVariables(p_.nlp, model, config, guess, spec, shared), spec.step,
                 spec.variant, &model, std::nullopt};
    addPhaseSets(p_.nlp, model, config, b.phase, spec.cost);
    if (spec.feedback_from >= 0) addVariantSets(spec, b);
    phase_stage_.push_back(
        close({spec.label, StageKind::kPhase, spec.step, spec.variant, {}, {}, i}));
    couple(phase_stage_.back(), spec.shares_duration);
    couple(phase_stage_.back(), spec.feedback_from);
    touchdown_stage_.push_back(spec.touchdown ? emitTouchdown(i, b) : -1);
    p_.built.push_back(std::move(b));
  }

  void emitTransition(const TransitionSpec& t) {
    open();
    addRows(t);
    const PhaseSpec& to = shape_.phases[static_cast<size_t>(t.to)];
    const int stage = close({t.name, StageKind::kTransition, to.step, to.variant, {}, {}, -1});
    declareCouplings(stage, t);
  }

 private:
  /// A variant's torques by the feedback law around the reference, and its spread about it.
  void addVariantSets(const PhaseSpec& spec, const BuiltPhase& b) {
    const Phase& reference = built(spec.feedback_from);
    const FeedbackGains& law = shape_.feedback;
    const std::string name = b.phase.name() + "_feedback";
    if (law.law == FeedbackGains::Law::kJointPd)
      p_.nlp.addConstraint(std::make_unique<FeedbackLaw>(name, b.phase, reference, *b.model, law));
    else if (!b.phase.doubleSupport())
      p_.nlp.addConstraint(std::make_unique<ComputedTorqueLaw>(
          b.phase.name() + "_computed_torque", b.phase, reference,
          *shape_.controllers[static_cast<size_t>(spec.variant)], law));
    else
      p_.nlp.addConstraint(std::make_unique<FeedbackLaw>(
          name, b.phase, reference, *b.model, FeedbackGains{{}, law.dsp_kp, law.dsp_kd}));
    if (shape_.spread > 0)
      p_.nlp.addCost(std::make_unique<VariantSpread>(b.phase.name() + "_spread", b.phase, reference,
                                                     shape_.spread));
  }

  /// The touchdown at the end of phase i (built as `b`, on its variant's model); its stage.
  int emitTouchdown(int i, BuiltPhase& b) {
    const PhaseSpec& spec = shape_.phases[static_cast<size_t>(i)];
    open();
    const OcpConfig& config = configs_[static_cast<size_t>(spec.variant)];
    b.touchdown = Touchdown::add(p_.nlp, *b.model, config, b.phase, config.step_length, spec.copy);
    const int stage =
        close({spec.copy + "touchdown", StageKind::kTouchdown, spec.step, spec.variant, {}, {}, i});
    couple(stage, i);
    return stage;
  }

  void addRows(const TransitionSpec& t) {
    const int n2 = built(t.to).point.stateSize();
    switch (t.kind) {
      case TransitionKind::kContinuity:
        addLink(p_.nlp, t.name, n2, concat(endState(t.from), startState(t.to)), 0, Continuity{});
        break;
      case TransitionKind::kRelabel:
        addLink(p_.nlp, t.name, n2, concat(endState(t.from), startState(t.to)), 0,
                Periodicity{p_.built[static_cast<size_t>(t.to)].model});
        break;
      case TransitionKind::kSameStart:
        addLink(p_.nlp, t.name, n2, concat(startState(t.from), startState(t.to)), 0, Continuity{});
        break;
      case TransitionKind::kEndNear:
        p_.nlp.addConstraint(
            std::make_unique<StateDistance>(t.name, endState(t.from), endState(t.to), t.value));
        break;
      case TransitionKind::kStepDuration:
        addStepDuration(t);
        break;
    }
  }

  const Phase& built(int i) const { return p_.built[static_cast<size_t>(i)].phase; }

  /// (theta, dtheta) at a phase's first point.
  std::vector<int> startState(int i) const {
    const Phase& phase = built(i);
    return concat(phase.indices(0, phase.point.q), phase.indices(0, phase.point.v));
  }

  /// (theta, dtheta) at a phase's end, the rates after its touchdown if it has one.
  std::vector<int> endState(int i) const {
    const BuiltPhase& b = p_.built[static_cast<size_t>(i)];
    return concat(b.phase.indices(-1, b.phase.point.q),
                  b.touchdown ? b.touchdown->ratesAfter() : b.phase.indices(-1, b.phase.point.v));
  }

  /// A step duration meets its phases' durations; the other transitions meet the state at
  /// their ends, an end after a touchdown through its rates.
  void declareCouplings(int stage, const TransitionSpec& t) {
    if (t.kind == TransitionKind::kStepDuration) {
      for (int phase = t.from; phase <= t.to; ++phase) couple(stage, phase);
      return;
    }
    couple(stage, t.from);
    couple(stage, t.to);
    if (t.kind == TransitionKind::kSameStart) return;
    couple(stage, touchdown_stage_[static_cast<size_t>(t.from)], true);
    if (t.kind == TransitionKind::kEndNear)
      couple(stage, touchdown_stage_[static_cast<size_t>(t.to)], true);
  }

  void addStepDuration(const TransitionSpec& t) {
    std::vector<int> free;
    double fixed = 0;
    for (int i = t.from; i <= t.to; ++i) {
      const PhaseLayout& l = built(i).layout;
      if (l.freeDuration())
        free.push_back(l.duration_index);
      else
        fixed += l.duration;
    }
    addLink(p_.nlp, t.name, 1, free, 0, DurationSum{fixed}, t.value, t.value);
  }

  void open() {
    columns_ = p_.nlp.variables();
    rows_ = p_.nlp.constraints();
  }

  int close(Stage stage) {
    stage.columns = {columns_, p_.nlp.variables() - columns_};
    stage.rows = {rows_, p_.nlp.constraints() - rows_};
    p_.stages.stages.push_back(std::move(stage));
    return static_cast<int>(p_.stages.stages.size()) - 1;
  }

  /// Declares that `stage` meets phase `phase`'s stage (or, with `is_stage`, stage `phase`).
  void couple(int stage, int phase, bool is_stage = false) {
    if (phase < 0) return;
    const int other = is_stage ? phase : phase_stage_[static_cast<size_t>(phase)];
    if (other >= 0 && other != stage) p_.stages.couplings.emplace_back(stage, other);
  }

  GaitProblem& p_;
  const GaitShape& shape_;
  std::vector<OcpConfig> configs_;  ///< per variant: the config its sets read
  const std::vector<gaits::Trajectory>& guesses_;
  std::vector<int> phase_stage_, touchdown_stage_;  // per phase of the shape
  int columns_ = 0, rows_ = 0;
};

void requireGuesses(const GaitShape& shape, const std::vector<gaits::Trajectory>& guesses) {
  if (guesses.size() != 1 && static_cast<int>(guesses.size()) != shape.steps)
    throw std::invalid_argument("expected one guess, or one per step");
  for (const auto& guess : guesses)
    if (guess.nLinks() != shape.models.front()->nLinks())
      throw std::invalid_argument("initial guess and robot have different numbers of links");
}

/// The nominal's first step, named as callers of one-step problems know it.
void nameNominal(GaitProblem& p) {
  for (const BuiltPhase& b : p.built) {
    if (b.step != 0 || b.variant != 0) continue;
    if (b.phase.doubleSupport()) {
      p.dsp = b.phase;
    } else {
      p.ssp = b.phase;
      p.touchdown = *b.touchdown;
    }
  }
}

}  // namespace

GaitProblem assembleGaitProblem(const GaitShape& shape, const OcpConfig& config,
                                const std::vector<gaits::Trajectory>& guesses) {
  requireGuesses(shape, guesses);
  GaitProblem p;
  p.step_length = config.step_length;
  for (const OcpConfig& c : variantConfigs(config)) p.step_lengths.push_back(c.step_length);
  p.steps = shape.steps;
  p.variants = shape.variants;
  p.models = shape.models;
  p.controllers = shape.controllers;
  Builder builder(p, shape, config, guesses);
  for (int i = 0; i < static_cast<int>(shape.phases.size()); ++i) {
    builder.emitPhase(i);
    for (const TransitionSpec& t : shape.transitions)
      if (std::max(t.from, t.to) == i) builder.emitTransition(t);
  }
  nameNominal(p);
  return p;
}

}  // namespace gaitopt::ocp
