#include "ocp/solve/ipopt_adapter.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>

#include <fmt/format.h>
#include <IpIpoptApplication.hpp>
#include <IpIpoptData.hpp>
#include <IpJournalist.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include "ocp/solve/kkt/kkt_statistics.hpp"
#include "ocp/solve/kkt/mumps_factor.hpp"
#include "ocp/solve/kkt/pardiso_interface.hpp"

namespace gaitopt::ocp {
namespace {

using Ipopt::Index;
using Ipopt::Number;
using Clock = std::chrono::steady_clock;

/// Accumulates the wall time of one callback into a total.
class CallbackTimer {
 public:
  explicit CallbackTimer(double& total) : total_(total), start_(Clock::now()) {}
  ~CallbackTimer() { total_ += std::chrono::duration<double>(Clock::now() - start_).count(); }
  CallbackTimer(const CallbackTimer&) = delete;
  CallbackTimer& operator=(const CallbackTimer&) = delete;

 private:
  double& total_;
  Clock::time_point start_;
};

/// Counts MUMPS's numerical factorizations of the KKT matrix with `linear_solver: mumps`: Ipopt
/// 3.11 has no counter, but its MUMPS interface announces each one on the linear-algebra journal
/// ("Calling MUMPS-2 for numerical factorization ..."). Only that category at that level reaches
/// this journal, and only the format string is inspected (nothing is formatted). gaitopt's own
/// KKT solver counts its factorizations itself (kkt_statistics.hpp).
class FactorizationCounter : public Ipopt::Journal {
 public:
  explicit FactorizationCounter(int& count)
      : Ipopt::Journal("factorization_counter", Ipopt::J_NONE), count_(count) {
    SetAllPrintLevels(Ipopt::J_NONE);
    SetPrintLevel(Ipopt::J_LINEAR_ALGEBRA, Ipopt::J_MOREDETAILED);
  }

 protected:
  void PrintImpl(Ipopt::EJournalCategory, Ipopt::EJournalLevel, const char*) override {}
  void PrintfImpl(Ipopt::EJournalCategory, Ipopt::EJournalLevel, const char* format,
                  va_list) override {
    if (std::strstr(format, "Calling MUMPS-2 for numerical factorization") != nullptr) ++count_;
  }
  void FlushBufferImpl() override {}

