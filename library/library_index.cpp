#include "library/library_index.hpp"

#include <cmath>

#include <fmt/format.h>

namespace gaitopt::library {
namespace {

const io::Row kHeader = {"point",
                         "speed",
                         "step_length",
                         "slope",
                         "status",
                         "converged",
                         "cost",
                         "cost_of_transport",
                         "poly_cost_of_transport",
                         "iterations",
                         "solve_time_s",
                         "start",
                         "message"};

std::string number(double v) {
  return std::isfinite(v) ? fmt::format("{:.12g}", v) : "nan";
}

io::Row fields(const IndexRow& r) {
  return {r.point,
          number(r.speed),
          number(r.step_length),
          number(r.slope),
          r.status,
          r.converged ? "1" : "0",
          number(r.cost),
          number(r.cost_of_transport),
          number(r.poly_cost_of_transport),
          std::to_string(r.iterations),
          number(r.solve_time_s),
          r.start,
          r.message};
}

std::optional<IndexRow> parse(const io::Row& f) {
  try {
    return IndexRow{f[0],
                    std::stod(f[1]),
                    std::stod(f[2]),
                    std::stod(f[3]),
                    f[4],
                    f[5] == "1",
                    std::stod(f[6]),
                    std::stod(f[7]),
                    std::stod(f[8]),
                    std::stoi(f[9]),
                    std::stod(f[10]),
                    f[11],
                    f[12]};
  } catch (const std::exception&) {
    return std::nullopt;  // a foreign row: the point is redone
  }
}

/// JSON has no NaN: a missing number is null.
nlohmann::ordered_json jsonNumber(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
}

double numberFromJson(const nlohmann::json& j) {
  return j.is_null() ? std::nan("") : j.get<double>();
}

}  // namespace

LibraryIndex::LibraryIndex(const std::string& dir) : log_(dir + "/index.csv", kHeader) {}

std::optional<IndexRow> LibraryIndex::row(const std::string& point) const {
  const auto it = log_.rows().find(point);
  if (it == log_.rows().end()) return std::nullopt;
  return parse(it->second);
}

void LibraryIndex::append(const IndexRow& row) {
  log_.append(fields(row));
}

nlohmann::ordered_json toJson(const IndexRow& r) {
  return {{"point", r.point},
          {"speed", r.speed},
          {"step_length", r.step_length},
          {"slope", r.slope},
          {"status", r.status},
          {"converged", r.converged},
          {"cost", jsonNumber(r.cost)},
          {"cost_of_transport", jsonNumber(r.cost_of_transport)},
          {"poly_cost_of_transport", jsonNumber(r.poly_cost_of_transport)},
          {"iterations", r.iterations},
          {"solve_time_s", r.solve_time_s},
          {"start", r.start},
          {"message", r.message}};
}

IndexRow indexRowFromJson(const nlohmann::json& j) {
  return {j.at("point").get<std::string>(),
          j.at("speed").get<double>(),
          j.at("step_length").get<double>(),
          j.at("slope").get<double>(),
          j.at("status").get<std::string>(),
          j.at("converged").get<bool>(),
          numberFromJson(j.at("cost")),
          numberFromJson(j.at("cost_of_transport")),
          numberFromJson(j.at("poly_cost_of_transport")),
          j.at("iterations").get<int>(),
          j.at("solve_time_s").get<double>(),
          j.at("start").get<std::string>(),
          j.at("message").get<std::string>()};
}

nlohmann::ordered_json LibraryIndex::json(const Grid& grid) const {
  auto points = nlohmann::ordered_json::array();
  int solved = 0, failed = 0;
  for (int p = 0; p < grid.size(); ++p) {
    const auto r = row(grid.point(p).name);
    if (!r) continue;
    (r->converged ? solved : failed) += 1;
    points.push_back(toJson(*r));
  }
  nlohmann::ordered_json axes;
  for (int a = 0; a < 3; ++a) axes[kAxisNames[a]] = grid.axes()[a];
  return {{"axes", axes},
          {"points_total", grid.size()},
          {"points_solved", solved},
          {"points_failed", failed},
          {"points", points}};
}

}  // namespace gaitopt::library
