// The files of a library folder (library/library_folder.hpp, library_index.hpp): library.json
// written by a run and read back by `gaitopt interpolate`, and index rows through index.csv and
// index.json, every field; and the shipped library folders keyed by the files they are made from
// now, so that `make demo-full` resumes them instead of refusing them.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "config/config_error.hpp"
#include "io/io_test_dir.hpp"
#include "io/strict_json.hpp"
#include "library/library_config.hpp"
#include "library/library_folder.hpp"

namespace gaitopt::library {
namespace {

class LibraryFolderTest : public io::test::IoTest {
 protected:
  /// A setup of the shipped RABBIT base problem over a 2 x 3 x 1 grid, in this test's folder.
  LibrarySetup setup(const std::array<std::vector<double>, 3>& axes,
                     std::vector<GridAxis> config_axes = {}) const {
    LibraryConfig config;
    config.name = "round_trip";
    config.path = path("round_trip.yaml");  // its bytes key the folder (library.json)
    put(config.path, "name: round_trip\n");
    config.ocp_path = std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml";
    config.base = ocp::loadOcpConfig(config.ocp_path);
    config.config_axes = config_axes;
    return {config, Grid(axes, std::move(config_axes)), path("lib"), {}};
  }
};

const std::array<std::vector<double>, 3> kAxes = {
    std::vector<double>{0.5, 0.7}, std::vector<double>{0.3, 0.4, 0.5}, std::vector<double>{0.0}};

TEST_F(LibraryFolderTest, LibraryJsonRoundTripsTheGridAndTheBaseProblem) {
  const LibrarySetup s = setup(kAxes);
  std::filesystem::create_directories(s.out_dir);
  claimLibraryFolder(s);
  const LibraryFolder back = readLibraryFolder(s.out_dir);
  EXPECT_EQ(back.grid.axes(), (std::vector<std::vector<double>>(kAxes.begin(), kAxes.end())));
  EXPECT_TRUE(back.grid.configAxes().empty());
  EXPECT_EQ(back.base.name, s.config.base.name);
  EXPECT_DOUBLE_EQ(back.base.step_length, s.config.base.step_length);
  // The OCP file is recorded relative to the folder, so both can move together.
  const auto json = io::readStrictJson(s.out_dir + "/library.json");
  const std::filesystem::path ocp = json.at("ocp").get<std::string>();
  EXPECT_TRUE(ocp.is_relative()) << ocp;
  EXPECT_TRUE(
      std::filesystem::equivalent(std::filesystem::path(s.out_dir) / ocp, s.config.ocp_path))
      << ocp;
}

// Two config axes listed in the order that is not alphabetical: the grid's order (which names
// and numbers the points) must come back, not the JSON object's.
TEST_F(LibraryFolderTest, LibraryJsonRoundTripsConfigAxesInTheirOrder) {
  const std::vector<GridAxis> keys = {{"constraints.zmp_margin", {0.01, 0.02}},
                                      {"constraints.friction_margin", {0.1, 0.2, 0.3}}};
  const LibrarySetup s = setup(kAxes, keys);
  std::filesystem::create_directories(s.out_dir);
  claimLibraryFolder(s);
  const LibraryFolder back = readLibraryFolder(s.out_dir);
  ASSERT_EQ(back.grid.configAxes().size(), 2u);
  EXPECT_EQ(back.grid.configAxes()[0].key, "constraints.zmp_margin");
  EXPECT_EQ(back.grid.configAxes()[1].values, keys[1].values);
  ASSERT_EQ(back.grid.size(), s.grid.size());
  for (int p = 0; p < s.grid.size(); ++p) EXPECT_EQ(back.grid.point(p).name, s.grid.point(p).name);
  // Another sweep of one key is another library.
  auto other = keys;
  other[1].values.pop_back();
  EXPECT_THROW(claimLibraryFolder(setup(kAxes, other)), config::ConfigError);
}

TEST_F(LibraryFolderTest, AnotherGridInTheSameFolderIsRefused) {
  const LibrarySetup s = setup(kAxes);
  std::filesystem::create_directories(s.out_dir);
  claimLibraryFolder(s);
  auto other = kAxes;
  other[0].push_back(0.9);
  EXPECT_THROW(claimLibraryFolder(setup(other)), config::ConfigError);
}

TEST_F(LibraryFolderTest, AFolderWithoutLibraryJsonIsNotALibrary) {
  EXPECT_THROW(readLibraryFolder(dir_.string()), config::ConfigError);
}

/// A row with every field set, a comma, a quote and a line break in the message, and NaN costs.
IndexRow awkwardRow() {
  return {"v0.500_L0.300_s+0.000",
          0.5,
          0.3,
          -0.01,
          {0.25},
          "Maximum_Iterations_Exceeded",
          false,
          12.25,
          std::nan(""),
          0.1875,
          3000,
          42.5,
          "warm:v0.700_L0.300_s+0.000,polynomial",
          "restoration failed, \"tiny step\"\nat iteration 17"};
}

void expectSameRow(const IndexRow& a, const IndexRow& b) {
  EXPECT_EQ(a.point, b.point);
  EXPECT_EQ(a.speed, b.speed);
  EXPECT_EQ(a.step_length, b.step_length);
  EXPECT_EQ(a.slope, b.slope);
  EXPECT_EQ(a.config_values, b.config_values);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.converged, b.converged);
  EXPECT_EQ(a.cost, b.cost);
  EXPECT_EQ(std::isnan(a.cost_of_transport), std::isnan(b.cost_of_transport));
  EXPECT_EQ(a.poly_cost_of_transport, b.poly_cost_of_transport);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.solve_time_s, b.solve_time_s);
  EXPECT_EQ(a.start, b.start);
}

