// Grid: the points of a gait library (speed slowest, slope fastest), their folder names, their
// neighbours at corners, edges and inside, grid distance and the nearest point to given values.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "library/grid.hpp"

namespace gaitopt::library {
namespace {

/// 3 speeds x 2 step lengths x 1 slope: index = 2 * speed position + step position.
Grid grid3x2x1() {
  return Grid({{{0.4, 0.6, 0.8}, {0.3, 0.4}, {0.0}}});
}

std::vector<int> sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(Grid, SizeOrderAndNames) {
  const Grid g = grid3x2x1();
  ASSERT_EQ(g.size(), 6);
  // Speed varies slowest, slope fastest.
  EXPECT_EQ(g.point(0).name, "v0.400_L0.300_s+0.000");
  EXPECT_EQ(g.point(1).name, "v0.400_L0.400_s+0.000");
  EXPECT_EQ(g.point(2).name, "v0.600_L0.300_s+0.000");
  EXPECT_EQ(g.point(5).name, "v0.800_L0.400_s+0.000");
  for (int p = 0; p < g.size(); ++p) {
    EXPECT_EQ(g.point(p).index, p);
    EXPECT_EQ(g.point(p).at[0], p / 2);
    EXPECT_EQ(g.point(p).at[1], p % 2);
    EXPECT_EQ(g.point(p).at[2], 0);
  }
  EXPECT_DOUBLE_EQ(g.point(3).values[0], 0.6);
  EXPECT_DOUBLE_EQ(g.point(3).values[1], 0.4);
  EXPECT_THROW(g.point(6), std::out_of_range);
  // A downhill slope keeps its sign in the name; the slope varies fastest.
  const Grid s({{{0.5}, {0.35}, {-0.05, 0.0, 0.05}}});
  ASSERT_EQ(s.size(), 3);
  EXPECT_EQ(s.point(0).name, "v0.500_L0.350_s-0.050");
  EXPECT_EQ(s.point(2).name, "v0.500_L0.350_s+0.050");
}

TEST(Grid, AnEmptyAxisIsRejected) {
  EXPECT_THROW(Grid({{{0.4}, {}, {0.0}}}), std::invalid_argument);
}

TEST(Grid, NeighboursAtCornersAndEdges) {
  const Grid g = grid3x2x1();
  // (speed, step) positions: 0=(0,0) 1=(0,1) 2=(1,0) 3=(1,1) 4=(2,0) 5=(2,1).
  EXPECT_EQ(sorted(g.neighbours(0)), (std::vector<int>{1, 2}));     // corner
  EXPECT_EQ(sorted(g.neighbours(1)), (std::vector<int>{0, 3}));     // corner
  EXPECT_EQ(sorted(g.neighbours(2)), (std::vector<int>{0, 3, 4}));  // edge, middle speed
  EXPECT_EQ(sorted(g.neighbours(3)), (std::vector<int>{1, 2, 5}));
  EXPECT_EQ(sorted(g.neighbours(5)), (std::vector<int>{3, 4}));  // corner
  // A single point has none.
  EXPECT_TRUE(Grid({{{0.5}, {0.35}, {0.0}}}).neighbours(0).empty());
}

TEST(Grid, AnInsidePointHasSixNeighbours) {
  const Grid g({{{0.4, 0.5, 0.6}, {0.3, 0.35, 0.4}, {-0.05, 0.0, 0.05}}});
  ASSERT_EQ(g.size(), 27);
  // Centre (1,1,1) = 9 + 3 + 1 = 13; neighbours differ by 9, 3 or 1.
  EXPECT_EQ(sorted(g.neighbours(13)), (std::vector<int>{4, 10, 12, 14, 16, 22}));
  for (int q : g.neighbours(13)) EXPECT_DOUBLE_EQ(g.distance(13, q), 1.0);
  EXPECT_EQ(g.neighbours(0).size(), 3u);  // corner of a cube
  EXPECT_EQ(g.neighbours(1).size(), 4u);  // edge
  EXPECT_EQ(g.neighbours(4).size(), 5u);  // face centre (0,1,1)
}

TEST(Grid, DistanceCountsGridSteps) {
  const Grid g = grid3x2x1();
  EXPECT_DOUBLE_EQ(g.distance(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(g.distance(0, 1), 1.0);
  EXPECT_DOUBLE_EQ(g.distance(0, 3), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(g.distance(0, 4), 2.0);
  EXPECT_DOUBLE_EQ(g.distance(0, 5), std::sqrt(5.0));
  EXPECT_DOUBLE_EQ(g.distance(5, 0), g.distance(0, 5));
}

TEST(Grid, NearestPointAxisByAxis) {
  const Grid g = grid3x2x1();
  EXPECT_EQ(g.nearest({0.4, 0.3, 0.0}), 0);
  EXPECT_EQ(g.nearest({0.55, 0.36, 0.1}), 3);   // 0.6, 0.4
  EXPECT_EQ(g.nearest({0.69, 0.34, -0.2}), 2);  // 0.6, 0.3
  EXPECT_EQ(g.nearest({5.0, 1.0, 0.0}), 5);     // beyond the grid: its corner
  EXPECT_EQ(g.nearest({-1.0, 0.0, 0.0}), 0);
  for (int p = 0; p < g.size(); ++p) EXPECT_EQ(g.nearest(g.point(p).values), p);
}

// Names are keys: of the point folders and of index.csv's rows. Axis values closer than the
// names' 3 decimals (0.6001 and 0.6004, both "v0.600") would make two points one.
TEST(Grid, DistinctPointsHaveDistinctNamesOrTheGridIsRejected) {
  EXPECT_THROW(Grid({{{0.6001, 0.6004}, {0.35}, {0.0}}}), std::invalid_argument);
  EXPECT_NO_THROW(Grid({{{0.600, 0.601}, {0.35}, {0.0}}}));
}

// A config key is one more axis, after the walk's, varying fastest: its value is in the name
// (the folder), its steps are neighbours, and it counts in distance and nearest.
TEST(Grid, AConfigKeyIsAFourthAxis) {
  const Grid g({{{0.4, 0.6}, {0.35}, {0.0}}}, {{"constraints.friction_margin", {0.1, 0.2, 0.3}}});
  ASSERT_EQ(g.size(), 6);
  ASSERT_EQ(g.dimensions(), 4);
  EXPECT_EQ(g.axisName(3), "constraints.friction_margin");
  EXPECT_EQ(g.point(0).name, "v0.400_L0.350_s+0.000_constraints.friction_margin=0.1");
  EXPECT_EQ(g.point(4).name, "v0.600_L0.350_s+0.000_constraints.friction_margin=0.2");
  EXPECT_DOUBLE_EQ(g.point(4).values[3], 0.2);
  EXPECT_EQ(g.point(4).walk(), (std::array<double, 3>{0.6, 0.35, 0.0}));
  // (speed, margin) positions: 3 * speed + margin.
  EXPECT_EQ(sorted(g.neighbours(4)), (std::vector<int>{1, 3, 5}));
  EXPECT_DOUBLE_EQ(g.distance(0, 5), std::sqrt(1.0 + 4.0));
  EXPECT_EQ(g.nearest({0.58, 0.35, 0.0, 0.27}), 5);
  EXPECT_THROW(g.nearest({0.58, 0.35, 0.0}), std::invalid_argument);  // a value per axis
  EXPECT_THROW(Grid({{{0.4}, {0.35}, {0.0}}}, {{"cost.weight", {}}}), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::library