 private:
  int& count_;
};

const char* statusName(Ipopt::SolverReturn status) {
  switch (status) {
    case Ipopt::SUCCESS:
      return "Solve_Succeeded";
    case Ipopt::MAXITER_EXCEEDED:
      return "Maximum_Iterations_Exceeded";
    case Ipopt::CPUTIME_EXCEEDED:
      return "Maximum_CpuTime_Exceeded";
    case Ipopt::STOP_AT_TINY_STEP:
      return "Search_Direction_Becomes_Too_Small";
    case Ipopt::STOP_AT_ACCEPTABLE_POINT:
      return "Solved_To_Acceptable_Level";
    case Ipopt::LOCAL_INFEASIBILITY:
      return "Infeasible_Problem_Detected";
    case Ipopt::USER_REQUESTED_STOP:
      return "User_Requested_Stop";
    case Ipopt::DIVERGING_ITERATES:
      return "Diverging_Iterates";
    case Ipopt::RESTORATION_FAILURE:
      return "Restoration_Failed";
    case Ipopt::ERROR_IN_STEP_COMPUTATION:
      return "Error_In_Step_Computation";
    case Ipopt::INVALID_NUMBER_DETECTED:
      return "Invalid_Number_Detected";
    case Ipopt::TOO_FEW_DEGREES_OF_FREEDOM:
      return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::INVALID_OPTION:
      return "Invalid_Option";
    case Ipopt::OUT_OF_MEMORY:
      return "Insufficient_Memory";
    case Ipopt::INTERNAL_ERROR:
      return "Internal_Error";
    default:
      return "Unknown_Error";
  }
}

/// Worst constraint or bound violation of x with constraint values g; NaN counts as infinite.
double violation(const Nlp& nlp, const Eigen::VectorXd& x, const Eigen::VectorXd& g,
                 const Eigen::VectorXd& gl, const Eigen::VectorXd& gu) {
  if (!g.allFinite() || !x.allFinite()) return std::numeric_limits<double>::infinity();
  return std::max({0.0, (gl - g).maxCoeff(), (g - gu).maxCoeff(),
                   (nlp.lowerBounds() - x).maxCoeff(), (x - nlp.upperBounds()).maxCoeff()});
}

/// The least violated point Ipopt evaluated: what a failed solve keeps when its last iterate is
/// worse (Ipopt 3.11 does not hand out its iterates, but every one passes through eval_g).
struct LeastViolation {
  Eigen::VectorXd x;
  double violation = std::numeric_limits<double>::infinity();
};

/// Keeps the best accepted iterate (BestIterate): a feasible one beats any infeasible one,
/// feasible ones by cost, infeasible ones by violation.
void offerIterate(BestIterate& best, const Eigen::VectorXd& x, double violation, double cost,
                  double feasible_tolerance) {
  const bool feasible = violation <= feasible_tolerance;
  const bool better = best.x.size() == 0 || (feasible && !best.feasible) ||
                      (feasible && best.feasible && cost < best.cost) ||
                      (!feasible && !best.feasible && violation < best.violation);
  if (better) best = {x, violation, cost, feasible};
}

class Adapter : public Ipopt::TNLP {
 public:
  Adapter(const Nlp& nlp, SolveResult& result, LeastViolation& best, const SolverOptions& options,
          const WarmStart* start)
      : nlp_(nlp),
        result_(result),
        best_(best),
        progress_(options.progress),
        feasible_tolerance_(options.constraint_tolerance),
        start_(start),
        gl_(nlp.constraintLower()),
        gu_(nlp.constraintUpper()) {
    const CallbackTimer t(result.profile.sparsity_time_s);
    jac_.record(nlp.jacobianTriplets(nlp.initialGuess()));
    hess_.record(
        nlp.hessianTriplets(nlp.initialGuess(), 1.0, Eigen::VectorXd::Ones(nlp.constraints())));
    recordKktSize(result.profile);
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac, Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = nlp_.variables();
    m = nlp_.constraints();
    nnz_jac = jac_.nonZeros();
    nnz_h = hess_.nonZeros();
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* xl, Number* xu, Index m, Number* gl, Number* gu) override {
    Eigen::Map<Eigen::VectorXd>(xl, n) = nlp_.lowerBounds();
    Eigen::Map<Eigen::VectorXd>(xu, n) = nlp_.upperBounds();
    Eigen::Map<Eigen::VectorXd>(gl, m) = nlp_.constraintLower();
    Eigen::Map<Eigen::VectorXd>(gu, m) = nlp_.constraintUpper();
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number* z_l, Number* z_u,
                          Index m, bool init_lambda, Number* lambda) override {
    const bool duals = start_ != nullptr && !start_->multipliers.empty();
    if ((init_z || init_lambda) && !duals) return false;  // asked only with warm_start_init_point
    if (init_x) Eigen::Map<Eigen::VectorXd>(x, n) = start_ ? start_->x : nlp_.initialGuess();
    if (init_z) {
      Eigen::Map<Eigen::VectorXd>(z_l, n) = start_->multipliers.z_lower;
      Eigen::Map<Eigen::VectorXd>(z_u, n) = start_->multipliers.z_upper;
    }
    if (init_lambda) Eigen::Map<Eigen::VectorXd>(lambda, m) = start_->multipliers.lambda;
    return true;
  }

  bool eval_f(Index n, const Number* x, bool, Number& f) override {
    const CallbackTimer t(result_.callback_time_s);
    f = nlp_.cost(vec(x, n));
    return std::isfinite(f);
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad) override {
    const CallbackTimer t(result_.callback_time_s);
    Eigen::Map<Eigen::VectorXd>(grad, n) = nlp_.costGradient(vec(x, n));
    return true;
  }

  bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
    const CallbackTimer t(result_.callback_time_s);
    const Eigen::VectorXd xv = vec(x, n), gv = nlp_.constraintValues(xv);
    Eigen::Map<Eigen::VectorXd>(g, m) = gv;
    const double v = violation(nlp_, xv, gv, gl_, gu_);
    if (v <= best_.violation) best_ = {xv, v};
    lastEvaluated_ = {xv, v};
    return true;
  }

  bool eval_jac_g(Index n, const Number* x, bool, Index, Index, Index* rows, Index* cols,
                  Number* values) override {
    const CallbackTimer t(result_.callback_time_s);
    if (values == nullptr) return fillStructure(jac_, rows, cols);
    // Ipopt evaluates the Jacobian at each iterate it accepts, before it reports the iteration
    // (its convergence check needs the dual infeasibility there): the iterate of the next
    // intermediate_callback.
    iterate_ = vec(x, n);
    nlp_.jacobianTriplets(iterate_, jac_values_);
    jac_.accumulate(jac_values_, values);
    return true;
  }

  bool eval_h(Index n, const Number* x, bool, Number obj_factor, Index m, const Number* lambda,
              bool, Index, Index* rows, Index* cols, Number* values) override {
    const CallbackTimer t(result_.callback_time_s);
    if (values == nullptr) return fillStructure(hess_, rows, cols);
    nlp_.hessianTriplets(vec(x, n), obj_factor, vec(lambda, m), hess_values_);
    hess_.accumulate(hess_values_, values);
    return true;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number obj, Number inf_pr,
                             Number inf_du, Number, Number, Number regularization, Number, Number,
                             Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    if (regularization > 0) ++result_.profile.inertia_corrections;
    if (iterate_.size() == nlp_.variables()) {
      const CallbackTimer t(result_.callback_time_s);
      offerIterate(result_.best_iterate, iterate_, iterateViolation(), nlp_.cost(iterate_),
                   feasible_tolerance_);
    }
    if (progress_)
      fmt::print("  iter {:4d}  cost {: .6e}  infeasibility {:.2e}  dual {:.2e}\n", iter, obj,
                 inf_pr, inf_du);
    return true;
  }

  /// The current iterate's violation: the last eval_g's, which Ipopt usually made there (the
  /// trial point it accepted), else evaluated again.
  double iterateViolation() const {
    const Eigen::VectorXd& last = lastEvaluated_.x;
    if (last.size() == iterate_.size() && last == iterate_) return lastEvaluated_.violation;
    return violation(nlp_, iterate_, nlp_.constraintValues(iterate_), gl_, gu_);
  }

  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* x, const Number* z_l,
                         const Number* z_u, Index m, const Number*, const Number* lambda,
                         Number obj, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    result_.status = statusName(status);
    result_.success = status == Ipopt::SUCCESS;
    result_.x = vec(x, n);
    result_.cost = obj;
    result_.multipliers = {vec(z_l, n), vec(z_u, n), vec(lambda, m)};
  }

 private:
  /// The augmented system of Ipopt's step: [W + Sigma_x, 0, J^T; 0, Sigma_s, -I_d^T;
  /// J, -I_d, -delta I], one slack s per inequality row d.
  void recordKktSize(SolveProfile& profile) const {
    const auto inequalities = static_cast<int>(((gu_ - gl_).array() > 0).count());
    const int variables = nlp_.variables(), rows = nlp_.constraints();
    profile.kkt_dimension = variables + inequalities + rows;
    // The lower triangle: W, Sigma_x, Sigma_s and -I_d, J, -delta I.
    profile.kkt_nonzeros = hess_.nonZeros() + variables + 2 * inequalities + jac_.nonZeros() + rows;
  }

  static Eigen::VectorXd vec(const Number* p, Index n) {
    return Eigen::Map<const Eigen::VectorXd>(p, n);
  }
  static bool fillStructure(const SparsityPattern& pattern, Index* rows, Index* cols) {
    std::copy(pattern.rows().begin(), pattern.rows().end(), rows);
    std::copy(pattern.cols().begin(), pattern.cols().end(), cols);
    return true;
  }

