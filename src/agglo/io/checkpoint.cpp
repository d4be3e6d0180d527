#include "agglo/io/checkpoint.hpp"

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

std::uint64_t fnv1a(const char* p, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
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

void write_all(int fd, const char* p, std::size_t n, const std::string& name) {
  while (n > 0) {
    const ssize_t k = ::write(fd, p, n);
    if (k < 0) throw std::runtime_error(fmt::format("cannot write checkpoint {}", name));
    p += k;
    n -= static_cast<std::size_t>(k);
  }
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
  if (fd < 0) throw std::runtime_error(fmt::format("cannot create checkpoint {}", tmp.string()));
  if (fault_now()) {  // fault injection: die with half a checkpoint on disk
    write_all(fd, bytes.data(), bytes.size() / 2, tmp.string());
    ::fsync(fd);
    std::raise(SIGKILL);
  }
  write_all(fd, bytes.data(), bytes.size(), tmp.string());
  if (::fsync(fd) != 0 || ::close(fd) != 0)
    throw std::runtime_error(fmt::format("cannot write checkpoint {}", tmp.string()));
  std::filesystem::rename(tmp, path);
  sync_dir(out.path());
}

namespace {
std::string read_bytes(const std::filesystem::path& file) {
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

CheckpointReader read_checkpoint(const OutputDir& out, const CheckpointHeader& expect, CheckpointHeader& found) {
  const auto path = out.file(kCheckpointFile);
  const std::string file = path.string();
  std::string bytes = read_bytes(path);
  if (bytes.size() < sizeof kMagic + 4 + 8 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw ConfigError(fmt::format("checkpoint {}: not an agglo checkpoint", file));
  std::uint64_t sum;
  std::memcpy(&sum, bytes.data() + bytes.size() - 8, 8);
  if (sum != fnv1a(bytes.data(), bytes.size() - 8))
    throw ConfigError(fmt::format("checkpoint {}: checksum mismatch (corrupted or truncated file)", file));
  bytes.resize(bytes.size() - 8);
  CheckpointReader r(std::move(bytes), file);
  (void)r.u64();  // the magic, checked above
  const auto format = r.pod<std::uint32_t>();
  expect_equal(file, "format version", std::to_string(format), std::to_string(kCheckpointFormat));
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
