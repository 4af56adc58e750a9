#pragma once
/// @file lemke.hpp
/// Lemke's complementary pivoting method (Lemke 1978, ref. [8] of Addi & Rodic 2010) for the
/// linear complementarity problem LCP(M, q): find z with
///   z >= 0,  w = M z + q >= 0,  z^T w = 0
/// (Addi & Rodic eq. 58, there written y = A x + b). It is the solver Addi & Rodic use for the
/// frictional impact LCP (56); time-stepping contact (lcp_contact_step.hpp) calls it each step.
#include <Eigen/Core>

namespace gaitopt::sim {

/// How a Lemke run ended.
enum class LemkeStatus {
  kSolved,          ///< z, w solve the LCP
  kRayTermination,  ///< the entering column had no limiting row: Lemke found no solution
  kPivotLimit,      ///< LemkeOptions::max_pivots reached first
};
const char* toString(LemkeStatus status);

/// Numerical safeguards of the pivoting (not physics; the defaults suit contact LCPs of a few
/// dozen rows, where Lemke typically needs O(n) pivots).
struct LemkeOptions {
  int max_pivots = 1000;           ///< pivots (the initial one included) before kPivotLimit
  double pivot_tolerance = 1e-12;  ///< column entries <= this x max(1, |column|_inf) cannot pivot
  double ratio_tolerance = 1e-9;   ///< relative gap under which two ratios count as tied
};

struct LemkeResult {
  LemkeStatus status = LemkeStatus::kRayTermination;
  Eigen::VectorXd z;  ///< n; the last almost-complementary point unless kSolved
  Eigen::VectorXd w;  ///< M z + q, n
  int pivots = 0;     ///< pivots done, the initial z0 pivot included (0 when q >= 0)
};

/// Solves LCP(M, q) by Lemke's method with covering vector d = (1, ..., 1) and the lexicographic
/// minimum-ratio rule (Cottle, Pang & Stone 1992, sec. 4.4), which prevents cycling on degenerate
/// problems. Returns z = 0 without pivoting when q >= 0. An LCP Lemke cannot solve (e.g. an
/// infeasible one) gives kRayTermination, never an exception. Lemke is guaranteed to process
/// copositive-plus M (e.g. positive semidefinite) and the Stewart-Trinkle contact LCP.
/// @param m  n x n
/// @param q  n
/// @throws std::invalid_argument if M is not n x n, an entry is not finite, or options are not
///         positive
LemkeResult solveLcp(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                     const LemkeOptions& options = {});

}  // namespace gaitopt::sim