  const Nlp& nlp_;
  SolveResult& result_;
  LeastViolation& best_;
  bool progress_;
  double feasible_tolerance_;
  const WarmStart* start_;
  Eigen::VectorXd iterate_;       // the point of the last Jacobian: the current iterate
  LeastViolation lastEvaluated_;  // the point of the last eval_g and its violation
  Eigen::VectorXd gl_, gu_;       // constraint bounds, assembled once
  SparsityPattern jac_, hess_;
  Triplets jac_values_, hess_values_;  // reused at every evaluation (Nlp::jacobianTriplets)
};

double maxViolation(const Nlp& nlp, const Eigen::VectorXd& x) {
  return violation(nlp, x, nlp.constraintValues(x), nlp.constraintLower(), nlp.constraintUpper());
}

/// After a failure, x becomes the least violated point evaluated if it beats the last iterate;
/// its cost is that point's, as its summary's cost terms are.
void keepLeastViolated(const Nlp& nlp, SolveResult& result, const LeastViolation& best) {
  if (result.success || !(best.violation < result.max_violation)) return;
  result.x = best.x;
  result.cost = nlp.cost(best.x);
  result.max_violation = best.violation;
  result.point = "least-violated point evaluated";
}

void setLinearSolver(Ipopt::OptionsList& ipopt, const SolverOptions& options) {
  if (options.linear_solver == "ldl") {
    ipopt.SetStringValue("linear_solver", "pardiso");  // Ipopt then loads kkt::kLibraryName
    return;
  }
  ipopt.SetStringValue("linear_solver", options.linear_solver);
  ipopt.SetIntegerValue("mumps_pivot_order", options.mumps_pivot_order);
}

/// Ipopt's primal-dual warm start (warm_start_init_point): x and the multipliers as given,
/// moved off the bounds by the options' pushes (warmStarted: 1e-6) rather than Ipopt's
/// warm-start defaults of 1e-3. From its own primal-dual optimum the default five-link problem
/// then re-solves in 1 iteration (tests/ocp/continuation_path_test.cpp).
void setWarmStart(Ipopt::OptionsList& ipopt, const SolverOptions& options) {
  ipopt.SetStringValue("warm_start_init_point", "yes");
  ipopt.SetNumericValue("warm_start_bound_push", options.bound_push);
  ipopt.SetNumericValue("warm_start_bound_frac", options.bound_frac);
  ipopt.SetNumericValue("warm_start_slack_bound_push", options.bound_push);
  ipopt.SetNumericValue("warm_start_slack_bound_frac", options.bound_frac);
  ipopt.SetNumericValue("warm_start_mult_bound_push", options.bound_push);
}

/// @throws std::invalid_argument when a start does not fit the problem.
void checkStart(const Nlp& nlp, const WarmStart& start) {
  const Multipliers& m = start.multipliers;
  const bool fits =
      start.x.size() == nlp.variables() &&
      (m.empty() || (m.z_lower.size() == nlp.variables() && m.z_upper.size() == nlp.variables() &&
                     m.lambda.size() == nlp.constraints()));
  if (!fits)
    throw std::invalid_argument(
        fmt::format("a start of {} variables and {} multipliers for a problem of {} variables and "
                    "{} rows",
                    start.x.size(), m.lambda.size(), nlp.variables(), nlp.constraints()));
}

}  // namespace

