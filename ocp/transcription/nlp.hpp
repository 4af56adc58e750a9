#pragma once
/// @file nlp.hpp
/// A sparse nonlinear program assembled from composable pieces, in the spirit of ifopt:
/// named variable blocks, constraint sets and cost terms, each filling only its own entries of
/// the constraint Jacobian and of the Hessian of the Lagrangian. The Ipopt adapter
/// (ipopt_adapter.hpp) only translates this to Ipopt::TNLP.
///
/// Sparsity contract: every call of a set's jacobian() / hessian() emits the same sequence of
/// (row, col) positions, whatever the point (an entry that happens to be zero is still emitted).
/// The Nlp records the sequence once and afterwards only sums values into fixed slots.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace gaitopt::ocp {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// "No bound", the one definition for every bound of the NLP. Ipopt reads a bound at or beyond
/// +-1e19 as absent (its nlp_lower_bound_inf / nlp_upper_bound_inf defaults), so 1e20 is no
/// bound to the solver, yet finite: a failed folder's summary.json records the bounds of the
/// worst violation, and JSON has no infinity. Values that are really infinite (a friction
/// ratio at zero normal force, gaits/export/metrics.hpp) are
/// std::numeric_limits<double>::infinity().
inline constexpr double kInf = 1e20;

/// x[indices]: the values of a few variables of the NLP, in the order given (the arguments of a
/// set that reads scattered variables: a link constraint, a law between two phases).
inline Eigen::VectorXd gather(const Eigen::VectorXd& x, const std::vector<int>& indices) {
  Eigen::VectorXd y(static_cast<Eigen::Index>(indices.size()));
  for (size_t i = 0; i < indices.size(); ++i) y(static_cast<Eigen::Index>(i)) = x(indices[i]);
  return y;
}

/// The phase tag of sets and blocks that belong to no single phase (they link phases).
inline constexpr const char* kLinkPhase = "link";

/// A contiguous range of the decision vector.
struct VariableBlock {
  std::string name;
  int offset = 0;
  int size = 0;
  std::string phase = kLinkPhase;  ///< the phase the block belongs to (Nlp::addVariables)
  /// > 0: the block is its phase's collocation points in time order, point_size variables
  /// each (PhaseLayout::pointSize); 0: not on the time grid.
  int point_size = 0;
};

/// Where a constraint row or a variable sits on the time grid, for reports of failed solves.
struct GridNode {
  const char* kind = "";  ///< "point" (a collocation point), "segment", or "" (not on the grid)
  int index = -1;         ///< the point or segment
  int entry = -1;         ///< the row (of a set) or element (of a block) within the node
};

/// A group of constraint rows g(x) with bounds lower <= g(x) <= upper.
class ConstraintSet {
 public:
  /// @param phase  the phase whose points the rows constrain ("ssp", "dsp"), or kLinkPhase for
  ///               rows that link phases (touchdown, periodicity, durations)
  ConstraintSet(std::string name, int rows, std::string phase = kLinkPhase)
      : name_(std::move(name)), phase_(std::move(phase)), rows_(rows) {}
  virtual ~ConstraintSet() = default;
  const std::string& name() const { return name_; }
  const std::string& phase() const { return phase_; }
  int rows() const { return rows_; }
  /// Bounds of the rows (equalities: lower == upper). Default: all zero (equalities g = 0).
  virtual Eigen::VectorXd lowerBounds() const { return Eigen::VectorXd::Zero(rows_); }
  virtual Eigen::VectorXd upperBounds() const { return Eigen::VectorXd::Zero(rows_); }
  /// g(x) into `g` (size rows()).
  virtual void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const = 0;
  /// dg/dx entries: row in [0, rows()), column a global variable index.
  virtual void jacobian(const Eigen::VectorXd& x, Triplets& out) const = 0;
  /// Lower triangle (row >= col, global indices) of sum_i lambda_i d2 g_i / dx2.
  virtual void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                       Triplets& out) const = 0;
  /// The node of row `row` in [0, rows()); default: not on the time grid.
  virtual GridNode nodeOf(int /*row*/) const { return {}; }

 private:
  std::string name_;
  std::string phase_;
  int rows_;
};

/// The worst bound violation of a point among constraint rows or variables, located by the
/// set's or block's own data (its phase and nodes), so reports parse no names.
struct Violation {
  std::string name;       ///< the constraint set or variable block ("" when nothing is violated)
  std::string phase;      ///< its phase (ConstraintSet::phase, VariableBlock::phase)
  const char* part = "";  ///< what `index` and node.entry count: "row" or "element"
  int index = -1;         ///< row within the set, or element within the block
  GridNode node;          ///< where that row or element sits on the time grid
  double amount = 0;      ///< distance outside [lower, upper] (0 when within)
  double value = 0, lower = 0, upper = 0;
};

