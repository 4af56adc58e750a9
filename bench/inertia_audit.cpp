/// @file inertia_audit.cpp
/// Does gaitopt's KKT solver tell Ipopt the right inertia? Ipopt regularises its Newton matrix
/// until the linear solver counts as many negative eigenvalues as there are constraint rows,
/// so its path follows that count. Each config is solved with `ldl` (whatever its own
/// linear_solver), and every matrix the solver factorizes (kkt_observer.hpp) is factorized again
/// by MUMPS as Ipopt sets it up (mumps_factor.hpp). Where the two counts differ, `checks`
/// matrices of each config with at most kDenseRows rows, drawn along its path, are decided by a
/// dense eigendecomposition of the equilibrated matrix (a congruence: same inertia), and the
/// eigenvalue nearest zero says whether even that count is resolved in double precision.
/// Writes a markdown report and the same counts as CSV beside it (OUT.csv). Usage: inertia_audit
/// OUT.md CHECKS CONFIG[@SSP,DSP]...
/// (@SSP,DSP: the config on that many segments per phase, small enough to decompose densely).
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/output/checked_write.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "ocp/solve/kkt/kkt_observer.hpp"
#include "ocp/solve/kkt/kkt_pairs.hpp"
#include "ocp/solve/kkt/mumps_factor.hpp"

namespace {

using namespace gaitopt;
using ocp::kkt::SymmetricPattern;

/// Matrices above this many rows are not decomposed densely (10 000 rows: minutes each).
constexpr int kDenseRows = 6000;
/// Ruiz passes for the dense check (each brings every row's largest entry nearer 1).
constexpr int kEquilibrationPasses = 10;

/// A dense eigendecomposition's verdict on one matrix.
struct DenseInertia {
  int negative = 0;
  double nearest_zero = 0;  ///< the eigenvalue of least magnitude, over the largest magnitude
  /// |nearest_zero| above n eps: every eigenvalue's sign is beyond the decomposition's error.
  bool resolved = false;
};

Eigen::MatrixXd denseMatrix(const SymmetricPattern& p, const double* values) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(p.n, p.n);
  for (int c = 0; c < p.n; ++c)
    for (int k = p.outer[c]; k < p.outer[c + 1]; ++k) {
      a(p.inner[k], c) += values[k];
      if (p.inner[k] != c) a(c, p.inner[k]) += values[k];
    }
  return a;
}

DenseInertia denseInertia(const SymmetricPattern& p, const double* values) {
  Eigen::MatrixXd a = denseMatrix(p, values);
  for (int pass = 0; pass < kEquilibrationPasses; ++pass) {
    Eigen::VectorXd s = a.cwiseAbs().rowwise().maxCoeff();
    s = s.unaryExpr([](double x) { return x > 0 ? 1 / std::sqrt(x) : 1.0; });
    a = s.asDiagonal() * a * s.asDiagonal();
  }
  const Eigen::VectorXd e =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, Eigen::EigenvaluesOnly).eigenvalues();
  DenseInertia d;
  d.negative = static_cast<int>((e.array() < 0).count());
  Eigen::Index nearest = 0;
  e.cwiseAbs().minCoeff(&nearest);
  const double largest = e.cwiseAbs().maxCoeff();
  d.nearest_zero = e[nearest] / largest;
  d.resolved = std::abs(d.nearest_zero) > p.n * std::numeric_limits<double>::epsilon();
  return d;
}

/// One matrix on which the two solvers disagree.
struct Disagreement {
  int factorization = 0, rows = 0, expected = 0, ldl = 0, mumps = 0;
  bool checked = false;
  DenseInertia dense;
};

/// What one config's solve saw.
struct Audit {
  std::string config, mesh, status;  // mesh: "SSP,DSP" when overridden
  int iterations = 0, factorizations = 0, mumps_singular = 0;
  std::vector<Disagreement> disagreements;
  /// Of them, the ones where only `ldl`, or only MUMPS, counted a KKT matrix's inertia (one
  /// negative eigenvalue per constraint row: Ipopt takes the step; else it regularises).
  int onlyLdlKkt() const {
    return countIf([](const Disagreement& d) { return d.ldl == d.expected; });
  }
  int onlyMumpsKkt() const {
    return countIf([](const Disagreement& d) { return d.mumps == d.expected; });
  }
  template <class Predicate>
  int countIf(Predicate p) const {
    return static_cast<int>(std::count_if(disagreements.begin(), disagreements.end(), p));
  }
};