SolveResult solveWithIpopt(const Nlp& nlp, const SolverOptions& options, const WarmStart* warm) {
  const auto start = Clock::now();
  SolveResult result;
  // Ipopt's MUMPS instance lives as long as the application: the lock is taken before it and
  // released after it (kkt::mumpsMutex).
  std::unique_lock<std::mutex> mumps_lock;
  if (options.linear_solver == "mumps") mumps_lock = std::unique_lock(kkt::mumpsMutex());
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetNumericValue("tol", options.tolerance);
  app->Options()->SetNumericValue("constr_viol_tol", options.constraint_tolerance);
  app->Options()->SetIntegerValue("max_iter", options.max_iterations);
  app->Options()->SetStringValue("hessian_approximation", options.hessian);
  app->Options()->SetStringValue("jacobian_approximation",
                                 options.jacobian == "exact" ? "exact" : options.jacobian);
  setLinearSolver(*app->Options(), options);
  app->Options()->SetStringValue("mu_strategy", options.mu_strategy);
  app->Options()->SetNumericValue("mu_init", options.mu_init);
  app->Options()->SetNumericValue("bound_push", options.bound_push);
  app->Options()->SetNumericValue("bound_frac", options.bound_frac);
  app->Options()->SetStringValue("bound_mult_init_method", options.bound_mult_init_method);
  app->Options()->SetNumericValue("constr_mult_init_max", options.constr_mult_init_max);
  // Ipopt's restoration phase reads the same option under "resto.", where its own default is 0;
  // set unprefixed, ours would reach it too (the robust config's path then changed, 1600.5 to
  // 868.3): kept at 0, so that the setting moves the solve's start only.
  app->Options()->SetNumericValue("resto.constr_mult_init_max", 0.0);
  app->Options()->SetIntegerValue("min_refinement_steps", options.min_refinement_steps);
  app->Options()->SetStringValue("nlp_scaling_method", options.nlp_scaling_method);
  app->Options()->SetIntegerValue("print_level", options.print_level);
  app->Options()->SetStringValue("sb", "yes");  // no Ipopt banner
  if (warm != nullptr) checkStart(nlp, *warm);
  if (warm != nullptr && !warm->multipliers.empty()) setWarmStart(*app->Options(), options);
  // No options file: Initialize() would read ./ipopt.opt, and a stray one in the working
  // directory would override these settings unseen by summary.json.
  if (app->Initialize(std::string()) != Ipopt::Solve_Succeeded)
    throw std::runtime_error("Ipopt could not be initialised (check the solver options)");
  if (options.linear_solver == "mumps")
    app->Jnlst()->AddJournal(new FactorizationCounter(result.profile.factorizations));
  LeastViolation best;
  Ipopt::SmartPtr<Ipopt::TNLP> adapter = new Adapter(nlp, result, best, options, warm);
  const kkt::KktStatistics before = kkt::threadKktStatistics();
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(adapter);
  if (options.linear_solver == "ldl") {
    result.profile.ldl = kkt::threadKktStatistics() - before;
    result.profile.factorizations = result.profile.ldl.factorizations;
  }
  if (status == Ipopt::Invalid_Option && options.linear_solver == "ldl")
    throw std::runtime_error(
        fmt::format("Ipopt could not load gaitopt's KKT solver {} (is it beside the program?)",
                    kkt::kLibraryName));
  if (result.x.size() == 0) {  // Ipopt failed before finalize_solution
    result.status = fmt::format("Ipopt_Error_{}", static_cast<int>(status));
    result.x = warm ? warm->x : nlp.initialGuess();
  }
  result.iterations = IsValid(app->Statistics()) ? app->Statistics()->IterationCount() : 0;
  if (IsValid(app->IpoptDataObject())) {
    Ipopt::TimingStatistics& timing = app->IpoptDataObject()->TimingStats();
    // Ipopt 3.11 does not time MUMPS's factorizations as such; this task holds them and the
    // back-solves of the augmented system.
    result.profile.linear_solver_time_s =
        timing.StdAugSystemSolverMultiSolve().TotalWallclockTime();
  }
  result.max_violation = maxViolation(nlp, result.x);
  keepLeastViolated(nlp, result, best);
  result.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

void SolveTotals::add(const SolveResult& r) {
  iterations += r.iterations;
  wall_time_s += r.wall_time_s;
  callback_time_s += r.callback_time_s;
  factorizations += r.profile.factorizations;
  ldl += r.profile.ldl;
  inertia_corrections += r.profile.inertia_corrections;
}

void SolveTotals::into(SolveResult& r) const {
  r.iterations = iterations;
  r.wall_time_s = wall_time_s;
  r.callback_time_s = callback_time_s;
  r.profile.factorizations = factorizations;
  r.profile.ldl = ldl;
  r.profile.inertia_corrections = inertia_corrections;
}

SolverOptions warmStarted(SolverOptions options) {
  options.mu_init = 1e-5;
  options.bound_push = 1e-6;
  options.bound_frac = 1e-6;
  options.bound_mult_init_method = "mu-based";
  return options;
}

}  // namespace gaitopt::ocp
