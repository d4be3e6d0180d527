#pragma once
// The MPI library behind agglo's task farm, loaded only when needed (comm.cpp). The MPI calls live in a
// small shared module (mpi_module.cpp, target agglo_mpi_module) that links the MPI library; comm.cpp opens
// it with dlopen when an MPI launcher started the process, so a plain `agglo` run does not load
// libmpi and its dependencies (hwloc, libevent, PMIx: about 9 ms of CPU and 190 page faults per
// process, most of `agglo --version`'s start-up; docs/timings.md). Internal to src/agglo/mpi.
#include <functional>
#include <string>

namespace agglo::mpi {

// Operations of comm.hpp on an initialised MPI library (MPI_COMM_WORLD). Compiled by the same compiler
// as the caller, so C++ types cross the boundary.
struct Backend {
  // MPI_Init_thread(MPI_THREAD_MULTIPLE); false when the library provides less. `local_size`: ranks on
  // this machine (MPI_COMM_TYPE_SHARED).
  bool (*init)(int& argc, char**& argv, int& local_size);
  void (*finalize)();
  int (*rank)();
  int (*size)();
  void (*send)(int dest, int tag, const std::string& bytes);
  bool (*try_receive)(int tag, int& source, std::string& bytes);
  std::string (*receive)(int source, int tag);
  std::string (*broadcast)(const std::string& bytes);
  void (*abort_all)(int exit_code);  // does not return
  void (*finish)(int exit_code, double timeout_s, const std::function<void()>& before_abort);
};

}  // namespace agglo::mpi

// The module's one exported symbol: its table of operations.
extern "C" const agglo::mpi::Backend* agglo_mpi_backend();
