#include "agglo/io/output_dir.hpp"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <ctime>
#include <fstream>
#include <memory>
#include <streambuf>
#include <sys/types.h>
#include <unistd.h>

#include <fmt/format.h>
#include <omp.h>

#include "agglo/core/cancel.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/version.hpp"

namespace agglo {

OutputError output_error(const std::filesystem::path& file, const std::string& reason) {
  return OutputError(fmt::format("cannot write {}: {} (free space, or choose another --out)", file.string(), reason));
}

OutputError output_error(const std::filesystem::path& file, int err) {
  return output_error(file, err != 0 ? std::generic_category().message(err) : std::string("write failed"));
}

namespace {
// The stream a file is written through: it collects the bytes in chunks of 1 MiB and hands each to the
// file after polling the cancel token (core/cancel.hpp), so that Ctrl-C or SIGTERM stops a long write
// (a 500 MB surface.vtu takes seconds) within one chunk. A failed file write keeps its errno.
class PollingBuf : public std::streambuf {
 public:
  // The buffer is left uninitialised: zeroing 1 MiB for every file written (and faulting in its pages) cost
  // a small run ~1 M instructions per output file (issue 27 item 2).
  explicit PollingBuf(std::filebuf& file) : file_(file), buf_(std::make_unique_for_overwrite<char[]>(kSize)) { reset(); }
  int error() const { return err_; }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override {
    if (!drain()) return -1;
    errno = 0;
    if (file_.pubsync() == 0) return 0;
    err_ = errno != 0 ? errno : EIO;
    return -1;
  }

 private:
  static constexpr std::size_t kSize = std::size_t{1} << 20;
  void reset() { setp(buf_.get(), buf_.get() + kSize); }
  bool drain() {
    poll_cancel();
    const std::streamsize n = pptr() - pbase();
    errno = 0;
    if (n > 0 && file_.sputn(pbase(), n) != n) {
      err_ = errno != 0 ? errno : EIO;
      return false;
    }
    reset();
    return true;
  }
  std::filebuf& file_;
  std::unique_ptr<char[]> buf_;
  int err_ = 0;
};
}  // namespace

void write_file_atomic(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body) {
  auto tmp = path;
  tmp += fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  std::error_code ec;
  errno = 0;
  std::filebuf file;
  if (!file.open(tmp, std::ios::out | std::ios::binary | std::ios::trunc)) throw output_error(path, errno);
  const WriteCancelScope live;  // a write begun after an interruption is finished
  PollingBuf buf(file);
  std::ostream out(&buf);
  out.exceptions(std::ios::badbit);  // the stream rethrows what the buffer throws (an interruption)
  int err = 0;
  try {
    body(out);
    out.flush();
  } catch (const std::ios_base::failure&) {  // the file refused bytes (a full disk)
    err = buf.error() != 0 ? buf.error() : EIO;
  } catch (...) {
    file.close();
    std::filesystem::remove(tmp, ec);
    throw;
  }
  errno = 0;
  if (!file.close() && err == 0) err = errno != 0 ? errno : EIO;  // a full disk may fail only here
  if (err == 0) std::filesystem::rename(tmp, path, ec);
  if (err == 0 && ec) err = ec.value();
  if (err != 0) {
    std::filesystem::remove(tmp, ec);
    throw output_error(path, err);
  }
}

namespace {
// The writer's pid of a temporary file "<name>.tmp-<pid>"; 0 for any other name.
long tmp_owner(const std::filesystem::path& p) {
  const std::string name = p.filename().string();
  const auto at = name.rfind(".tmp-");
  if (at == std::string::npos || at + 5 == name.size()) return 0;
  const std::string digits = name.substr(at + 5);
  if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return 0;
  return std::stol(digits);
}

// True for "<name>.tmp-<pid>" written by a process that no longer runs.
bool orphaned_tmp(const std::filesystem::path& p) {
  const long pid = tmp_owner(p);
  if (pid == 0 || pid == static_cast<long>(::getpid())) return false;
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

namespace {
// The files that mark a folder as an agglo output folder.
bool is_run_marker(const std::string& name) {
  return name == "run.json" || name == "config.resolved.toml" || name == "journal.jsonl";
}

// The folder's run.json (an empty object when it is missing or unreadable).
nlohmann::json run_record(const std::filesystem::path& dir) {
  std::ifstream in(dir / "run.json");
  auto j = nlohmann::json::parse(in, nullptr, false);
  return j.is_object() ? j : nlohmann::json::object();
}

std::string text_field(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string("unknown");
}

// Removes every entry of `dir` (the folder itself stays).
void clear_folder(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    fs::remove_all(e.path(), ec);
    if (ec) throw ConfigError(fmt::format("output folder {}: --overwrite cannot remove {}: {}", dir.string(),
                                          e.path().filename().string(), ec.message()));
  }
}
}  // namespace

void claim_output_folder(const std::filesystem::path& dir, FolderPolicy policy, std::string_view command) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;  // missing (created later) or not a folder (OutputDir reports it)
  bool marked = false, other = false;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (is_run_marker(name)) marked = true;
    else if (tmp_owner(e.path()) == 0) other = true;  // temporary files alone do not make a run
  }
  if (!marked && !other) return;
  if (!marked)
    throw ConfigError(fmt::format("output folder {}: holds files that are not an agglo run; choose a new or empty "
                                  "folder with --out", dir.string()));
  if (policy == FolderPolicy::overwrite) {
    clear_folder(dir);
    return;
  }
  const auto rec = run_record(dir);
  const std::string held = text_field(rec, "command"), status = text_field(rec, "status");
  if (policy == FolderPolicy::resume && held == command) return;
  if (policy == FolderPolicy::resume)
    throw ConfigError(fmt::format("output folder {}: --resume continues only a '{}' run, the folder holds a '{}' run; "
                                  "choose another --out", dir.string(), command, held));
  throw ConfigError(fmt::format("output folder {}: already holds a '{}' run (status {}); pass --overwrite to replace "
                                "it or --resume to continue it", dir.string(), held, status));
}

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

std::string cpu_level() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();  // (the levels' defining features, names both GCC and clang know)
  const bool v2 = __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt");
  const bool v3 = v2 && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
  const bool v4 = v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                  __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
                  __builtin_cpu_supports("avx512vl");
  return v4 ? "x86-64-v4" : v3 ? "x86-64-v3" : v2 ? "x86-64-v2" : "x86-64";
#else
  return "other";
#endif
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
                        {"cpu_level", cpu_level()},
                        {"wall_time_s", wall_time_s},
                        {"finished_utc", buf}};
}

std::filesystem::path default_output_dir(const std::string& case_file, const std::string& command) {
  auto stem = std::filesystem::path(case_file).stem().string();
  return std::filesystem::path("results") / (command.empty() ? stem : stem + "-" + command);
}

}  // namespace agglo
