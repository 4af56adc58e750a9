#include "study/study_run.hpp"

#include <mutex>

#include "parallel/parallel_for.hpp"
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

/// The rows of one point: its solve, and its walks and sweeps when it converged.
struct PointRows {
  std::vector<std::string> solve;
  std::vector<std::vector<std::string>> walks, sweeps;
};

PointRows runPoint(const StudyConfig& c, const std::vector<StudyPoint>& points, std::size_t i,
                   const std::string& dir, const StudyTools& t) {
  solvePoint(c, points, i, dir, t);
  PointRows rows{solveRow(points[i], dir), {}, {}};
  if (!solved(points[i], dir)) return rows;
  for (const WalkBlock& block : c.walks)
    for (auto& row : walkPoint(block, points[i], dir, t)) rows.walks.push_back(std::move(row));
  for (std::size_t b = 0; b < c.stability.size(); ++b)
    for (auto& row : sweepPoint(c.stability[b], b, points[i], dir, t))
      rows.sweeps.push_back(std::move(row));
  return rows;
}

/// The first point of each line: the points along the last axis follow one another (a warm
/// start needs the one before it), different lines are independent.
std::vector<std::size_t> lineStarts(const std::vector<StudyPoint>& points) {
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].previous) starts.push_back(i);
  return starts;
}

/// Every point's rows, the lines spread over `jobs` workers.
std::vector<PointRows> runPoints(const StudyConfig& c, const std::vector<StudyPoint>& points,
                                 const std::string& dir, const StudyTools& t, int jobs) {
  std::mutex print;
  StudyTools locked = t;
  if (t.progress)
    locked.progress = [&](const std::string& what) {
      const std::lock_guard<std::mutex> lock(print);
      t.progress(what);
    };
  const std::vector<std::size_t> starts = lineStarts(points);
  std::vector<PointRows> rows(points.size());
  parallel::parallelFor(starts.size(), jobs, [&](std::size_t line) {
    const std::size_t end = line + 1 < starts.size() ? starts[line + 1] : points.size();
    for (std::size_t i = starts[line]; i < end; ++i) rows[i] = runPoint(c, points, i, dir, locked);
  });
  return rows;
}

}  // namespace

StudyCounts runStudy(const StudyConfig& c, const std::string& dir, const StudyTools& t, int jobs) {
  const std::vector<StudyPoint> points = studyPoints(c);
  Table solves = tableOf(c, solveColumns()), walks = tableOf(c, walkColumns()),
        sweeps = tableOf(c, sweepColumns());
  StudyCounts counts;
  const std::vector<PointRows> rows = runPoints(c, points, dir, t, jobs);
  for (std::size_t i = 0; i < points.size(); ++i) {
    addRow(solves, points[i], rows[i].solve);
    ++counts.points;
    counts.converged += solved(points[i], dir) ? 1 : 0;
    for (const auto& row : rows[i].walks) addRow(walks, points[i], row);
    for (const auto& row : rows[i].sweeps) addRow(sweeps, points[i], row);
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
  counts.unfinished = *t.unfinished;
  return counts;
}

}  // namespace gaitopt::study
