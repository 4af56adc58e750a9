#include "ocp/shape/gait_shape.hpp"

#include <fmt/format.h>

#include "dynamics/model_variation.hpp"

namespace gaitopt::ocp {
namespace {

/// "variant1_step2_": the names of a copy's sets; "" for the nominal's first step.
std::string copyPrefix(int step, int variant) {
  std::string prefix = variant > 0 ? fmt::format("variant{}_", variant) : "";
  if (step > 0) prefix += fmt::format("step{}_", step + 1);
  return prefix;
}

/// The model of variant `v` > 0: every link's mass and inertia scaled by its mass_scale, its
/// length and CoM offset by its length_scale.
std::shared_ptr<const dynamics::Model> variantModel(const dynamics::Model& nominal,
                                                    const VariantConfig& v) {
  const double e = v.mass_scale - 1, l = v.length_scale - 1;
  return std::make_shared<const dynamics::Model>(
      dynamics::perturbedModel(nominal, {.mass = e, .inertia = e, .length = l, .com = l}));
}

/// The model variant v's computed-torque law computes with: the nominal, or off by Mu's case.
std::shared_ptr<const dynamics::Model> controllerModel(
    const std::shared_ptr<const dynamics::Model>& nominal, const VariantConfig& v) {
  if (v.controller_case == 1) return nominal;
  return std::make_shared<const dynamics::Model>(
      dynamics::perturbedModel(*nominal, dynamics::muUncertaintyCase(v.controller_case)));
}

/// One step's phases of one variant, with the continuity from the touchdown into the DSP.
void addStep(GaitShape& shape, const OcpConfig& config, int step, int variant) {
  const std::string copy = copyPrefix(step, variant);
  const int first = static_cast<int>(shape.phases.size());
  for (size_t j = 0; j < config.phases.size(); ++j) {
    const bool ssp = j == 0;
    const gaits::Phase kind = ssp ? gaits::Phase::kSsp : gaits::Phase::kDsp;
    PhaseSpec p{.label = copy + (ssp ? "ssp" : "dsp"),
                .copy = copy,
                .kind = kind,
                .mesh = config.phases[j],
                .step = step,
                .variant = variant,
                .touchdown = ssp};
    if (variant > 0) {
      p.shares_duration = p.feedback_from = shape.find(step, 0, kind);
      p.cost = false;
    }
    shape.phases.push_back(p);
  }
  const int last = static_cast<int>(shape.phases.size()) - 1;
  if (last > first)
    shape.transitions.push_back(
        {copy + "touchdown_to_dsp", TransitionKind::kContinuity, first, last});
  if (step > 0)  // the previous step's end, relabelled, starts this one
    shape.transitions.push_back({copy + "start", TransitionKind::kRelabel, first - 1, first});
}

/// The steps' durations: each step's phases sum to step_duration (free durations only).
void addStepDurations(GaitShape& shape, const OcpConfig& config) {
  if (config.step_duration <= 0) return;
  for (int step = 0; step < shape.steps; ++step) {
    const int first = shape.find(step, 0, gaits::Phase::kSsp);
    const int last = first + static_cast<int>(config.phases.size()) - 1;
    shape.transitions.push_back({copyPrefix(step, 0) + "step_duration",
                                 TransitionKind::kStepDuration, first, last, config.step_duration});
  }
}

}  // namespace

int GaitShape::find(int step, int variant, gaits::Phase kind) const {
  for (size_t i = 0; i < phases.size(); ++i)
    if (phases[i].step == step && phases[i].variant == variant && phases[i].kind == kind)
      return static_cast<int>(i);
  return -1;
}

GaitShape describeGait(const dynamics::Model& model, const OcpConfig& config) {
  GaitShape shape;
  shape.steps = config.shape.steps;
  shape.variants = config.shape.variantCount();
  shape.feedback = config.shape.feedback;
  shape.spread = config.shape.spread;
  // The caller owns the nominal model: a shared pointer that does not own it.
  shape.models.emplace_back(std::shared_ptr<const dynamics::Model>(), &model);
  shape.controllers.push_back(shape.models.front());
  for (const VariantConfig& v : config.shape.variants) {
    shape.models.push_back(variantModel(model, v));
    shape.controllers.push_back(controllerModel(shape.models.front(), v));
  }
  for (int variant = 0; variant < shape.variants; ++variant) {
    for (int step = 0; step < shape.steps; ++step) addStep(shape, config, step, variant);
    const int first = shape.find(0, variant, gaits::Phase::kSsp);
    const int last = static_cast<int>(shape.phases.size()) - 1;
    if (variant == 0) {
      shape.transitions.push_back({"periodicity", TransitionKind::kRelabel, last, first});
      addStepDurations(shape, config);
      continue;
    }
    const std::string copy = copyPrefix(0, variant);
    const int nominal_last = shape.find(shape.steps - 1, 0, shape.phases[last].kind);
    shape.transitions.push_back({copy + "start", TransitionKind::kSameStart, 0, first});
    shape.transitions.push_back(
        {copy + "end", TransitionKind::kEndNear, nominal_last, last, config.shape.end_tolerance});
  }
  return shape;
}

}  // namespace gaitopt::ocp
