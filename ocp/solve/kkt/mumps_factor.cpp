#include "ocp/solve/kkt/mumps_factor.hpp"

#include <dmumps_c.h>

#include <string>

namespace gaitopt::ocp::kkt {
namespace {

constexpr int kInitialise = -1, kTerminate = -2, kAnalyse = 1, kFactorize = 2, kSolve = 3;
constexpr int kHostWorks = 1, kSymmetricIndefinite = 2;
constexpr int kCommWorld = -987654;  // MUMPS's USE_COMM_WORLD; the sequential library ignores it
constexpr int kStructurallySingular = -6, kShortOfMemory = -8, kShortOfWorkspace = -9,
              kSingular = -10;  // INFO(1)
constexpr int kMemoryAttempts = 20;

}  // namespace

struct MumpsFactor::Handle {
  mutable DMUMPS_STRUC_C data{};
};

namespace {

void check(const DMUMPS_STRUC_C& data) {
  if (data.info[0] == kStructurallySingular || data.info[0] == kSingular) throw SingularMatrix();
  if (data.info[0] < 0)
    throw std::runtime_error("MUMPS job " + std::to_string(data.job) +
                             " failed: INFO(1) = " + std::to_string(data.info[0]));
}

void call(DMUMPS_STRUC_C& data, int job) {
  data.job = job;
  const std::scoped_lock lock(mumpsMutex());
  dmumps_c(&data);
  check(data);
}

/// Ipopt 3.11's settings (IpMumpsSolverInterface.cpp), silent. ICNTL(k) is icntl[k - 1].
void setLikeIpopt(DMUMPS_STRUC_C& data) {
  data.icntl[0] = data.icntl[1] = data.icntl[2] = data.icntl[3] = 0;  // no output
  data.icntl[5] = 7;      // permutation and scaling chosen automatically
  data.icntl[6] = 0;      // AMD: gaitopt's mumps_pivot_order (ocp_config.hpp)
  data.icntl[7] = 77;     // scaling chosen automatically
  data.icntl[9] = 0;      // no iterative refinement: KktSolver refines
  data.icntl[12] = 1;     // the root factorized without ScaLAPACK: an exact inertia
  data.icntl[13] = 1000;  // working memory over the estimate [%]
  data.cntl[0] = 1e-6;    // relative pivot threshold
}

}  // namespace

std::mutex& mumpsMutex() {
  static std::mutex mutex;
  return mutex;
}

MumpsFactor::MumpsFactor(const SymmetricPattern& pattern) : mumps_(std::make_unique<Handle>()) {
  for (int column = 0; column < pattern.n; ++column)
    for (int k = pattern.outer[column]; k < pattern.outer[column + 1]; ++k) {
      rows_.push_back(pattern.inner[k] + 1);
      columns_.push_back(column + 1);
    }
  DMUMPS_STRUC_C& data = mumps_->data;
  data.par = kHostWorks;
  data.sym = kSymmetricIndefinite;
  data.comm_fortran = kCommWorld;
  call(data, kInitialise);
  setLikeIpopt(data);
  data.n = pattern.n;
  data.nnz = static_cast<MUMPS_INT8>(rows_.size());
  data.irn = rows_.data();
  data.jcn = columns_.data();
}

MumpsFactor::~MumpsFactor() {
  mumps_->data.job = kTerminate;
  const std::scoped_lock lock(mumpsMutex());
  dmumps_c(&mumps_->data);
}

void MumpsFactor::factorize(const double* values) {
  DMUMPS_STRUC_C& data = mumps_->data;
  data.a = const_cast<double*>(values);  // MUMPS reads A through a non-const pointer
  if (!analysed_) call(data, kAnalyse);
  analysed_ = true;
  const std::scoped_lock lock(mumpsMutex());
  // Short of working memory (INFO(1) -8 or -9), MUMPS is given twice as much, as Ipopt does.
  for (int attempt = 0; attempt < kMemoryAttempts; ++attempt) {
    data.job = kFactorize;
    dmumps_c(&data);
    if (data.info[0] != kShortOfMemory && data.info[0] != kShortOfWorkspace) break;
    data.icntl[13] *= 2;
  }
  check(data);
}

void MumpsFactor::solve(double* x) const {
  DMUMPS_STRUC_C& data = mumps_->data;
  data.nrhs = 1;
  data.lrhs = data.n;
  data.rhs = x;
  call(data, kSolve);
}

int MumpsFactor::negativeEigenvalues() const {
  return mumps_->data.infog[11];
}

}  // namespace gaitopt::ocp::kkt
