#pragma once
// Runs a job of the run pipeline on a worker thread while the calling Python thread waits with the GIL
// released, in short slices. Between slices the calling thread (holding the GIL) passes the latest
// progress to the Python callback `progress(fraction, sim_time_s)`, the run's warnings to
// warnings.warn, and runs PyErr_CheckSignals(): on Ctrl-C (KeyboardInterrupt) or an exception from the
// callback the run's CancelToken is set, the worker joined, and agglo.InterruptedError (Ctrl-C) or the
// callback's exception raised. The callback is never called from the worker or OpenMP threads.
#include <functional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file: the casters of std types must agree (ODR)

#include "agglo/run/command.hpp"

namespace agglo::python {

struct Released {
  run::CommandResult result;
  std::vector<std::string> messages;  // Reporter::info lines
};

// `job(ctx)` with ctx.reporter and ctx.cancel set; OpenMP threads of the worker = ctx.threads (0: all).
// `progress` may be None.
Released run_released(const std::function<run::CommandResult(const run::RunContext&)>& job, run::RunContext ctx,
                      const pybind11::object& progress);

}  // namespace agglo::python
