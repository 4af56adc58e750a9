#include "config/quantities.hpp"

#include <fmt/format.h>

#include "config/config_error.hpp"

namespace gaitopt::config {

std::string expectation(const Quantity& q) {
  return fmt::format("a number in [{:g}, {:g}]{}", q.lo, q.hi,
                     q.unit.empty() ? "" : fmt::format(" [{}]", q.unit));
}

std::string rangeError(const Quantity& q, double value) {
  if (value >= q.lo && value <= q.hi) return "";
  return fmt::format("expected {}, got {}", expectation(q), value);
}

double requireInRange(const Quantity& q, double value, const std::string& source,
                      const std::string& key) {
  if (std::string why = rangeError(q, value); !why.empty())
    throw ConfigError(source, key, 0, std::move(why));
  return value;
}

}  // namespace gaitopt::config
