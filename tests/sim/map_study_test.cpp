// A 2-D stability map (sim/studies/map_study.hpp) on made-up rows: the largest all-walking
// rectangle, the walking region's counts and per-row intervals, and the map file's rows keyed by
// both values across a reopen (a resumed run skips exactly the finished points).
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "sim/studies/map_study.hpp"

namespace gaitopt::sim {
namespace {

const SweepParameter kPush{config::kPush, "hip impulse", -1, 1, 3, false};
const SweepParameter kMass{config::kMassError, "mass error", -0.1, 0.1, 3, false};

/// '#' walks, '.' falls; rows are values of a, columns values of b.
std::vector<std::vector<bool>> grid(const std::vector<std::string>& text) {
  std::vector<std::vector<bool>> g;
  for (const auto& line : text) {
    g.emplace_back();
    for (char c : line) g.back().push_back(c == '#');
  }
  return g;
}

TEST(LargestWalkingRectangle, FindsTheBiggestBlockAnywhereAndAroundAPoint) {
  const auto walks = grid({"#....",  //
                           "##.##",  //
                           "##.##",  //
                           "##.##",  //
                           "....#"});
  const GridRectangle any = largestWalkingRectangle(walks);
  EXPECT_EQ(any.points(), 6);  // rows 1-3, columns 0-1 (found before columns 3-4)
  EXPECT_EQ(any.a_first, 1);
  EXPECT_EQ(any.a_last, 3);
  EXPECT_EQ(any.b_first, 0);
  EXPECT_EQ(any.b_last, 1);
  const GridRectangle right = largestWalkingRectangle(walks, 2, 4);
  EXPECT_EQ(right.points(), 6);
  EXPECT_EQ(right.b_first, 3);
  const GridRectangle corner = largestWalkingRectangle(walks, 4, 4);
  EXPECT_EQ(corner.points(), 4);                                // column 4, rows 1-4
  EXPECT_EQ(largestWalkingRectangle(walks, 4, 0).points(), 0);  // that point falls
}

SweepRow row(double a, double b, bool walks) {
  SweepRow r{a, walks ? 20 : 3, 20, !walks, walks ? "" : "step 4: fall"};
  r.value_b = b;
  return r;
}

TEST(WalkingRegion, CountsPointsAndGivesEachRowItsInterval) {
  const MapParameter a{&kPush, {-1, 0, 1}, 0}, b{&kMass, {-0.1, 0, 0.1}, 0};
  std::map<std::string, SweepRow> rows;
  const auto walks = grid({"...",  //
                           "##.",  //
                           ".##"});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      rows[SweepFile::key(a.values[i], b.values[j])] = row(a.values[i], b.values[j], walks[i][j]);
  const auto j = walkingRegion(a, b, rows);
  EXPECT_EQ(j.at("points"), 9);
  EXPECT_EQ(j.at("a").at("geometric"), false);  // the picture's axis: linear, or log if true
  EXPECT_EQ(j.at("points_walked"), 4);
  EXPECT_TRUE(j.at("nominal_walks"));
  EXPECT_TRUE(j.at("per_row")[0].at("walks_from").is_null());
  EXPECT_EQ(j.at("per_row")[1].at("walks_from"), -0.1);
  EXPECT_EQ(j.at("per_row")[1].at("walks_to"), 0.0);
  EXPECT_EQ(j.at("per_row")[2].at("walks_to"), 0.1);
  const auto& r = j.at("largest_rectangle_around_nominal");
  EXPECT_EQ(r.at("points"), 2);  // (0, -0.1)-(0, 0) and (0, 0)-(1, 0) tie: the first found
  EXPECT_EQ(r.at("a_from"), 0.0);
  EXPECT_EQ(r.at("b_from"), -0.1);
  // A missing point counts as not walking.
  rows.erase(SweepFile::key(0.0, 0.0));
  EXPECT_FALSE(walkingRegion(a, b, rows).at("nominal_walks"));
}

TEST(SweepFile, MapRowsAreKeyedByBothValuesAcrossAReopen) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("gaitopt_map_" + std::to_string(::getpid()) + ".csv"))
                               .string();
  std::filesystem::remove(path);
  {
    SweepFile file(path, {"push", "mass_error"});
    file.append(row(0.25, -0.025, true));
    file.append(row(0.25, 0, false));
  }
  std::ofstream(path, std::ios::app) << "0.5,0,3,20,1,\"step";  // torn by a kill
  const SweepFile back(path, {"push", "mass_error"});
  EXPECT_EQ(back.rows().size(), 2u);
  EXPECT_TRUE(back.has(0.25, -0.025));
  EXPECT_TRUE(back.has(0.25, 0));
  EXPECT_FALSE(back.has(0.5, 0));
  const SweepRow& r = back.rows().at(SweepFile::key(0.25, 0));
  EXPECT_EQ(r.value, 0.25);
  EXPECT_EQ(r.value_b, 0.0);
  EXPECT_EQ(r.steps_completed, 3);
  EXPECT_EQ(r.failure, "step 4: fall");
  std::filesystem::remove(path);
}

// A resumed run reads its rows back at the file's 10 digits; on the grid they stand at the
// grid's own values, as the run that walked them had them (a resumed stability summary said
// 0.4842105263 where the uninterrupted one said 0.4842105263157894).
TEST(SweepFile, RowsOnTheGridStandAtTheGridsValues) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("gaitopt_sweep_" + std::to_string(::getpid()) + ".csv"))
                               .string();
  std::filesystem::remove(path);
  const double value = 0.4842105263157894, other = 0.1 + 0.2;
  {
    SweepFile file(path, {"friction"});
    file.append(row(value, 0, true));
    file.append(row(other, 0, true));
  }
  const SweepFile back(path, {"friction"});
  EXPECT_EQ(back.rows().at(SweepFile::key(value)).value, 0.4842105263);
  const auto on_grid = back.rowsAt({value, 0.7});  // 0.7 not walked, `other` not asked
  ASSERT_EQ(on_grid.size(), 1u);
  EXPECT_EQ(on_grid.at(SweepFile::key(value)).value, value);
  std::filesystem::remove(path);
  {
    SweepFile map(path, {"push", "mass_error"});
    map.append(row(value, other, true));
  }
  const SweepFile map_back(path, {"push", "mass_error"});
  const SweepRow r = map_back.rowsAt({value}, {other}).at(SweepFile::key(value, other));
  EXPECT_EQ(r.value, value);
  EXPECT_EQ(r.value_b, other);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace gaitopt::sim
