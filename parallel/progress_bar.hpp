#pragma once
/// @file progress_bar.hpp
/// The progress line of long commands on stderr: "LABEL [#####.....]  45% 18900/42000".
#include <string>

#include "parallel/parallel_for.hpp"

namespace gaitopt::parallel {

/// A progress function drawing the bar under `label`; an empty function when `quiet`.
ProgressFn progressBar(const std::string& label, bool quiet);

}  // namespace gaitopt::parallel
