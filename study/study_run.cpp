#include "study/study_run.hpp"

#include "study/axis_summary.hpp"
#include "study/study_points.hpp"
#include "study/study_solve.hpp"
#include "study/study_table.hpp"
#include "study/study_walks.hpp"
#include "study/walk_pivot.hpp"

namespace gaitopt::study {
namespace {

/// gait, then one column per axis.
std::vector<std::string> pointColumns(const StudyConfig& c) {
  std::vector<std::string> columns = {"gait"};
  for (const StudyAxis& axis : c.axes) columns.push_back(axis.name);
  return columns;
}

std::vector<std::string> pointFields(const StudyPoint& p) {
  std::vector<std::string> fields = {p.gait};
  fields.insert(fields.end(), p.labels.begin(), p.labels.end());
  return fields;
}

Table tableOf(const StudyConfig& c, const std::vector<std::string>& columns) {
  Table table{pointColumns(c), {}};
  table.header.insert(table.header.end(), columns.begin(), columns.end());
  return table;
}

void addRow(Table& table, const StudyPoint& p, const std::vector<std::string>& fields) {
  std::vector<std::string> row = pointFields(p);
  row.insert(row.end(), fields.begin(), fields.end());
  table.rows.push_back(std::move(row));
}

void writeBoth(const Table& table, const std::string& stem) {
  writeCsv(table, stem + ".csv");
  writeMarkdown(table, stem + ".md");
}

}  // namespace

StudyCounts runStudy(const StudyConfig& c, const std::string& dir, const StudyTools& t) {
  const std::vector<StudyPoint> points = studyPoints(c);
  Table solves = tableOf(c, solveColumns()), walks = tableOf(c, walkColumns()),
        sweeps = tableOf(c, sweepColumns());
  StudyCounts counts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    solvePoint(c, points, i, dir, t);
    addRow(solves, points[i], solveRow(points[i], dir));
    ++counts.points;
    if (!solved(points[i], dir)) continue;
    ++counts.converged;
    for (const WalkBlock& block : c.walks)
      for (const auto& row : walkPoint(block, points[i], dir, t)) addRow(walks, points[i], row);
    for (std::size_t b = 0; b < c.stability.size(); ++b)
      for (const auto& row : sweepPoint(c.stability[b], b, points[i], dir, t))
        addRow(sweeps, points[i], row);
  }
  writeBoth(solves, dir + "/solves");
  writeMarkdown(axisSummary(c, solves), dir + "/by_axis.md");
  counts.walks = static_cast<int>(walks.rows.size());
  counts.sweeps = static_cast<int>(sweeps.rows.size());
  if (!c.walks.empty()) {
    writeBoth(walks, dir + "/walks");
    writeMarkdown(walkPivot(walks, 1 + c.axes.size()), dir + "/walks_by_plant.md");
  }
  if (!c.stability.empty()) writeBoth(sweeps, dir + "/stability");
  return counts;
}

}  // namespace gaitopt::study