/// Watches the thread's KKT factorizations for one solve and compares each with MUMPS's.
class Auditor {
 public:
  Auditor(Audit& audit, int checks) : audit_(audit), checks_(checks) {
    ocp::kkt::threadFactorizationObserver() = [this](const SymmetricPattern& p, const double* v,
                                                     int negative) { see(p, v, negative); };
  }
  ~Auditor() { ocp::kkt::threadFactorizationObserver() = nullptr; }
  Auditor(const Auditor&) = delete;
  Auditor& operator=(const Auditor&) = delete;

  /// Decides the sampled matrices by dense eigendecompositions.
  void decide() {
    for (const Kept& k : kept_) {
      Disagreement& d = audit_.disagreements[k.disagreement];
      d.checked = true;
      d.dense = denseInertia(k.pattern, k.values.data());
      std::fprintf(stderr, "inertia_audit: %s %s factorization %d: ldl %d, MUMPS %d, dense %d\n",
                   audit_.config.c_str(), audit_.mesh.c_str(), d.factorization, d.ldl, d.mumps,
                   d.dense.negative);
    }
  }

 private:
  void see(const SymmetricPattern& p, const double* values, int negative) {
    const int index = ++audit_.factorizations;
    if (!mumps_ || p.outer != pattern_.outer || p.inner != pattern_.inner) {  // a new mesh
      pattern_ = p;
      mumps_ = std::make_unique<ocp::kkt::MumpsFactor>(pattern_);
    }
    try {
      mumps_->factorize(values);
    } catch (const ocp::kkt::SingularMatrix&) {
      ++audit_.mumps_singular;
      return;
    }
    if (mumps_->negativeEigenvalues() == negative) return;
    Disagreement d;
    d.factorization = index;
    d.rows = p.n;
    d.expected = p.n - ocp::kkt::constraintRowsStart(p);
    d.ldl = negative;
    d.mumps = mumps_->negativeEigenvalues();
    audit_.disagreements.push_back(d);
    if (p.n <= kDenseRows) sample(p, values);
  }

  /// Reservoir sampling (Vitter's algorithm R, a fixed seed): the matrices to decide densely
  /// are drawn evenly from the whole path, not its first disagreements.
  void sample(const SymmetricPattern& p, const double* values) {
    ++sampled_;
    const long slot = static_cast<int>(kept_.size()) < checks_
                          ? static_cast<long>(kept_.size())
                          : std::uniform_int_distribution<long>(0, sampled_ - 1)(random_);
    if (slot >= checks_) return;  // not drawn: no copy of the matrix
    Kept kept{audit_.disagreements.size() - 1, p,
              std::vector<double>(values, values + p.nonZeros())};
    if (slot == static_cast<long>(kept_.size()))
      kept_.push_back(std::move(kept));
    else
      kept_[slot] = std::move(kept);
  }

  struct Kept {
    size_t disagreement;
    SymmetricPattern pattern;
    std::vector<double> values;
  };

  Audit& audit_;
  int checks_;
  SymmetricPattern pattern_;
  std::unique_ptr<ocp::kkt::MumpsFactor> mumps_;
  std::vector<Kept> kept_;
  long sampled_ = 0;
  std::mt19937_64 random_{1};
};

/// "PATH" or "PATH@SSP,DSP": the config, with the segments of its two phases replaced.
ocp::OcpConfig configOf(const std::string& argument, Audit& a) {
  const size_t at = argument.find('@');
  const std::string path = argument.substr(0, at);
  ocp::OcpConfig config = ocp::loadOcpConfig(path);
  a.config = std::filesystem::path(path).stem().string();
  if (at == std::string::npos) return config;
  const std::string mesh = argument.substr(at + 1);
  const size_t comma = mesh.find(',');
  if (comma == std::string::npos || config.phases.size() != 2)
    throw std::invalid_argument(argument + ": expected PATH@SSP,DSP on a two-phase config");
  config.phases[0].segments = std::stoi(mesh.substr(0, comma));
  config.phases[1].segments = std::stoi(mesh.substr(comma + 1));
  a.mesh = mesh;
  return config;
}

