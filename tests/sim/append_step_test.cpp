// The walk's record of its steps (sim/walk/hybrid_walk.hpp): a touchdown far short of the planned
// step is a scuff at mid-swing that ends the walk, not a step walked; steps a push or a model
// error shortens still count.
#include <gtest/gtest.h>

#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::sim {
namespace {

StepResult stepOf(double advance) {
  StepResult s;
  s.ok = true;
  s.advance = advance;
  s.slip = 1e-4;
  return s;
}

TEST(AppendStep, AScuffAtMidSwingIsNotAStep) {
  WalkResult w;
  EXPECT_TRUE(appendStep(w, stepOf(0.3), 0.5));    // 60 %: a shortened step
  EXPECT_FALSE(appendStep(w, stepOf(3e-5), 0.5));  // the legs together
  EXPECT_EQ(w.steps_completed, 1);
  EXPECT_TRUE(w.fell);
  EXPECT_NE(w.failure.find("step 2: the swing tip struck the ground 3e-05 m ahead of the stance "
                           "tip, 0 % of the planned 0.5 m step"),
            std::string::npos)
      << w.failure;
  EXPECT_EQ(w.max_slip, 1e-4);  // the failed step's record is kept
}

// Knee-less legs cross at mid-swing: the rigid ground's touchdown there, at the stance tip,
// leaves no consistent frictional impact. Where the tip landed says what it was: a scuff. A
// step that fell before any touchdown keeps its own failure.
TEST(AppendStep, AnImpactThatFailsAtTheStanceTipIsAScuff) {
  StepResult at_stance_tip = stepOf(1e-10);
  at_stance_tip.ok = false;
  at_stance_tip.impact = "double";
  at_stance_tip.failure = "no consistent frictional impact (no stick/slide mode satisfies Coulomb)";
  WalkResult w;
  EXPECT_FALSE(appendStep(w, at_stance_tip, 0.5));
  EXPECT_NE(w.failure.find("step 1: the swing tip struck the ground 1e-10 m ahead of the stance "
                           "tip"),
            std::string::npos)
      << w.failure;
  StepResult fallen = stepOf(0);
  fallen.ok = false;
  fallen.failure = "the hip fell below 0.5 of the leg length";
  WalkResult v;
  EXPECT_FALSE(appendStep(v, fallen, 0.5));
  EXPECT_EQ(v.failure, "step 1: the hip fell below 0.5 of the leg length");
}

}  // namespace
}  // namespace gaitopt::sim
