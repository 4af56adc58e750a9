#pragma once
/// @file exact_export.hpp
/// Issue 34's checks of a dense export (gaits/export/export_checks.hpp), asserted where a shipped
/// optimum is held to them: the double support's tip within 1e-6 m of its point, and the rates and
/// accelerations within 0.2 % and 1 % of their peaks of the differences of the angles and rates.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "dynamics/model.hpp"
#include "gaits/export/export_checks.hpp"
#include "gaits/export/export_contract.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::test {

/// Records the three figures as the test's `drift_rates_accelerations` and expects each within
/// its bound.
inline void expectExactBetweenThePoints(const gaits::Trajectory& dense,
                                        const dynamics::Model& model) {
  const double drift = gaits::maxDspTipDrift(dense, model);
  const double rates = gaits::maxRateMismatch(dense);
  const double accelerations = gaits::maxAccelerationMismatch(dense);
  ::testing::Test::RecordProperty("drift_rates_accelerations",
                                  fmt::format("{:.2e} {:.4f} {:.4f}", drift, rates, accelerations));
  EXPECT_LT(drift, gaits::kMaxDspTipDrift);
  EXPECT_LT(rates, gaits::kMaxRateMismatch);
  EXPECT_LT(accelerations, gaits::kMaxAccelerationMismatch);
}

}  // namespace gaitopt::test
