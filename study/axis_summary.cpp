#include "study/axis_summary.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include <fmt/format.h>

namespace gaitopt::study {
namespace {

using Row = std::vector<std::string>;

double valueOf(const Row& row, std::size_t column) {
  return row[column].empty() ? 0.0 : std::stod(row[column]);
}

std::string median(std::vector<double> v) {
  if (v.empty()) return "";
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return fmt::format("{:.4g}", n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

/// The largest spread (max - min) / |min| of the converged costs of any one gait.
double largestSpread(const std::vector<std::pair<std::string, double>>& costs) {
  double spread = 0;
  for (const auto& [gait, cost] : costs) {
    double lo = cost, hi = cost;
    for (const auto& [other, c] : costs)
      if (other == gait) lo = std::min(lo, c), hi = std::max(hi, c);
    spread = std::max(spread, (hi - lo) / std::abs(lo));
  }
  return spread;
}

/// converged, median iterations, median time, MUMPS's share, the largest spread of one gait's
/// optima.
Row figures(const Table& t, const std::vector<const Row*>& rows) {
  const std::size_t ok = columnOf(t, "converged"), it = columnOf(t, "iterations"),
                    time = columnOf(t, "wall_time_s"), cost = columnOf(t, "cost"),
                    fact = columnOf(t, "factorizations"), mumps = columnOf(t, "mumps_fallbacks");
  std::vector<double> iterations, times;
  std::vector<std::pair<std::string, double>> costs;  // gait, cost of each converged solve
  double factorizations = 0, fallbacks = 0;
  for (const Row* r : rows) {
    iterations.push_back(valueOf(*r, it));
    times.push_back(valueOf(*r, time));
    factorizations += valueOf(*r, fact);
    fallbacks += valueOf(*r, mumps);
    if ((*r)[ok] == "1") costs.emplace_back((*r)[0], valueOf(*r, cost));
  }
  return {fmt::format("{} of {}", costs.size(), rows.size()), median(iterations), median(times),
          factorizations > 0 ? fmt::format("{:.1f} %", 100 * fallbacks / factorizations) : "",
          costs.empty() ? "" : fmt::format("{:.2f} %", 100 * largestSpread(costs))};
}

void addGroup(Table& out, const Table& solves, const std::string& what, std::size_t column,
              const std::string& value) {
  std::vector<const Row*> rows;
  for (const Row& r : solves.rows)
    if (r[column] == value) rows.push_back(&r);
  Row row = {what, value};
  for (std::string& f : figures(solves, rows)) row.push_back(std::move(f));
  out.rows.push_back(std::move(row));
}

std::vector<std::string> distinct(const Table& t, std::size_t column) {
  std::vector<std::string> values;
  for (const Row& r : t.rows)
    if (std::find(values.begin(), values.end(), r[column]) == values.end())
      values.push_back(r[column]);
  return values;
}

}  // namespace

Table axisSummary(const StudyConfig& c, const Table& solves) {
  Table out{{"of", "value", "converged", "median iterations", "median solve s",
             "KKT factorizations left to MUMPS", "largest spread of a gait's optima"},
            {}};
  for (const std::string& gait : distinct(solves, 0)) addGroup(out, solves, "gait", 0, gait);
  for (std::size_t a = 0; a < c.axes.size(); ++a)
    for (const std::string& label : c.axes[a].labels)
      addGroup(out, solves, c.axes[a].name, a + 1, label);
  return out;
}

}  // namespace gaitopt::study
