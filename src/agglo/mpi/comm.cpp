#include "agglo/mpi/comm.hpp"

#include <cstdlib>
#include <stdexcept>

#ifdef AGGLO_HAVE_MPI
#include <dlfcn.h>

#include <filesystem>

#include "agglo/mpi/backend.hpp"
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
const Backend* g_mpi = nullptr;  // set while a Session is active
int g_local_size = 1;

// The module built beside the executable (AGGLO_MPI_BACKEND_PATH), or one of that name in the directory
// of the running executable; RTLD_GLOBAL so that the MPI library's own plugins see its symbols.
const Backend* load_backend() {
  std::string path = AGGLO_MPI_BACKEND_PATH;
  if (!std::filesystem::exists(path)) {
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) path = (exe.parent_path() / std::filesystem::path(path).filename()).string();
  }
  void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!module) throw std::runtime_error(std::string("cannot load agglo's MPI module: ") + dlerror());
  auto* entry = reinterpret_cast<const Backend* (*)()>(dlsym(module, "agglo_mpi_backend"));
  if (!entry) throw std::runtime_error("agglo's MPI module " + path + " has no agglo_mpi_backend");
  return entry();
}
}  // namespace

Session::Session(int& argc, char**& argv) {
  if (!launched()) return;
  const Backend* mpi = load_backend();
  const bool multiple = mpi->init(argc, argv, g_local_size);
  g_mpi = mpi;
  active_ = true;
  if (!multiple)
    throw std::runtime_error("the MPI library does not support MPI_THREAD_MULTIPLE, which agglo's task farm needs");
}

Session::~Session() {
  if (active_) g_mpi->finalize();
  g_mpi = nullptr;
}

int rank() { return g_mpi ? g_mpi->rank() : 0; }
int size() { return g_mpi ? g_mpi->size() : 1; }
int local_size() { return g_mpi ? g_local_size : 1; }

void send(int dest, int tag, const std::string& bytes) {
  if (!g_mpi) throw std::logic_error("agglo::mpi::send without an MPI session");
  g_mpi->send(dest, tag, bytes);
}

bool try_receive(int tag, int& source, std::string& bytes) { return g_mpi && g_mpi->try_receive(tag, source, bytes); }

std::string receive(int source, int tag) {
  if (!g_mpi) throw std::logic_error("agglo::mpi::receive without an MPI session");
  return g_mpi->receive(source, tag);
}

std::string broadcast(const std::string& bytes) { return g_mpi ? g_mpi->broadcast(bytes) : bytes; }

void abort_all(int exit_code) {
  if (g_mpi) g_mpi->abort_all(exit_code);
  std::_Exit(exit_code);
}

void finish(int exit_code, double timeout_s, const std::function<void()>& before_abort) {
  if (g_mpi) g_mpi->finish(exit_code, timeout_s, before_abort);
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
