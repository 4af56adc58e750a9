#include "ocp/shape/stage_structure.hpp"

#include <algorithm>

namespace gaitopt::ocp {

int StageStructure::stageOfColumn(int column) const {
  for (size_t s = 0; s < stages.size(); ++s)
    if (stages[s].columns.contains(column)) return static_cast<int>(s);
  return -1;
}

int StageStructure::stageOfRow(int row) const {
  for (size_t s = 0; s < stages.size(); ++s)
    if (stages[s].rows.contains(row)) return static_cast<int>(s);
  return -1;
}

bool StageStructure::coupled(int a, int b) const {
  if (a == b) return true;
  return std::any_of(couplings.begin(), couplings.end(), [&](const auto& c) {
    return (c.first == a && c.second == b) || (c.first == b && c.second == a);
  });
}

}  // namespace gaitopt::ocp
