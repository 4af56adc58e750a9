#pragma once
/// @file registry.hpp
/// A list of entries a user picks by name (the controllers of
/// sim/controllers/controller_registry.hpp, the grounds of sim/walk/ground_registry.hpp), each a
/// struct with a `name`: the names in registration order, and the lookup whose error lists every
/// registered name, so an option, a config reader and the Python module accept the same names.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace gaitopt::config {

template <class Entry>
std::vector<std::string> registeredNames(const std::vector<Entry>& entries) {
  std::vector<std::string> names;
  for (const Entry& e : entries) names.push_back(e.name);
  return names;
}

/// The entry called `name`, or null.
template <class Entry>
const Entry* findRegistered(const std::vector<Entry>& entries, const std::string& name) {
  const auto it =
      std::find_if(entries.begin(), entries.end(), [&](const Entry& e) { return e.name == name; });
  return it == entries.end() ? nullptr : &*it;
}

/// The entry called `name`. @throws std::invalid_argument "unknown KIND 'NAME' (registered:
/// a, b, c)" otherwise.
template <class Entry>
const Entry& registered(const std::vector<Entry>& entries, const std::string& name,
                        const std::string& kind) {
  if (const Entry* e = findRegistered(entries, name)) return *e;
  throw std::invalid_argument(fmt::format("unknown {} '{}' (registered: {})", kind, name,
                                          fmt::join(registeredNames(entries), ", ")));
}

}  // namespace gaitopt::config
