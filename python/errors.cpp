/// @file errors.cpp
/// The CLI's exit codes (io/exit_code.hpp) as Python exceptions, each carrying
/// `exit_code`: InputError (2, also a ValueError) for bad files and values, InfeasibleError (3)
/// for valid input describing something impossible, NotConvergedError (4) for a solve that
/// stopped early, GaitoptError (1) for the rest.
#include <stdexcept>
#include <string>

#include "config/config_error.hpp"
#include "io/exit_code.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace gaitopt::python {
namespace {

/// A new exception type in `m`; the module keeps it alive, the handle borrows it.
py::handle makeError(py::module_& m, const char* name, py::handle bases, int exit_code,
                     const char* doc) {
  py::object type = py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      (std::string("gaitopt.") + name).c_str(), doc, bases.ptr(), nullptr));
  if (!type) throw py::error_already_set();
  type.attr("exit_code") = exit_code;
  m.attr(name) = type;
  return type.ptr();  // borrowed: m keeps it
}

}  // namespace

void bindErrors(py::module_& m) {
  const py::handle base = makeError(m, "GaitoptError", PyExc_Exception, io::kExitFailure,
                                    "A gaitopt failure; exit_code is the CLI's exit code for it.");
  static py::handle input =
      makeError(m, "InputError", py::make_tuple(base, py::handle(PyExc_ValueError)),
                io::kExitInputError, "Bad input: a file, key or value (the CLI exits 2).");
  static py::handle infeasible =
      makeError(m, "InfeasibleError", base, io::kExitInfeasible,
                "Valid input describing something impossible (the CLI exits 3).");
  static py::handle not_converged =
      makeError(m, "NotConvergedError", base, io::kExitNotConverged,
                "The solver stopped without converging (the CLI exits 4).");
  static py::handle failure = base;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const config::ConfigError& e) {
      PyErr_SetString(input.ptr(), e.what());
    } catch (const std::invalid_argument& e) {
      PyErr_SetString(input.ptr(), e.what());
    } catch (const SolveFailed& e) {
      PyErr_SetString(e.infeasible ? infeasible.ptr() : not_converged.ptr(), e.what());
    } catch (const std::domain_error& e) {
      PyErr_SetString(infeasible.ptr(), e.what());
    } catch (const py::builtin_exception&) {
      throw;  // pybind11's own (TypeError, ...)
    } catch (const std::runtime_error& e) {
      PyErr_SetString(failure.ptr(), e.what());
    }
  });
}

}  // namespace gaitopt::python
