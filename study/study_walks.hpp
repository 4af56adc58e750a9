#pragma once
/// @file study_walks.hpp
/// A study's closed-loop runs of each optimum: walks (`gaitopt simulate`) on plants that are
/// not its model, and sweeps (`gaitopt stability`) of where it stops walking.
#include <string>
#include <vector>

#include "study/study_points.hpp"
#include "study/study_tools.hpp"

namespace gaitopt::study {

/// Walks the optimum of `point` under each controller of `block` on each of its plants; one
/// row per walk: walk, controller, plant option, plant value, steps walked and asked, largest
/// tracking error
/// [rad], largest slip [m], failure ("" when it walked every step).
std::vector<std::vector<std::string>> walkPoint(const WalkBlock& block, const StudyPoint& point,
                                                const std::string& dir, const StudyTools& t);
std::vector<std::string> walkColumns();

/// Sweeps the optimum of `point` under each controller of `block`; one row per controller and
/// sweep: controller, sweep, nominal value, the walking interval around it (or why the nominal
/// walk fails), and the nearest values beyond it with their failures. `index` numbers the study's
/// stability blocks.
std::vector<std::vector<std::string>> sweepPoint(const StabilityBlock& block, std::size_t index,
                                                 const StudyPoint& point, const std::string& dir,
                                                 const StudyTools& t);
std::vector<std::string> sweepColumns();

}  // namespace gaitopt::study
