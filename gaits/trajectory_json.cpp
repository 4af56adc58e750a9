#include "gaits/trajectory_json.hpp"

#include <nlohmann/json.hpp>

#include "gaits/trajectory_columns.hpp"
#include "io/checked_write.hpp"

namespace gaitopt::gaits {

void writeTrajectoryJson(const std::vector<Knot>& rows, double step_length,
                         const dynamics::Model& model, const std::string& path) {
  const std::vector<std::string> names = columnNames(model);
  const std::vector<PhysicalJoint> joints = physicalJoints(model);
  nlohmann::ordered_json data = nlohmann::ordered_json::object();
  for (const auto& name : names) data[name] = nlohmann::ordered_json::array();
  for (const Knot& knot : rows) {
    data["t"].push_back(knot.t);
    data["phase"].push_back(toString(knot.phase));
    const Eigen::VectorXd row = rowNumbers(knot, model, joints, step_length);
    for (Eigen::Index i = 0; i < row.size(); ++i)
      data[names[static_cast<size_t>(i) + 2]].push_back(row(i));
  }
  const nlohmann::ordered_json json = {
      {"robot", model.name()}, {"step_length", step_length}, {"columns", names}, {"data", data}};
  io::writeFileAtomically(path, json.dump() + "\n");
}

}  // namespace gaitopt::gaits