/// One line for people, e.g. "ssp_clearance (ssp, point 12, row 0): -0.031 outside [0, 1e+20]
/// by 0.031"; the index within the set or block when it is not on the grid; "none" when nothing
/// is violated.
std::string describe(const Violation& v);
/// Where alone, e.g. "ssp_clearance (ssp, point 12, row 0)" (describe's first part).
std::string whereOf(const Violation& v);

/// A term of the objective.
class CostTerm {
 public:
  explicit CostTerm(std::string name) : name_(std::move(name)) {}
  virtual ~CostTerm() = default;
  const std::string& name() const { return name_; }
  virtual double value(const Eigen::VectorXd& x) const = 0;
  /// Adds the gradient into `grad` (size n).
  virtual void gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const = 0;
  /// Lower triangle of factor * d2 value / dx2.
  virtual void hessian(const Eigen::VectorXd& x, double factor, Triplets& out) const = 0;

 private:
  std::string name_;
};

/// Triplets compressed to fixed slots: recorded once, then values are summed per slot.
class SparsityPattern {
 public:
  /// Records the positions of `entries`; duplicates share a slot, slots in order of first
  /// appearance.
  void record(const Triplets& entries);
  int nonZeros() const { return static_cast<int>(rows_.size()); }
  const std::vector<int>& rows() const { return rows_; }
  const std::vector<int>& cols() const { return cols_; }
  /// Sums the values of `entries` (same sequence as recorded) into `values` (size nonZeros()).
  /// @throws std::logic_error if the sequence length changed (a broken sparsity contract).
  void accumulate(const Triplets& entries, double* values) const;

 private:
  std::vector<int> rows_, cols_;
  std::vector<int> slot_;  // slot of the k-th recorded triplet
};

class Nlp {
 public:
  /// Adds a block of `size` variables of phase `phase`, collocation points of `point_size`
  /// variables each when point_size > 0 (VariableBlock); returns it (offset into the decision
  /// vector).
  VariableBlock addVariables(const std::string& name, int size, const Eigen::VectorXd& lower,
                             const Eigen::VectorXd& upper, const Eigen::VectorXd& initial,
                             const std::string& phase = kLinkPhase, int point_size = 0);
  void addConstraint(std::unique_ptr<ConstraintSet> set);
  void addCost(std::unique_ptr<CostTerm> term);

  int variables() const { return static_cast<int>(x0_.size()); }
  int constraints() const;
  const Eigen::VectorXd& initialGuess() const { return x0_; }
  const Eigen::VectorXd& lowerBounds() const { return xl_; }
  const Eigen::VectorXd& upperBounds() const { return xu_; }
  Eigen::VectorXd constraintLower() const;
  Eigen::VectorXd constraintUpper() const;
  const std::vector<std::unique_ptr<ConstraintSet>>& constraintSets() const { return sets_; }
  const std::vector<VariableBlock>& variableBlocks() const { return blocks_; }
  const std::vector<std::unique_ptr<CostTerm>>& costTerms() const { return costs_; }

  /// Where constraint row `row` sits: its set, phase and grid node (amounts and bounds 0).
  /// @throws std::logic_error beyond the last row
  Violation locateConstraintRow(int row) const;
  /// Where variable `i` sits: its block, phase and grid node (amounts and bounds 0).
  /// @throws std::logic_error beyond the last variable
  Violation locateVariable(int i) const;
  /// The constraint row of `x` farthest outside its bounds (the first on ties).
  Violation worstConstraint(const Eigen::VectorXd& x) const;
  /// The variable of `x` farthest outside its bounds (the first on ties).
  Violation worstBound(const Eigen::VectorXd& x) const;

  double cost(const Eigen::VectorXd& x) const;
  Eigen::VectorXd costGradient(const Eigen::VectorXd& x) const;
  Eigen::VectorXd constraintValues(const Eigen::VectorXd& x) const;
  /// Jacobian triplets with global rows, in a fixed sequence, written over `out`: a solver
  /// passes the same buffer at every iterate, so its storage is allocated once, not faulted in
  /// again at each evaluation.
  void jacobianTriplets(const Eigen::VectorXd& x, Triplets& out) const;
  Triplets jacobianTriplets(const Eigen::VectorXd& x) const;
  /// Lower-triangle Hessian triplets of obj_factor * cost + lambda^T g, in a fixed sequence,
  /// written over `out` (as jacobianTriplets).
  void hessianTriplets(const Eigen::VectorXd& x, double obj_factor, const Eigen::VectorXd& lambda,
                       Triplets& out) const;
  Triplets hessianTriplets(const Eigen::VectorXd& x, double obj_factor,
                           const Eigen::VectorXd& lambda) const;

 private:
  Eigen::VectorXd x0_, xl_, xu_;
  std::vector<VariableBlock> blocks_;
  std::vector<std::unique_ptr<ConstraintSet>> sets_;
  std::vector<std::unique_ptr<CostTerm>> costs_;
};

}  // namespace gaitopt::ocp
