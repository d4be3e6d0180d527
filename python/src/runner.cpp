// run_released (runner.hpp).
#include "runner.hpp"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include <omp.h>

#include "agglo/core/error.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

constexpr auto kSlice = std::chrono::milliseconds(50);  // longest wait between checks for Ctrl-C

// Collects what the run reports, from any thread; the calling thread drains it while holding the GIL.
class QueueReporter final : public run::Reporter {
 public:
  void progress(std::string_view, double fraction, double sim_time_s) override {
    std::lock_guard lock(mutex_);
    latest_ = {fraction, sim_time_s};
  }
  void warning(std::string_view message) override {
    std::lock_guard lock(mutex_);
    warnings_.emplace_back(message);
  }
  void info(std::string_view message) override {
    std::lock_guard lock(mutex_);
    infos_.emplace_back(message);
  }
  // Passes the queued warnings and the latest progress to Python (GIL held); Python errors propagate.
  void deliver(const py::object& callback) {
    std::optional<std::pair<double, double>> p;
    std::vector<std::string> w;
    {
      std::lock_guard lock(mutex_);
      p = std::exchange(latest_, std::nullopt);
      w.swap(warnings_);
    }
    for (const auto& message : w)
      py::module_::import("warnings").attr("warn")(message, py::handle(PyExc_RuntimeWarning), 1);
    if (p && !callback.is_none()) callback(p->first, p->second);
  }
  std::vector<std::string> infos() {
    std::lock_guard lock(mutex_);
    return infos_;
  }

 private:
  std::mutex mutex_;
  std::optional<std::pair<double, double>> latest_;
  std::vector<std::string> warnings_, infos_;
};

// The worker thread and what it leaves behind.
struct Worker {
  std::mutex mutex;
  std::condition_variable done_cv;
  bool done = false;
  run::CommandResult result;
  std::exception_ptr error;
  std::thread thread;

  // Waits up to one slice for the end of the job (GIL released); true when it has ended.
  bool wait_slice() {
    py::gil_scoped_release release;
    std::unique_lock lock(mutex);
    return done_cv.wait_for(lock, kSlice, [&] { return done; });
  }
  void join() {
    if (!thread.joinable()) return;
    py::gil_scoped_release release;
    thread.join();
  }
};

}  // namespace

Released run_released(const std::function<run::CommandResult(const run::RunContext&)>& job, run::RunContext ctx,
                      const py::object& progress) {
  QueueReporter reporter;
  run::CancelToken cancel;
  ctx.reporter = &reporter;
  ctx.cancel = &cancel;
  Worker w;
  w.thread = std::thread([&] {
    if (ctx.threads > 0) omp_set_num_threads(ctx.threads);  // per thread: applies to this worker's runs
    const CancelScope cancel_scope(ctx.cancel);  // the engines poll it (core/cancel.hpp)
    try {
      w.result = job(ctx);
    } catch (...) {
      w.error = std::current_exception();
    }
    std::lock_guard lock(w.mutex);
    w.done = true;
    w.done_cv.notify_all();
  });
  try {
    for (bool finished = false; !finished;) {
      finished = w.wait_slice();
      reporter.deliver(progress);
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  } catch (py::error_already_set& e) {  // Ctrl-C or an exception from the callback: stop the run first
    cancel.cancel();
    w.join();
    if (e.matches(PyExc_KeyboardInterrupt)) throw InterruptedError("interrupted");
    throw;
  } catch (...) {
    cancel.cancel();
    w.join();
    throw;
  }
  w.join();
  if (w.error) std::rethrow_exception(w.error);
  return {std::move(w.result), reporter.infos()};
}

}  // namespace agglo::python