TEST_F(LibraryFolderTest, AnIndexRowRoundTripsThroughIndexCsv) {
  const IndexRow row = awkwardRow();
  const Grid grid(kAxes, {{"constraints.friction_margin", {0.25}}});
  LibraryIndex(dir_.string(), grid).append(row);
  const auto back = LibraryIndex(dir_.string(), grid).row(row.point);
  ASSERT_TRUE(back.has_value());
  expectSameRow(*back, row);
  // One line per row: the line break of the message is written as a space.
  EXPECT_EQ(back->message, "restoration failed, \"tiny step\" at iteration 17");
}

TEST_F(LibraryFolderTest, AnIndexRowRoundTripsThroughJson) {
  const IndexRow row = awkwardRow();
  const IndexRow back = indexRowFromJson(nlohmann::json::parse(toJson(row).dump()));
  expectSameRow(back, row);
  EXPECT_EQ(back.message, row.message);
  EXPECT_TRUE(toJson(row).at("cost_of_transport").is_null());  // JSON has no NaN
}

TEST(ShippedLibraries, AreKeyedByTheCurrentContentsOfTheirFiles) {
  // A file edited since a library was made (a comment included) makes `gaitopt library` refuse
  // to resume its folder: results/ must be remade, or its key renewed when the edit changes no
  // value. Each folder's library.json against the claim a rerun into it would make (the rate is
  // the run's command line, so it is taken from the record).
  namespace fs = std::filesystem;
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(GAITOPT_SOURCE_DIR) / "results")) {
    const fs::path json = entry.path() / "library.json";
    if (!fs::exists(json)) continue;
    SCOPED_TRACE(json.string());
    const nlohmann::ordered_json recorded = io::readStrictJson(json.string());
    const fs::path config_path = fs::path(GAITOPT_SOURCE_DIR) / "configs" / "library" /
                                 (recorded.at("name").get<std::string>() + ".yaml");
    LibraryConfig config = loadLibraryConfig(config_path.string());
    Grid grid(config.axes, config.config_axes);
    const LibrarySetup rerun{
        std::move(config),
        std::move(grid),
        entry.path().string(),
        {config_path.string(), recorded.at("rate_hz").get<double>(), {}, {}, {}}};
    EXPECT_EQ(libraryClaim(rerun).dump(1), recorded.dump(1));
    ++checked;
  }
  // library_mu2004, library_cot_speed_mu2004, library_slope_mu2004, library_ensemble_mu2004
  EXPECT_EQ(checked, 4);
}

}  // namespace
}  // namespace gaitopt::library
