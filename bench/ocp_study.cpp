/// @file ocp_study.cpp
/// The collocation study (bench/ocp_study.hpp): speed against accuracy of the OCP.
/// Usage: ocp_study collocation|derivatives|guesses [--repeats N] [--seeds N] [--tol T]
///   collocation: both schemes on coarse to fine meshes, median of N solves (default 3) at
///                Ipopt tolerance T (default 1e-9: solver error far below discretisation error)
///   derivatives: exact / limited-memory / limited-memory + finite-difference Jacobian
///   guesses:     polynomial, naive and N seeds (default 10) of perturbed optima per noise level
/// Prints the study's CSV to stdout, one line of progress per study to stderr.
/// Exit codes: 0 done, 2 bad command line, 1 anything else.
#include <chrono>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include <fmt/format.h>

#include "bench/ocp_study.hpp"

namespace {

using namespace gaitopt;

struct Options {
  std::string study;
  int repeats = 3;
  int seeds = 10;
  double tolerance = 1e-9;
};

constexpr const char* kUsage =
    "usage: ocp_study collocation|derivatives|guesses [--repeats N] [--seeds N] [--tol T]";

[[noreturn]] void badUsage(const std::string& what) {
  std::cerr << "error: " << what << "\n" << kUsage << "\n";
  std::exit(2);
}

/// The positive number after `flag`.
double positiveValue(int argc, char** argv, int& i) {
  const std::string flag = argv[i];
  if (++i >= argc) badUsage(flag + " needs a value");
  char* end = nullptr;
  const double v = std::strtod(argv[i], &end);
  if (end == argv[i] || *end != '\0' || !(v > 0)) {
    badUsage(fmt::format("{}: expected a positive number, got '{}'", flag, argv[i]));
  }
  return v;
}

int positiveCount(int argc, char** argv, int& i) {
  const std::string flag = argv[i];
  const double v = positiveValue(argc, argv, i);
  if (v != static_cast<int>(v)) badUsage(fmt::format("{}: expected a whole number", flag));
  return static_cast<int>(v);
}

Options parse(int argc, char** argv) {
  if (argc < 2) badUsage("missing the study");
  Options o{.study = argv[1]};
  if (o.study != "collocation" && o.study != "derivatives" && o.study != "guesses") {
    badUsage("unknown study '" + o.study + "'");
  }
  for (int i = 2; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--repeats") {
      o.repeats = positiveCount(argc, argv, i);
    } else if (flag == "--seeds") {
      o.seeds = positiveCount(argc, argv, i);
    } else if (flag == "--tol") {
      o.tolerance = positiveValue(argc, argv, i);
    } else {
      badUsage("unknown option '" + flag + "'");
    }
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    const auto start = std::chrono::steady_clock::now();
    const auto cases = bench::studyCases();
    if (o.study == "collocation") bench::collocationStudy(cases, o.repeats, o.tolerance, std::cout);
    if (o.study == "derivatives") bench::derivativeStudy(cases, o.repeats, std::cout);
    if (o.study == "guesses") bench::guessStudy(cases, o.seeds, std::cout);
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    std::cerr << fmt::format("ocp_study {}: {:.1f} s\n", o.study, took.count());
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
