/// @file constraint_rank.cpp
/// Which constraint rows are linearly dependent at a solve's end? Ipopt's Newton matrix is
/// nonsingular near a solution only when the gradients of the equalities and of the rows and
/// bounds at their limits are independent (LICQ); where they are not, the matrix goes singular
/// to working precision and the rounding of the linear solves steers the path
/// (docs/optimal_gaits.md#independent-constraints). Solves CONFIG as `gaitopt optimize` does,
/// then takes the row-normalised gradients of the equalities and of everything within TOL of a
/// bound at the last iterate, and prints their smallest singular values and, for each one below
/// 1e-6 of the largest, the rows that make up its left singular vector (by name, phase and
/// point). Dense: for the single-model configs (a few thousand variables), not the ensemble.
/// Usage: constraint_rank CONFIG [TOL=1e-7]
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numeric>
#include <string>
#include <vector>

#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"

namespace {

using namespace gaitopt;
using namespace gaitopt::ocp;

/// How many of the smallest singular values are printed.
constexpr int kPrinted = 6;
/// A singular value below this fraction of the largest is a dependency worth naming.
constexpr double kDependent = 1e-6;

bool nearBound(double value, double lower, double upper, double tol) {
  return std::abs(value - lower) < tol || std::abs(value - upper) < tol;
}

/// The active rows' gradients, normalised, with a name per row.
struct ActiveSet {
  Eigen::MatrixXd gradients;
  std::vector<std::string> names;
};

ActiveSet activeSet(const Nlp& nlp, const Eigen::VectorXd& x, double tol) {
  const Eigen::VectorXd g = nlp.constraintValues(x), gl = nlp.constraintLower(),
                        gu = nlp.constraintUpper();
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(nlp.constraints(), nlp.variables());
  for (const auto& t : nlp.jacobianTriplets(x)) jacobian(t.row(), t.col()) += t.value();
  std::vector<Eigen::RowVectorXd> rows;
  ActiveSet a;
  for (int i = 0; i < nlp.constraints(); ++i)
    if (gl(i) == gu(i) || nearBound(g(i), gl(i), gu(i), tol)) {
      rows.push_back(jacobian.row(i));
      a.names.push_back(whereOf(nlp.locateConstraintRow(i)));
    }
  for (int v = 0; v < nlp.variables(); ++v)
    if (nearBound(x(v), nlp.lowerBounds()(v), nlp.upperBounds()(v), tol)) {
      rows.push_back(Eigen::RowVectorXd::Unit(nlp.variables(), v));
      a.names.push_back("bound of " + whereOf(nlp.locateVariable(v)));
    }
  a.gradients.resize(static_cast<Eigen::Index>(rows.size()), nlp.variables());
  for (size_t k = 0; k < rows.size(); ++k) {
    const double norm = rows[k].norm();
    a.gradients.row(static_cast<Eigen::Index>(k)) =
        norm > 0 ? Eigen::RowVectorXd(rows[k] / norm) : rows[k];
  }
  return a;
}

/// The rows of one left singular vector, largest weight first, down to 1e-3.
void printDependency(const ActiveSet& a, const Eigen::VectorXd& u) {
  std::vector<int> order(static_cast<size_t>(u.size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int i, int j) { return std::abs(u(i)) > std::abs(u(j)); });
  for (size_t k = 0; k < std::min<size_t>(order.size(), 12) && std::abs(u(order[k])) >= 1e-3; ++k)
    std::printf("    %+.3f  %s\n", u(order[k]), a.names[static_cast<size_t>(order[k])].c_str());
}

void report(const ActiveSet& a) {
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(a.gradients, Eigen::ComputeFullU);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const auto count = static_cast<int>(sigma.size());
  std::printf("%ld active rows x %ld variables; largest singular value %.3g\n",
              static_cast<long>(a.gradients.rows()), static_cast<long>(a.gradients.cols()),
              sigma(0));
  for (int j = count - 1; j >= std::max(0, count - kPrinted); --j) {
    std::printf("  sigma_%d = %.3e\n", j, sigma(j));
    if (sigma(j) < kDependent * sigma(0)) printDependency(a, svd.matrixU().col(j));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: constraint_rank CONFIG [TOL=1e-7]\n");
    return 2;
  }
  try {
    const double tol = argc > 2 ? std::stod(argv[2]) : 1e-7;
    const OcpConfig config = loadOcpConfig(argv[1]);
    const auto model = problemModel(config);
    const GaitSolution s = solveGait(model, config, initialGuess(model, config));
    std::printf("%s: %s after %d iterations, cost %.6g\n", argv[1], s.result.status.c_str(),
                s.result.iterations, s.result.cost);
    report(activeSet(s.problem.nlp, s.result.x, tol));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "constraint_rank: %s\n", e.what());
    return 1;
  }
  return 0;
}
