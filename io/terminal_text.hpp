#pragma once
/// @file terminal_text.hpp
/// Text from files (a CSV header, a JSON key) shown on a terminal: control bytes (ESC sequences
/// could move the cursor, retitle the window or hide the rest of a message) become \xNN.
#include <cstddef>
#include <string>
#include <string_view>

namespace gaitopt::io {

/// `text` with every C0 control byte but newline and tab, and DEL, written as \xNN.
std::string printable(std::string_view text);

/// "1 step", "2 steps": `n` and `noun`, with an s unless n is 1 (nouns whose plural adds one).
std::string counted(std::size_t n, std::string_view noun);

}  // namespace gaitopt::io
