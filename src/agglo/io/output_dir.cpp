#include "agglo/io/output_dir.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sys/types.h>
#include <unistd.h>

#include <fmt/format.h>
#include <omp.h>

#include "agglo/core/error.hpp"
#include "agglo/core/version.hpp"

namespace agglo {

void write_file_atomic(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body) {
  auto tmp = path;
  tmp += fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
    try {
      body(out);
    } catch (...) {
      out.close();
      std::filesystem::remove(tmp);
      throw;
    }
    out.flush();
    if (!out) {
      std::filesystem::remove(tmp);
      throw std::runtime_error(fmt::format("error while writing {}", tmp.string()));
    }
  }
  std::filesystem::rename(tmp, path);
}

namespace {
// True for "<name>.tmp-<pid>" written by a process that no longer runs.
bool orphaned_tmp(const std::filesystem::path& p) {
  const std::string name = p.filename().string();
  const auto at = name.rfind(".tmp-");
  if (at == std::string::npos || at + 5 == name.size()) return false;
  const std::string digits = name.substr(at + 5);
  if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return false;
  const long pid = std::stol(digits);
  if (pid == static_cast<long>(::getpid())) return false;
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// Removes the temporary files a killed run left in `dir` and its sub-folders (snapshots/, case_*/).
void remove_orphaned_tmp(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    if (it.depth() >= 2) it.disable_recursion_pending();
    if (it->is_regular_file(ec) && orphaned_tmp(it->path())) fs::remove(it->path(), ec);
  }
}

// ConfigError naming the folder and the reason unless a file can be created in it.
void check_writable(const std::filesystem::path& dir) {
  const auto probe = dir / fmt::format(".agglo-write-check.tmp-{}", static_cast<long>(::getpid()));
  errno = 0;
  std::ofstream f(probe, std::ios::binary | std::ios::trunc);
  const int err = errno;
  if (!f)
    throw ConfigError(fmt::format("output folder {}: cannot write in it: {}", dir.string(),
                                  err ? std::strerror(err) : "unknown reason"));
  f.close();
  std::error_code ec;
  std::filesystem::remove(probe, ec);
}
}  // namespace

OutputDir::OutputDir(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) throw ConfigError(fmt::format("output folder {}: cannot create it: {}", dir_.string(), ec.message()));
  if (!std::filesystem::is_directory(dir_, ec))
    throw ConfigError(fmt::format("output folder {}: exists and is not a folder", dir_.string()));
  check_writable(dir_);
  remove_orphaned_tmp(dir_);
}

void OutputDir::write(const std::string& name, const std::function<void(std::ostream&)>& body) const {
  auto p = dir_ / name;
  std::filesystem::create_directories(p.parent_path());
  write_file_atomic(p, body);
}

void OutputDir::write_text(const std::string& name, const std::string& text) const {
  write(name, [&](std::ostream& o) { o << text; });
}

void OutputDir::write_json(const std::string& name, const nlohmann::json& j) const {
  write(name, [&](std::ostream& o) { o << j.dump(2) << '\n'; });
}

nlohmann::json run_metadata(const std::string& command, const std::string& case_file, long long seed,
                            double wall_time_s) {
  auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return nlohmann::json{{"program", "agglo"},
                        {"version", kVersion},
                        {"git_hash", kGitHash},
                        {"command", command},
                        {"case", case_file},
                        {"seed", seed},
                        {"threads", omp_get_max_threads()},
                        {"wall_time_s", wall_time_s},
                        {"finished_utc", buf}};
}

std::filesystem::path default_output_dir(const std::string& case_file, const std::string& command) {
  auto stem = std::filesystem::path(case_file).stem().string();
  return std::filesystem::path("results") / (command.empty() ? stem : stem + "-" + command);
}

}  // namespace agglo
