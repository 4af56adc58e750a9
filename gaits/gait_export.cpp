#include "gaits/gait_export.hpp"

#include "gaits/gait_summary.hpp"
#include "gaits/grid_export.hpp"
#include "gaits/switch_states.hpp"
#include "gaits/trajectory_csv.hpp"
#include "gaits/trajectory_json.hpp"

namespace gaitopt::gaits {

size_t writeGaitExport(const std::string& dir, const Trajectory& traj, const dynamics::Model& model,
                       double rate_hz, nlohmann::ordered_json summary) {
  const GridExport grid = exportGrid(traj, rate_hz);
  writeTrajectoryCsv(grid.samples, grid.step_length, model, dir + "/trajectory.csv");
  writeTrajectoryJson(grid.samples, grid.step_length, model, dir + "/trajectory.json");
  summary.update(switchStatesJson(grid, model));
  writeJsonFile(summary, dir + "/summary.json");
  return grid.samples.size();
}

}  // namespace gaitopt::gaits
