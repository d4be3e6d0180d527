// The MPI calls of agglo's task farm (comm.hpp), built as the shared module agglo_mpi_module that
// comm.cpp opens only in processes an MPI launcher started (backend.hpp). Waits never spin a core: they
// test the request and sleep briefly.
#include "agglo/mpi/backend.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <thread>

namespace {

// Sleeps between tests of a pending request: short at first (messages of the farm answer in
// microseconds), then 1 ms (a rank waiting for a long job costs nothing).
void pause(int k) { std::this_thread::sleep_for(std::chrono::microseconds(k < 100 ? 20 : 1000)); }

void wait(MPI_Request& request) {
  int done = 0;
  for (int k = 0;; ++k) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    pause(k);
  }
}

bool init(int& argc, char**& argv, int& local_size) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided);
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
  MPI_Comm_size(local, &local_size);
  MPI_Comm_free(&local);
  return provided >= MPI_THREAD_MULTIPLE;
}

void finalize() { MPI_Finalize(); }

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

void send(int dest, int tag, const std::string& bytes) {
  MPI_Request request;
  MPI_Isend(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD, &request);
  wait(request);
}

std::string receive_matched(MPI_Message& message, MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string bytes(static_cast<std::size_t>(count), '\0');
  MPI_Mrecv(bytes.data(), count, MPI_CHAR, &message, MPI_STATUS_IGNORE);
  return bytes;
}

bool try_receive(int tag, int& source, std::string& bytes) {
  int found = 0;
  MPI_Message message;
  MPI_Status status;
  MPI_Improbe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &found, &message, &status);
  if (!found) return false;
  source = status.MPI_SOURCE;
  bytes = receive_matched(message, status);
  return true;
}

std::string receive(int source, int tag) {
  for (int k = 0;; ++k) {
    int found = 0;
    MPI_Message message;
    MPI_Status status;
    MPI_Improbe(source, tag, MPI_COMM_WORLD, &found, &message, &status);
    if (found) return receive_matched(message, status);
    pause(k);
  }
}

std::string broadcast(const std::string& bytes) {
  unsigned long long n = bytes.size();
  MPI_Request request;
  MPI_Ibcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD, &request);
  wait(request);
  std::string out = rank() == 0 ? bytes : std::string(n, '\0');
  MPI_Ibcast(out.data(), static_cast<int>(n), MPI_CHAR, 0, MPI_COMM_WORLD, &request);
  wait(request);
  return out;
}

void abort_all(int exit_code) {
  MPI_Abort(MPI_COMM_WORLD, exit_code);
  std::_Exit(exit_code);
}

void finish(int exit_code, double timeout_s, const std::function<void()>& before_abort) {
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  const auto start = std::chrono::steady_clock::now();
  int done = 0;
  for (int k = 0;; ++k) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    if (exit_code != 0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > timeout_s) {
      if (before_abort) before_abort();
      abort_all(exit_code);
    }
    pause(k);
  }
}

constexpr agglo::mpi::Backend kBackend{init,    finalize,  rank,      size,     send, try_receive,
                                       receive, broadcast, abort_all, finish};

}  // namespace

extern "C" const agglo::mpi::Backend* agglo_mpi_backend() { return &kBackend; }
