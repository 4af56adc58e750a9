#pragma once
/// @file number_text.hpp
/// Numbers as text for the 1 kHz exports (trajectory.csv, trajectory.json): the shortest decimal
/// that reads back as exactly the same double, so a file round-trips bit for bit. std::to_chars
/// (libstdc++'s Ryu) writes it in half the time of fmt's "{}" and a third of "{:.17g}", which was
/// most of the cost of writing a result folder.
#include <charconv>
#include <string>

namespace gaitopt::io {

/// Appends the shortest exact text of `value` ("nan", "inf" and "-inf" where it is not finite).
inline void appendShortest(std::string& out, double value) {
  char text[32];  // the longest shortest form, "-2.2250738585072014e-308", has 24
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  out.append(text, end);
}

}  // namespace gaitopt::io
