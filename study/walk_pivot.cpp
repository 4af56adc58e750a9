#include "study/walk_pivot.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace gaitopt::study {
namespace {

using Row = std::vector<std::string>;

/// "20 of 20", or "3 of 20 (step 4: foot rotation)": the failure up to its detail; a walk that was
/// refused (no steps: its input did not fit) is the exit it ended with, "simulate exited 2".
std::string cell(const Table& t, const Row& r) {
  const std::string steps = r[columnOf(t, "steps")], asked = r[columnOf(t, "steps_requested")];
  const std::string failure = r[columnOf(t, "failure")];
  if (steps.empty()) return failure.substr(0, failure.find(':'));
  if (steps == asked) return steps + " of " + asked;
  const std::size_t detail = failure.find(':', failure.find(':') + 1);
  return fmt::format("{} of {} ({})", steps, asked, failure.substr(0, detail));
}

void addUnique(std::vector<std::string>& list, const std::string& value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

}  // namespace

Table walkPivot(const Table& walks, std::size_t point_columns) {
  const std::size_t plant = columnOf(walks, "plant"), option = columnOf(walks, "plant_option");
  const std::size_t keys = point_columns + 2;  // the point, walk and controller
  std::vector<std::string> plants;
  for (const Row& r : walks.rows) addUnique(plants, r[option] + " " + r[plant]);
  Table out{Row(walks.header.begin(), walks.header.begin() + keys), {}};
  out.header.insert(out.header.end(), plants.begin(), plants.end());
  for (const Row& r : walks.rows) {
    const Row key(r.begin(), r.begin() + keys);
    auto row = std::find_if(out.rows.begin(), out.rows.end(), [&](const Row& o) {
      return std::equal(key.begin(), key.end(), o.begin());
    });
    if (row == out.rows.end()) {
      out.rows.push_back(key);
      out.rows.back().resize(keys + plants.size());
      row = out.rows.end() - 1;
    }
    const auto at = std::find(plants.begin(), plants.end(), r[option] + " " + r[plant]);
    (*row)[keys + (at - plants.begin())] = cell(walks, r);
  }
  return out;
}

}  // namespace gaitopt::study
