#pragma once
/// @file mumps_factor.hpp
/// MUMPS's LDL^T of the same matrix, with threshold pivoting inside the elimination: what
/// KktSolver falls back to on a matrix whose static pivots leave a zero pivot. Set up as Ipopt
/// 3.11's own MUMPS interface sets it for gaitopt (IpMumpsSolverInterface.cpp: symmetric
/// indefinite, AMD order as gaitopt's mumps_pivot_order, scaling 77, pivot tolerance 1e-6,
/// ICNTL(13) = 1 for an exact inertia), so a fallback factorization is the one
/// `linear_solver: mumps` would have made.
#include <memory>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

/// MUMPS found the matrix singular (INFO(1) = -10): Ipopt then regularises the constraints.
struct SingularMatrix : std::runtime_error {
  SingularMatrix() : std::runtime_error("singular matrix") {}
};

/// Debian's sequential MUMPS keeps state shared by all its instances: one call at a time in the
/// process. Every call here holds this lock, and a solve through Ipopt's own MUMPS interface
/// (`linear_solver: mumps`) holds it for the whole solve (ipopt_adapter.cpp), so threads of one
/// process (Python's) may solve side by side.
std::mutex& mumpsMutex();

class MumpsFactor {
 public:
  explicit MumpsFactor(const SymmetricPattern& pattern);
  ~MumpsFactor();
  MumpsFactor(const MumpsFactor&) = delete;
  MumpsFactor& operator=(const MumpsFactor&) = delete;

  /// Factorizes A(values), analysing it first on the first call; throws SingularMatrix.
  void factorize(const double* values);
  /// x := A^{-1} x for the last factorized A.
  void solve(double* x) const;
  /// INFOG(12): the negative pivots, A's negative eigenvalues.
  int negativeEigenvalues() const;

 private:
  struct Handle;
  std::vector<int> rows_, columns_;  // 1-based coordinates of the pattern's entries
  std::unique_ptr<Handle> mumps_;
  bool analysed_ = false;
};

}  // namespace gaitopt::ocp::kkt
