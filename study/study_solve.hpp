#pragma once
/// @file study_solve.hpp
/// One solve of a study: `gaitopt optimize` of a point's config with its `--set` values.
#include <string>
#include <vector>

#include "study/study_points.hpp"
#include "study/study_tools.hpp"

namespace gaitopt::study {

/// DIR/runs/FOLDER (or FOLDER.failed) holds the optimum of points[i]. With `warm_start:
/// previous` the point is also solved from the optimum of its previous point, and the cheaper
/// optimum kept; with `previous_only` it is solved from that optimum alone, from the guess when
/// the previous point did not converge (DIR/runs/FOLDER.start says which start it came from).
void solvePoint(const StudyConfig& c, const std::vector<StudyPoint>& points, std::size_t i,
                const std::string& dir, const StudyTools& t);

/// The names of solveRow's fields.
std::vector<std::string> solveColumns();

/// status, converged, iterations, cost, time, the KKT counts, the posture, the start of the
/// solve of `point` and its folder under DIR/runs/ (the status "no summary" when the solver
/// wrote none).
std::vector<std::string> solveRow(const StudyPoint& point, const std::string& dir);

/// DIR/runs/FOLDER, the folder of the point's optimum when it converged.
std::string gaitFolder(const StudyPoint& point, const std::string& dir);

/// Whether DIR/runs/FOLDER holds a converged optimum.
bool solved(const StudyPoint& point, const std::string& dir);

}  // namespace gaitopt::study
