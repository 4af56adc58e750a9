#pragma once
/// @file stage_structure.hpp
/// The built problem's stages (docs/design.md#the-problems-shape): which columns (variables) and
/// rows (constraints) of the flat NLP belong to which phase, touchdown or transition of which
/// step and variant, and which stages' rows reach into which others' columns (the border
/// couplings). It is what a stage-wise KKT factorization (FATROP's per-stage blocks) needs; the
/// builder records it as it emits the stages, each contiguous in both columns and rows.
#include <string>
#include <utility>
#include <vector>

namespace gaitopt::ocp {

/// [first, first + size) of the decision vector or of the constraint rows.
struct IndexRange {
  int first = 0;
  int size = 0;

  int end() const { return first + size; }
  bool contains(int i) const { return i >= first && i < end(); }
};

enum class StageKind {
  kPhase,      ///< a collocated phase: its duration (unless shared), points and its own sets
  kTouchdown,  ///< the touchdown at the end of an SSP: impact variables and rows
  kTransition  ///< rows only: continuity, relabelling, boundary conditions, step durations
};

struct Stage {
  std::string name;  ///< the phase label, "touchdown" with its copy prefix, or the set name
  StageKind kind = StageKind::kPhase;
  int step = 0;
  int variant = 0;
  IndexRange columns;
  IndexRange rows;
  /// kPhase and kTouchdown: the phase (an index into GaitProblem::built); else -1.
  int phase = -1;
};

struct StageStructure {
  std::vector<Stage> stages;  ///< in the order the builder emitted them
  /// (a, b): rows of stage a, or Hessian entries between a and b, involve columns of stage b
  /// (a != b; a Hessian coupling may be recorded either way round).
  std::vector<std::pair<int, int>> couplings;

  /// The stage that owns column `column` / row `row`; -1 if none does.
  int stageOfColumn(int column) const;
  int stageOfRow(int row) const;
  /// Whether the builder declared that a and b meet (in either order), or a == b.
  bool coupled(int a, int b) const;
};

}  // namespace gaitopt::ocp
