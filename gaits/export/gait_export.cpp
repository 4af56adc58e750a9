#include "gaits/export/gait_export.hpp"

#include <future>

#include "gaits/export/gait_summary.hpp"
#include "gaits/trajectory/grid_export.hpp"
#include "gaits/trajectory/switch_states.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "gaits/trajectory/trajectory_json.hpp"
#include "gaits/trajectory/trajectory_text.hpp"

namespace gaitopt::gaits {

size_t writeGaitExport(const std::string& dir, const Trajectory& traj, const dynamics::Model& model,
                       double rate_hz, nlohmann::ordered_json summary) {
  const GridExport grid = exportGrid(traj, rate_hz);
  const TrajectoryText text(grid.samples, grid.step_length, model);  // formatted once for both
  auto json =
      std::async(std::launch::async, [&] { writeTrajectoryJson(text, dir + "/trajectory.json"); });
  writeTrajectoryCsv(text, dir + "/trajectory.csv");
  json.get();
  summary.update(switchStatesJson(grid, model));
  writeJsonFile(summary, dir + "/summary.json");
  return grid.samples.size();
}

}  // namespace gaitopt::gaits
