#include "agglo/mpi/comm.hpp"

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#ifdef AGGLO_HAVE_MPI
#include <mpi.h>
#endif

namespace agglo::mpi {

bool launched() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v)) return true;
  return false;
}

#ifdef AGGLO_HAVE_MPI

bool available() { return true; }

namespace {
bool g_active = false;
int g_local_size = 1;

// Sleeps between tests of a pending request: short at first (messages of the farm answer in
// microseconds), then 1 ms (a rank waiting for a long job costs nothing).
void wait(MPI_Request& request) {
  int done = 0;
  for (int k = 0;; ++k) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(std::chrono::microseconds(k < 100 ? 20 : 1000));
  }
}
}  // namespace

Session::Session(int& argc, char**& argv) {
  if (!launched()) return;
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided);
  g_active = active_ = true;
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
  MPI_Comm_size(local, &g_local_size);
  MPI_Comm_free(&local);
  if (provided < MPI_THREAD_MULTIPLE)
    throw std::runtime_error("the MPI library does not support MPI_THREAD_MULTIPLE, which agglo's task farm needs");
}

Session::~Session() {
  if (active_) MPI_Finalize();
  g_active = false;
}

int rank() {
  int r = 0;
  if (g_active) MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  int s = 1;
  if (g_active) MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

int local_size() { return g_active ? g_local_size : 1; }

void send(int dest, int tag, const std::string& bytes) {
  MPI_Request request;
  MPI_Isend(bytes.data(), static_cast<int>(bytes.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD, &request);
  wait(request);
}

namespace {
std::string receive_matched(MPI_Message& message, MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string bytes(static_cast<std::size_t>(count), '\0');
  MPI_Mrecv(bytes.data(), count, MPI_CHAR, &message, MPI_STATUS_IGNORE);
  return bytes;
}
}  // namespace

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
    std::this_thread::sleep_for(std::chrono::microseconds(k < 100 ? 20 : 1000));
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
  if (!g_active) return;
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
    std::this_thread::sleep_for(std::chrono::microseconds(k < 100 ? 20 : 1000));
  }
}

#else  // one process

bool available() { return false; }
Session::Session(int&, char**&) {}
Session::~Session() = default;
int rank() { return 0; }
int size() { return 1; }
int local_size() { return 1; }
void send(int, int, const std::string&) { throw std::logic_error("agglo was built without MPI"); }
bool try_receive(int, int&, std::string&) { return false; }
std::string receive(int, int) { throw std::logic_error("agglo was built without MPI"); }
std::string broadcast(const std::string& bytes) { return bytes; }
void abort_all(int exit_code) { std::_Exit(exit_code); }
void finish(int, double, const std::function<void()>&) {}

#endif

}  // namespace agglo::mpi
