// The exception classes of the module, one per failure class of the CLI, and the translation of the
// C++ errors (core/error.hpp) into them with the CLI's one-line messages:
//   agglo.Error             base class (an Exception)
//   agglo.ConfigError       bad input: key, value, file (also a ValueError)         CLI exit 2
//   agglo.LimitError        a valid case beyond a run budget (steps, memory, output) CLI exit 2
//   agglo.NumericalError    blow-up or invalid run (also an ArithmeticError)         CLI exit 3
//   agglo.InterruptedError  run cancelled by Ctrl-C (also a KeyboardInterrupt)       CLI exit 130
#include <iterator>
#include <string>
#include <string_view>
#include <utility>

#include <pybind11/pybind11.h>

#include "agglo/core/error.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

struct ExceptionClass {
  const char* name;
  const char* builtin_base;  // a second base besides agglo.Error (nullptr: none)
  const char* doc;
};

// The classes below agglo.Error, in the order of `classes` in bind_errors.
constexpr ExceptionClass kClasses[] = {
    {"ConfigError", "ValueError",
     "Bad input: a key, value or file the case rules reject (the CLI's exit code 2). The message is the CLI's one "
     "line naming file, key, value and what is allowed. Also a ValueError."},
    {"LimitError", nullptr,
     "A valid case whose estimated steps, memory or output exceed a run budget (docs/limits.md; raise it with the "
     "keyword arguments max_steps, max_memory, max_output of the command functions or the environment variables "
     "AGGLO_MAX_STEPS, AGGLO_MAX_MEMORY, AGGLO_MAX_OUTPUT)."},
    {"NumericalError", "ArithmeticError",
     "A numerical blow-up detected during a run (NaN, energy explosion), or a run that cannot observe its experiment "
     "(the target not one agglomerate, torn apart before the launch, or never hit by the projectile); the CLI's exit "
     "code 3. Also an ArithmeticError."},
    {"InterruptedError", "KeyboardInterrupt",
     "The run was cancelled (Ctrl-C while it ran; the CLI's exit code 130). Also a KeyboardInterrupt, so `except "
     "KeyboardInterrupt` stops a script as usual; an output folder (out=) keeps what was written, marked incomplete "
     "in run.json."},
};

// A budget message in Python's words: the CLI options (--max-steps ...) become the keyword arguments of
// the command functions (max_steps= ...), which every function that checks budgets takes.
std::string python_words(std::string message) {
  for (const auto& [cli, keyword] : {std::pair{"--max-steps", "max_steps="}, std::pair{"--max-memory", "max_memory="},
                                     std::pair{"--max-output", "max_output="}})
    for (auto at = message.find(cli); at != std::string::npos; at = message.find(cli, at))
      message.replace(at, std::string_view(cli).size(), keyword);
  return message;
}

py::handle new_exception(py::module_& m, const char* name, const char* doc, const py::tuple& bases) {
  const std::string qualified = std::string("agglo.") + name;
  PyObject* cls = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!cls) throw py::error_already_set();
  m.attr(name) = py::handle(cls);
  return cls;  // the reference is kept for the module's lifetime
}

}  // namespace

void bind_errors(py::module_& m) {
  auto builtins = py::module_::import("builtins");
  const py::handle error = new_exception(m, "Error", "Base class of the errors raised by agglo.",
                                         py::make_tuple(builtins.attr("Exception")));
  static py::handle classes[std::size(kClasses)];
  for (std::size_t k = 0; k < std::size(kClasses); ++k) {
    const auto& c = kClasses[k];
    classes[k] = new_exception(m, c.name, c.doc,
                               c.builtin_base ? py::make_tuple(error, builtins.attr(c.builtin_base)) : py::make_tuple(error));
  }
  static const py::handle &config = classes[0], &limit = classes[1], &numerical = classes[2], &interrupted = classes[3];
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const LimitError& e) {  // before its base class ConfigError
      PyErr_SetString(limit.ptr(), python_words(one_line(e.what())).c_str());
    } catch (const ConfigError& e) {
      PyErr_SetString(config.ptr(), one_line(e.what()).c_str());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical.ptr(), one_line(e.what()).c_str());
    } catch (const InterruptedError& e) {
      PyErr_SetString(interrupted.ptr(), one_line(e.what()).c_str());
    }
  });
}

}  // namespace agglo::python
