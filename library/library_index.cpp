#include "library/library_index.hpp"

#include <cmath>

#include <fmt/format.h>

namespace gaitopt::library {
namespace {

/// The columns: the point, its value on every axis, then what its solve gave.
io::Row header(const Grid& grid) {
  io::Row h = {"point"};
  for (int a = 0; a < grid.dimensions(); ++a) h.push_back(grid.axisName(a));
  for (const char* c : {"status", "converged", "cost", "cost_of_transport",
                        "poly_cost_of_transport", "iterations", "solve_time_s", "start", "message"})
    h.emplace_back(c);
  return h;
}

std::string number(double v) {
  return std::isfinite(v) ? fmt::format("{:.12g}", v) : "nan";
}

io::Row fields(const IndexRow& r) {
  io::Row f = {r.point, number(r.speed), number(r.step_length), number(r.slope)};
  for (double v : r.config_values) f.push_back(number(v));
  for (std::string v : {r.status, std::string(r.converged ? "1" : "0"), number(r.cost),
                        number(r.cost_of_transport), number(r.poly_cost_of_transport),
                        std::to_string(r.iterations), number(r.solve_time_s), r.start, r.message})
    f.push_back(std::move(v));
  return f;
}

std::optional<IndexRow> parse(const io::Row& f, std::size_t config_axes) {
  try {
    IndexRow r;
    r.point = f.at(0);
    r.speed = std::stod(f.at(1));
    r.step_length = std::stod(f.at(2));
    r.slope = std::stod(f.at(3));
    std::size_t k = 4;
    for (; k < 4 + config_axes; ++k) r.config_values.push_back(std::stod(f.at(k)));
    r.status = f.at(k);
    r.converged = f.at(k + 1) == "1";
    r.cost = std::stod(f.at(k + 2));
    r.cost_of_transport = std::stod(f.at(k + 3));
    r.poly_cost_of_transport = std::stod(f.at(k + 4));
    r.iterations = std::stoi(f.at(k + 5));
    r.solve_time_s = std::stod(f.at(k + 6));
    r.start = f.at(k + 7);
    r.message = f.at(k + 8);
    return r;
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

LibraryIndex::LibraryIndex(const std::string& dir, const Grid& grid)
    : config_axes_(grid.configAxes().size()), log_(dir + "/index.csv", header(grid)) {}

std::optional<IndexRow> LibraryIndex::row(const std::string& point) const {
  const auto it = log_.rows().find(point);
  if (it == log_.rows().end()) return std::nullopt;
  return parse(it->second, config_axes_);
}

void LibraryIndex::append(const IndexRow& row) {
  log_.append(fields(row));
}

nlohmann::ordered_json toJson(const IndexRow& r) {
  nlohmann::ordered_json j = {
      {"point", r.point}, {"speed", r.speed}, {"step_length", r.step_length}, {"slope", r.slope}};
  if (!r.config_values.empty()) j["config_values"] = r.config_values;
  j.update(nlohmann::ordered_json{{"status", r.status},
                                  {"converged", r.converged},
                                  {"cost", jsonNumber(r.cost)},
                                  {"cost_of_transport", jsonNumber(r.cost_of_transport)},
                                  {"poly_cost_of_transport", jsonNumber(r.poly_cost_of_transport)},
                                  {"iterations", r.iterations},
                                  {"solve_time_s", r.solve_time_s},
                                  {"start", r.start},
                                  {"message", r.message}});
  return j;
}

IndexRow indexRowFromJson(const nlohmann::json& j) {
  return {j.at("point").get<std::string>(),
          j.at("speed").get<double>(),
          j.at("step_length").get<double>(),
          j.at("slope").get<double>(),
          j.value("config_values", std::vector<double>{}),
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
  for (int a = 0; a < grid.dimensions(); ++a) axes[grid.axisName(a)] = grid.axes()[a];
  return {{"axes", axes},
          {"points_total", grid.size()},
          {"points_solved", solved},
          {"points_failed", failed},
          {"points", points}};
}

}  // namespace gaitopt::library
