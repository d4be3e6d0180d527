#pragma once
// The few MPI operations agglo's task farm needs (run/ensemble_farm.cpp), behind a header that does not
// include <mpi.h>, so the library builds and behaves as one process without MPI (CMake option AGGLO_MPI).
// MPI is initialised only when the process was started by an MPI launcher (mpirun / srun set the
// environment variables checked by launched()); a plain `agglo` never touches MPI. Waits never spin a
// core: they test the request and sleep briefly (ranks of an oversubscribed run share cores, and an
// idle rank must not slow the others).
#include <functional>
#include <string>

namespace agglo::mpi {

// True when the library was built with MPI (AGGLO_HAVE_MPI).
bool available();

// True when an MPI launcher started this process (OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK is set).
bool launched();

// Initialises MPI (MPI_THREAD_MULTIPLE) when built with MPI and launched; finalises on destruction.
// std::runtime_error when the MPI library offers less than MPI_THREAD_MULTIPLE.
class Session {
 public:
  Session(int& argc, char**& argv);
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

 private:
  bool active_ = false;
};

int rank();  // 0 without an active Session
int size();  // 1 without an active Session
int local_size();  // ranks of this run on this machine (MPI_COMM_TYPE_SHARED); 1 without an active Session

// Point-to-point messages of bytes in MPI_COMM_WORLD (thread-safe; only with size() > 1).
void send(int dest, int tag, const std::string& bytes);
// A message waiting from any rank with `tag`, received into `bytes`; false when there is none now.
bool try_receive(int tag, int& source, std::string& bytes);
// Waits (without spinning) for the message from `source` with `tag`.
std::string receive(int source, int tag);
// Rank 0's `bytes` on every rank (returned); waits without spinning.
std::string broadcast(const std::string& bytes);

// Ends every rank of the run at once (after a failure that the other ranks cannot know of).
[[noreturn]] void abort_all(int exit_code);

// The last call of every rank before it exits with `exit_code`: waits (without spinning) until every
// rank has arrived. A rank that failed (exit_code != 0) waits at most `timeout_s` seconds and then ends
// every rank (abort_all), so that a failure met by one rank alone (a full disk on rank 0, a scratch
// folder another rank cannot create) cannot leave the others waiting for it forever.
// `before_abort` runs just before (e.g. to print this rank's error).
void finish(int exit_code, double timeout_s, const std::function<void()>& before_abort);

}  // namespace agglo::mpi
