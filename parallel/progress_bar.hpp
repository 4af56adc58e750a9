#pragma once
/// @file progress_bar.hpp
/// The progress line of long commands on stderr: "LABEL [#####.....]  45% 18900/42000, 1m20s
/// elapsed, about 1m38s left".
#include <string>

#include "parallel/parallel_for.hpp"

namespace gaitopt::parallel {

/// The line after `elapsed_s` seconds with `done` of `total` done; the time left is the rate so
/// far carried to the end (none before the first is done).
std::string progressText(const std::string& label, std::size_t done, std::size_t total,
                         double elapsed_s);

/// A progress function under `label`; an empty function when `quiet`. On a terminal the line is
/// redrawn in place when the count changes; to a file (a log of an overnight run) a line is
/// written at most once a minute, and at the end.
ProgressFn progressBar(const std::string& label, bool quiet);

}  // namespace gaitopt::parallel
