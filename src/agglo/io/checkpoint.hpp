#pragma once
// Checkpoint files of restartable runs (--checkpoint / --resume). One binary file, `checkpoint.bin`
// in the output folder, written atomically (temporary name, fsync, rename), so a run killed at any
// moment — even in the middle of a checkpoint write — leaves the previous checkpoint intact.
//
// Layout (little-endian): magic "AGGLOCKP", format version (u32), header strings (command, agglo
// version, git hash, hash of the resolved config), step (u64), simulated time (f64), payload length
// (u64), payload, FNV-1a 64 checksum of all preceding bytes (u64). The payload is the engine's own
// state, written and read field by field with CheckpointWriter / CheckpointReader.
//
// Reading refuses (ConfigError, one line naming the file and both values) a file that is truncated,
// fails its checksum, or was written by another format version, another build (version or git hash)
// or another resolved config.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/io/output_dir.hpp"

namespace agglo::io {

inline constexpr const char* kCheckpointFile = "checkpoint.bin";
// 2: the checksum and config hash are FNV-1a 64 with its real offset basis (1: a basis a digit short).
inline constexpr std::uint32_t kCheckpointFormat = 2;

// Serialises values in order into a byte string.
class CheckpointWriter {
 public:
  void u64(std::uint64_t v) { raw(&v, sizeof v); }
  void i64(std::int64_t v) { raw(&v, sizeof v); }
  void f64(double v) { raw(&v, sizeof v); }
  void boolean(bool v) { u64(v ? 1 : 0); }
  void str(const std::string& s) {
    u64(s.size());
    raw(s.data(), s.size());
  }
  // A vector of trivially copyable values (numbers, plain structs of numbers), length first.
  template <class T>
  void pod_vector(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    u64(v.size());
    raw(v.data(), v.size() * sizeof(T));
  }
  template <class T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    raw(&v, sizeof v);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  void raw(const void* p, std::size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string bytes_;
};

// Reads values back in the order they were written; ConfigError naming the file on running past the end.
// Each engine owns its payload and serialises it with these (acoustics/, sectional/, impact/checkpoint).
class CheckpointReader {
 public:
  CheckpointReader(std::string bytes, std::string file) : bytes_(std::move(bytes)), file_(std::move(file)) {}
  std::uint64_t u64() { return get<std::uint64_t>(); }
  std::int64_t i64() { return get<std::int64_t>(); }
  double f64() { return get<double>(); }
  bool boolean() { return u64() != 0; }
  std::string str() {
    const auto n = u64();
    need(n, n);
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  template <class T>
  std::vector<T> pod_vector() {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto n = u64();
    need(n * sizeof(T), n);
    std::vector<T> v(n);
    if (n) std::memcpy(v.data(), bytes_.data() + at_, n * sizeof(T));
    at_ += n * sizeof(T);
    return v;
  }
  template <class T>
  T pod() {
    return get<T>();
  }
  bool at_end() const { return at_ == bytes_.size(); }
  // ConfigError unless every byte was read (a payload the reader does not fully understand).
  void expect_end() const {
    if (!at_end())
      throw ConfigError(fmt::format("checkpoint {}: {} unread bytes at the end of its payload (written by another "
                                    "layout)", file_, bytes_.size() - at_));
  }
  const std::string& file() const { return file_; }

 private:
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>);
    need(sizeof(T), 1);
    T v;
    std::memcpy(&v, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  void need(std::size_t n, std::uint64_t count) const {
    if (count > bytes_.size() || n > bytes_.size() - at_)
      throw ConfigError(fmt::format("checkpoint {}: truncated payload (needs {} more bytes at offset {} of {})", file_,
                                    n, at_, bytes_.size()));
  }
  std::string bytes_;
  std::string file_;
  std::size_t at_ = 0;
};

// What identifies the run a checkpoint belongs to.
struct CheckpointHeader {
  std::string command;         // e.g. "acoustic"
  std::string config_hash;     // hash_of_config(resolved TOML)
  std::uint64_t step = 0;      // engine step at the checkpoint
  double time = 0.0;           // simulated time at the checkpoint [s]
};

// Hex FNV-1a 64 of a resolved config's text (what a checkpoint is tied to).
std::string config_hash(const std::string& resolved_toml);

// Writes `payload` under `header` into out/checkpoint.bin atomically. Fault injection for tests: when
// the environment variable AGGLO_FAULT_KILL_CHECKPOINT=N is set, the N-th checkpoint write of the
// process (counting from 1) sends SIGKILL to the process after half of the temporary file is on disk.
void write_checkpoint(const OutputDir& out, const CheckpointHeader& header, const std::string& payload);

// Number of write_checkpoint calls of this process so far (for the fault hook's N).
int checkpoint_writes();

// True when out/checkpoint.bin exists.
bool has_checkpoint(const OutputDir& out);

// Reads and checks out/checkpoint.bin against `expect` (command and config hash; step and time are
// returned in `found`); ConfigError on any mismatch or corruption, and before reading anything when it
// is not a regular file (through symlinks: a FIFO, /dev/zero, a directory) or larger than `max_bytes`
// (the memory budget: the whole file is held in memory). Returns the payload reader.
CheckpointReader read_checkpoint(const OutputDir& out, const CheckpointHeader& expect, CheckpointHeader& found,
                                 double max_bytes);

}  // namespace agglo::io
