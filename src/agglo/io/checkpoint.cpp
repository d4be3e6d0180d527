#include "agglo/io/checkpoint.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/version.hpp"

namespace agglo::io {

namespace {

constexpr char kMagic[8] = {'A', 'G', 'G', 'L', 'O', 'C', 'K', 'P'};

// FNV-1a 64 (offset basis 14695981039346656037, prime 1099511628211). Format 1 used the basis
// 1469598103934665603 (a digit short: not FNV-1a, though a checksum as good); its files are refused by
// their format number, read before the checksum.
std::uint64_t fnv1a(const char* p, std::size_t n) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(p[i]);
    h *= 1099511628211ull;
  }
  return h;
}

// The whole file: magic, format, header, payload, checksum.
std::string encode(const CheckpointHeader& h, const std::string& payload) {
  CheckpointWriter w;
  w.pod(kMagic);
  w.pod(kCheckpointFormat);
  w.str(h.command);
  w.str(kVersion);
  w.str(kGitHash);
  w.str(h.config_hash);
  w.u64(h.step);
  w.f64(h.time);
  w.str(payload);
  std::string bytes = w.bytes();
  const std::uint64_t sum = fnv1a(bytes.data(), bytes.size());
  bytes.append(reinterpret_cast<const char*>(&sum), sizeof sum);
  return bytes;
}

int& write_count() {
  static int count = 0;
  return count;
}

// AGGLO_FAULT_KILL_CHECKPOINT=N: true on the N-th write of this process.
bool fault_now() {
  const int n = ++write_count();
  const char* env = std::getenv("AGGLO_FAULT_KILL_CHECKPOINT");
  return env && std::atoi(env) == n;
}

// 0, or the errno of the failed write.
int write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0 && errno == EINTR) continue;
    if (k < 0) return errno;
    p += k;
    n -= static_cast<std::size_t>(k);
  }
  return 0;
}

void sync_dir(const std::filesystem::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

std::string config_hash(const std::string& resolved_toml) {
  return fmt::format("{:016x}", fnv1a(resolved_toml.data(), resolved_toml.size()));
}

int checkpoint_writes() { return write_count(); }

bool has_checkpoint(const OutputDir& out) { return std::filesystem::exists(out.file(kCheckpointFile)); }

void write_checkpoint(const OutputDir& out, const CheckpointHeader& header, const std::string& payload) {
  const std::string bytes = encode(header, payload);
  const auto path = out.file(kCheckpointFile);
  auto tmp = path;
  tmp += fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw output_error(path, errno);
  if (fault_now()) {  // fault injection: die with half a checkpoint on disk
    (void)write_all(fd, bytes.data(), bytes.size() / 2);
    ::fsync(fd);
    std::raise(SIGKILL);
  }
  // A failed write (a full disk) removes the temporary file and keeps the previous checkpoint.
  int err = write_all(fd, bytes.data(), bytes.size());
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  std::error_code ec;
  if (err == 0) std::filesystem::rename(tmp, path, ec);
  if (err == 0 && ec) err = ec.value();
  if (err != 0) {
    std::filesystem::remove(tmp, ec);
    throw output_error(path, err);
  }
  sync_dir(out.path());
}

namespace {
// What a file that is not a regular file is, for the refusal.
const char* file_kind(std::filesystem::file_type t) {
  using std::filesystem::file_type;
  switch (t) {
    case file_type::directory: return "a directory";
    case file_type::fifo: return "a FIFO";
    case file_type::character: return "a character device";
    case file_type::block: return "a block device";
    case file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

// The file's bytes, after checking (without opening it: a FIFO would block) that it is a regular file,
// through symlinks, of at most max_bytes.
std::string read_bytes(const std::filesystem::path& file, double max_bytes) {
  std::error_code ec;
  const auto st = std::filesystem::status(file, ec);
  if (ec || st.type() != std::filesystem::file_type::regular)
    throw ConfigError(fmt::format("checkpoint {}: {}, not a checkpoint file; it cannot be resumed (remove it, or start "
                                  "again with --overwrite)", file.string(), ec ? ec.message() : file_kind(st.type())));
  const auto size = std::filesystem::file_size(file, ec);
  if (!ec && static_cast<double>(size) > max_bytes)
    throw ConfigError(fmt::format("checkpoint {}: {} bytes, more than the memory budget of {:.4g} bytes that reading "
                                  "it needs; raise --max-memory (AGGLO_MAX_MEMORY) or start again with --overwrite",
                                  file.string(), size, max_bytes));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw ConfigError(fmt::format("checkpoint {}: cannot be read", file.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void expect_equal(const std::string& file, const char* what, const std::string& found, const std::string& want) {
  if (found != want)
    throw ConfigError(fmt::format("checkpoint {}: written by {} {}, this run has {} {}; it cannot be resumed (start "
                                  "again with --overwrite)", file, what, found, what, want));
}
}  // namespace

CheckpointReader read_checkpoint(const OutputDir& out, const CheckpointHeader& expect, CheckpointHeader& found,
                                 double max_bytes) {
  const auto path = out.file(kCheckpointFile);
  const std::string file = path.string();
  std::string bytes = read_bytes(path, max_bytes);
  if (bytes.size() < sizeof kMagic + 4 + 8 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw ConfigError(fmt::format("checkpoint {}: not an agglo checkpoint", file));
  std::uint32_t format = 0;  // before the checksum: another format may sum differently (format 1)
  std::memcpy(&format, bytes.data() + sizeof kMagic, sizeof format);
  expect_equal(file, "format version", std::to_string(format), std::to_string(kCheckpointFormat));
  std::uint64_t sum;
  std::memcpy(&sum, bytes.data() + bytes.size() - 8, 8);
  if (sum != fnv1a(bytes.data(), bytes.size() - 8))
    throw ConfigError(fmt::format("checkpoint {}: checksum mismatch (corrupted or truncated file)", file));
  bytes.resize(bytes.size() - 8);
  CheckpointReader r(std::move(bytes), file);
  (void)r.u64();                  // the magic and
  (void)r.pod<std::uint32_t>();  // the format, checked above
  found.command = r.str();
  expect_equal(file, "command", found.command, expect.command);
  expect_equal(file, "agglo version", r.str(), kVersion);
  expect_equal(file, "build (git hash)", r.str(), kGitHash);
  found.config_hash = r.str();
  expect_equal(file, "config hash", found.config_hash, expect.config_hash);
  found.step = r.u64();
  found.time = r.f64();
  CheckpointReader payload(r.str(), file);
  r.expect_end();
  return payload;
}

}  // namespace agglo::io
