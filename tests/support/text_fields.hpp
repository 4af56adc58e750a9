#pragma once
/// Splitting a line of a CSV or key file into its fields, for tests that read exported text.
#include <sstream>
#include <string>
#include <vector>

namespace gaitopt::test {

inline std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
  return parts;
}

}  // namespace gaitopt::test
