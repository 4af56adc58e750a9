#pragma once
/// @file ipopt_adapter.hpp
/// Solves an Nlp with Ipopt (Debian's coinor-libipopt, MUMPS). The adapter only translates:
/// bounds, the fixed sparsity patterns recorded at the initial guess, values, and the final
/// status. Every option comes from SolverOptions (no silent defaults).
#include <string>

#include <Eigen/Core>

#include "ocp/solve/kkt/kkt_statistics.hpp"
#include "ocp/transcription/nlp.hpp"

namespace gaitopt::ocp {

struct SolverOptions {
  double tolerance = 1e-6;  ///< Ipopt tol: the scaled optimality error (dual, complementarity)
  /// Ipopt constr_viol_tol: the largest unscaled constraint violation a solution may keep. Its
  /// own check beside `tolerance`, so a loose optimality tolerance leaves feasibility tight.
  double constraint_tolerance = 1e-4;
  int max_iterations = 500;       ///< Ipopt max_iter
  std::string hessian = "exact";  ///< "exact" or "limited-memory"
  /// "exact", or "finite-difference-values": Ipopt differences the constraints itself on our
  /// sparsity pattern (for comparison only)
  std::string jacobian = "exact";
  /// "ldl": gaitopt's block LDL^T with 2x2 pivots on matched constraint rows (ocp/solve/kkt/),
  /// which Ipopt loads as its Pardiso, and which hands a matrix its static pivots fail on to MUMPS;
  /// or "mumps" (Debian's Ipopt ships it) for every matrix. ldl: the five-link default and
  /// RABBIT in about 0.6 of MUMPS's time, same iterations and optimum; on path-sensitive
  /// problems it converges about as often (results/solve_profile.md, solver_robustness.csv)
  std::string linear_solver = "ldl";
  std::string mu_strategy = "adaptive";  ///< barrier update: "monotone" or "adaptive"
  double mu_init = 0.1;                  ///< initial barrier parameter
  double bound_push = 0.01;              ///< how far Ipopt moves the start inside the bounds
  double bound_frac = 0.01;              ///< the same, relative to the bound interval
  /// Initial bound multipliers: "constant" (all 1) or "mu-based" (mu_init / slack, so the
  /// start is on the central path of mu_init)
  std::string bound_mult_init_method = "constant";
  /// Ipopt's constr_mult_init_max: a cold start's constraint multipliers are Ipopt's
  /// least-squares estimates if none exceeds this, else 0; 0 skips the estimate, a linear solve
  /// on a matrix of its own (a warm start keeps the multipliers it is given)
  double constr_mult_init_max = 1000;
  /// Ipopt's min_refinement_steps: refinement steps Ipopt takes on every solution of the full
  /// primal-dual system, each a residual and one more back-solve, before it checks the residual
  /// ratio. `ldl` refines each solution to that ratio itself (kkt_solver.hpp), so 0 leaves
  /// Ipopt only the check; 1 is Ipopt's default, kept where a path-sensitive solve would move
  int min_refinement_steps = 1;
  /// MUMPS fill-reducing ordering (ICNTL(7)): 0 AMD, 2 AMF, 3 SCOTCH, 4 PORD, 5 METIS, 6 QAMD,
  /// 7 MUMPS chooses. AMD: 0.77 of the CPU time of a whole five-link solve against MUMPS's own
  /// choice, 0.91 on RABBIT, same iterations (results/solve_profile.md). With "mumps" only: the
  /// matrices "ldl" hands MUMPS are ordered by AMD (ocp/solve/kkt/mumps_factor.cpp), since Ipopt's
  /// Pardiso door carries no MUMPS option
  int mumps_pivot_order = 0;
  std::string nlp_scaling_method = "gradient-based";  ///< or "none"
  int print_level = 0;                                ///< 0 silent ... 5 Ipopt's iteration table
  bool progress = false;                              ///< one line per iteration on stdout (ours)
};

/// Where a solve's time went and how large its linear systems were (bench/solve_profile.cpp).
struct SolveProfile {
  /// Numerical factorizations of the KKT matrix: counted by gaitopt's KKT solver with
  /// `linear_solver: ldl`; with "mumps" from Ipopt's MUMPS interface's journal, the only place
  /// Ipopt 3.11 announces them.
  int factorizations = 0;
  /// What gaitopt's KKT solver counted (ocp/solve/kkt/kkt_statistics.hpp): its factorizations
  /// and those MUMPS made for it, by reason; all 0 with "mumps".
  kkt::KktStatistics ldl;
  /// Iterations whose step needed Ipopt's inertia correction (a Hessian regularization
  /// delta_w > 0, Waechter and Biegler 2006 sec. 3.1): a linear solver that miscounts the
  /// inertia raises it.
  int inertia_corrections = 0;
  double sparsity_time_s = 0;       ///< recording the Jacobian and Hessian patterns
  double linear_solver_time_s = 0;  ///< factorizations and back-solves of the KKT system (wall)
  /// The augmented system Ipopt factorises: variables, constraint rows and one slack per
  /// inequality row (fixed variables included; Ipopt removes them)
  int kkt_dimension = 0;
  int kkt_nonzeros = 0;  ///< lower triangle: Hessian, Jacobian and the slacks' diagonal
};

/// The Lagrange multipliers of a point (Ipopt's sign convention): of the variable bounds (z_L,
/// z_U >= 0, one per variable) and of the constraint rows (lambda, one per row).
struct Multipliers {
  Eigen::VectorXd z_lower, z_upper, lambda;