Audit audit(const std::string& argument, int checks) {
  Audit a;
  ocp::OcpConfig config = configOf(argument, a);
  std::fprintf(stderr, "inertia_audit: %s %s: solving\n", a.config.c_str(), a.mesh.c_str());
  config.solver.linear_solver = "ldl";
  const auto model = ocp::problemModel(config);
  const gaits::Trajectory guess = ocp::initialGuess(model, config);
  Auditor watch(a, checks);
  try {
    const ocp::GaitSolution s = ocp::solveGait(model, config, guess);
    a.status = s.result.status;
    a.iterations = s.result.iterations;
  } catch (const std::exception& e) {  // a failed solve's matrices are audited all the same
    a.status = std::string("error: ") + e.what();
  }
  std::fprintf(stderr, "inertia_audit: %s %s: %s, %d factorizations, %zu counts differ\n",
               a.config.c_str(), a.mesh.c_str(), a.status.c_str(), a.factorizations,
               a.disagreements.size());
  watch.decide();
  return a;
}

std::string verdict(const Disagreement& d) {
  if (!d.checked) return "not decomposed";
  if (!d.dense.resolved) return "unresolved in double precision";
  if (d.dense.negative == d.ldl) return "ldl";
  return d.dense.negative == d.mumps ? "MUMPS" : "neither";
}

std::string labelOf(const Audit& a) {
  return a.mesh.empty() ? a.config : a.config + " (" + a.mesh + " segments)";
}

int decided(const Audit& a, const std::string& by) {
  return a.countIf([&](const Disagreement& d) { return verdict(d) == by; });
}

std::string csvOf(const std::vector<Audit>& audits) {
  std::string out =
      "config,mesh,status,iterations,factorizations,mumps_singular,differ,only_ldl_kkt,"
      "only_mumps_kkt,decided_ldl,decided_mumps,decided_neither,unresolved\n";
  for (const Audit& a : audits)
    out += fmt::format("{},\"{}\",{},{},{},{},{},{},{},{},{},{},{}\n", a.config, a.mesh, a.status,
                       a.iterations, a.factorizations, a.mumps_singular, a.disagreements.size(),
                       a.onlyLdlKkt(), a.onlyMumpsKkt(), decided(a, "ldl"), decided(a, "MUMPS"),
                       decided(a, "neither"), decided(a, "unresolved in double precision"));
  return out;
}

std::string report(const std::vector<Audit>& audits) {
  std::ostringstream f;
  f << "Each config solved with `ldl`; every matrix it factorized also factorized by MUMPS "
       "(Ipopt's settings: AMD order, scaling 77, pivot tolerance 1e-6). "
       "`bench/inertia_audit.cpp`.\n\n"
       "| config | status | iterations | factorizations | MUMPS calls singular | counts differ "
       "| share | of them, only ldl's a KKT inertia | only MUMPS's |\n"
       "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Audit& a : audits)
    f << fmt::format("| {} | {} | {} | {} | {} | {} | {:.1f} % | {} | {} |\n", labelOf(a), a.status,
                     a.iterations, a.factorizations, a.mumps_singular, a.disagreements.size(),
                     100.0 * a.disagreements.size() / std::max(1, a.factorizations), a.onlyLdlKkt(),
                     a.onlyMumpsKkt());
  f << "\nThe matrices decided by a dense eigendecomposition (equilibrated; nearest zero: the "
       "eigenvalue of least magnitude over the largest; resolved when above n eps):\n\n"
       "| config | factorization | rows | constraint rows | ldl | MUMPS | dense | nearest zero | "
       "right |\n|---|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for (const Audit& a : audits)
    for (const Disagreement& d : a.disagreements)
      if (d.checked)
        f << fmt::format("| {} | {} | {} | {} | {} | {} | {} | {:.2e} | {} |\n", labelOf(a),
                         d.factorization, d.rows, d.expected, d.ldl, d.mumps, d.dense.negative,
                         d.dense.nearest_zero, verdict(d));
  return f.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: inertia_audit OUT.md CHECKS CONFIG[@SSP,DSP]...\n");
    return 2;
  }
  try {
    const int checks = std::max(0, std::stoi(argv[2]));
    std::vector<Audit> audits;
    for (int i = 3; i < argc; ++i) audits.push_back(audit(argv[i], checks));
    const std::string out = argv[1];
    io::writeFileAtomically(out, report(audits));
    io::writeFileAtomically(std::filesystem::path(out).replace_extension(".csv").string(),
                            csvOf(audits));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inertia_audit: %s\n", e.what());
    return 1;
  }
  return 0;
}
