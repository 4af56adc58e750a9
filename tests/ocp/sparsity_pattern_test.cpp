// SparsityPattern: duplicates share a slot, slots keep the order of first appearance (the order
// Ipopt and MUMPS see, on which the iterates depend), and values are summed per slot.
#include <gtest/gtest.h>

#include "ocp/transcription/nlp.hpp"

namespace gaitopt::ocp {
namespace {

Triplets entries(const std::vector<double>& values) {
  const std::vector<std::pair<int, int>> at = {{2, 1}, {0, 0}, {2, 1}, {1, 0}, {0, 0}, {2, 1}};
  Triplets t;
  for (size_t k = 0; k < at.size(); ++k) t.emplace_back(at[k].first, at[k].second, values[k]);
  return t;
}

TEST(SparsityPattern, DuplicatesShareASlotInOrderOfFirstAppearance) {
  SparsityPattern p;
  p.record(entries({0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(p.nonZeros(), 3);
  EXPECT_EQ(p.rows(), (std::vector<int>{2, 0, 1}));
  EXPECT_EQ(p.cols(), (std::vector<int>{1, 0, 0}));
  std::vector<double> values(3);
  p.accumulate(entries({1, 2, 4, 8, 16, 32}), values.data());
  EXPECT_EQ(values, (std::vector<double>{1 + 4 + 32, 2 + 16, 8}));
  Triplets shorter = entries({1, 2, 4, 8, 16, 32});
  shorter.pop_back();
  EXPECT_THROW(p.accumulate(shorter, values.data()), std::logic_error);
}

}  // namespace
}  // namespace gaitopt::ocp