  bool empty() const { return lambda.size() == 0; }
};

/// The accepted iterate a failed solve is best restarted from: among Ipopt's accepted iterates
/// those within constraint_tolerance, the cheapest; when none is, the least violated.
struct BestIterate {
  Eigen::VectorXd x;  ///< empty when Ipopt accepted none
  double violation = 0;
  double cost = 0;
  bool feasible = false;  ///< within constraint_tolerance
};

struct SolveResult {
  std::string status;  ///< Ipopt's SolverReturn name, e.g. "Solve_Succeeded"
  bool success = false;
  int iterations = 0;
  double cost = 0;
  double max_violation = 0;  ///< worst constraint or bound violation at x
  /// The last iterate; after a failure, the evaluated point of least violation when it is
  /// less violated than the last iterate (see `point`).
  Eigen::VectorXd x;
  /// Which point x is: "last iterate" or "least-violated point evaluated".
  std::string point = "last iterate";
  /// The multipliers of Ipopt's last iterate (also when x is the least-violated point).
  Multipliers multipliers;
  BestIterate best_iterate;
  double wall_time_s = 0;
  double callback_time_s = 0;  ///< time spent evaluating the Nlp (ours, not Ipopt's)
  SolveProfile profile;
};

/// The counts and times of several Ipopt solves (continuation stages, mesh rounds) summed.
struct SolveTotals {
  int iterations = 0;
  double wall_time_s = 0, callback_time_s = 0;
  int factorizations = 0, inertia_corrections = 0;
  kkt::KktStatistics ldl;

  void add(const SolveResult& r);
  /// Writes the sums over `r`'s own counts and times.
  void into(SolveResult& r) const;
};

/// A primal-dual start: Ipopt begins at x with these multipliers (its warm_start_init_point),
/// moved off the bounds by the options' bound_push and bound_frac only. Without multipliers
/// (empty) Ipopt starts at x and initialises them itself.
struct WarmStart {
  Eigen::VectorXd x;
  Multipliers multipliers;
};

/// `options` for a start next to an optimum: a small barrier, bound multipliers on its central
/// path (mu-based) and pushes of 1e-6 off the bounds, else the interior-point method first walks
/// away from it. Measured on the five-link problem from its own 1 kHz export: 12 iterations
/// against 15 from the polynomial guess; with constant multipliers 21 (pushes 1e-4), and the
/// refinement rounds of tests/ocp/mesh_refinement_test.cpp lose their monotone error decrease
/// with mu-based multipliers at pushes of 1e-4.
SolverOptions warmStarted(SolverOptions options);

/// From the Nlp's initial guess, or from `warm` (same variables and rows as `nlp`).
/// @throws std::runtime_error if Ipopt cannot be initialised (bad option), std::invalid_argument
/// if `warm` does not fit `nlp`.
SolveResult solveWithIpopt(const Nlp& nlp, const SolverOptions& options,
                           const WarmStart* warm = nullptr);

}  // namespace gaitopt::ocp
