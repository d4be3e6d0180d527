// io/checkpoint: round trip, and every way a checkpoint is refused (corruption, truncation, another
// command / config), and the fault-injection hook leaving the previous checkpoint usable.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "agglo/core/error.hpp"
#include "agglo/io/checkpoint.hpp"

namespace fs = std::filesystem;
using namespace agglo;
using namespace agglo::io;

namespace {

struct TmpDir {
  fs::path path;
  TmpDir() {
    path = fs::temp_directory_path() / ("agglo_ckpt_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TmpDir() { fs::remove_all(path); }
};

std::string payload(double x) {
  CheckpointWriter w;
  w.u64(42);
  w.f64(x);
  w.str("state");
  w.pod_vector(std::vector<double>{1.0, 2.5, -3.0});
  return w.bytes();
}

CheckpointHeader header(std::uint64_t step = 7) { return {"acoustic", config_hash("a = 1\n"), step, 0.25}; }

constexpr double kCap = 1e9;  // the largest checkpoint read (the memory budget in a run)

// The refusal's message of reading out's checkpoint ("" when it is read).
std::string refusal(const OutputDir& out, double cap = kCap) {
  CheckpointHeader found;
  try {
    (void)read_checkpoint(out, header(), found, cap);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Checkpoint, RoundTripReturnsEveryValueAndTheHeader) {
  TmpDir d;
  const OutputDir out(d.path);
  write_checkpoint(out, header(), payload(0.5));
  CheckpointHeader found;
  auto r = read_checkpoint(out, header(), found, kCap);
  EXPECT_EQ(found.step, 7u);
  EXPECT_EQ(found.time, 0.25);
  EXPECT_EQ(r.u64(), 42u);
  EXPECT_EQ(r.f64(), 0.5);
  EXPECT_EQ(r.str(), "state");
  EXPECT_EQ(r.pod_vector<double>(), (std::vector<double>{1.0, 2.5, -3.0}));
  EXPECT_TRUE(r.at_end());
  EXPECT_NO_THROW(r.expect_end());
  EXPECT_THROW(r.u64(), ConfigError);  // reading past the end
}

TEST(Checkpoint, AnotherConfigOrCommandIsRefused) {
  TmpDir d;
  const OutputDir out(d.path);
  write_checkpoint(out, header(), payload(0.5));
  CheckpointHeader found;
  auto other = header();
  other.config_hash = config_hash("a = 2\n");
  EXPECT_THROW(read_checkpoint(out, other, found, kCap), ConfigError);
  other = header();
  other.command = "collide";
  try {
    read_checkpoint(out, other, found, kCap);
    FAIL() << "accepted another command's checkpoint";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("command acoustic"), std::string::npos) << e.what();
  }
}

TEST(Checkpoint, AnyFlippedByteOrTruncationIsDetected) {
  TmpDir d;
  const OutputDir out(d.path);
  write_checkpoint(out, header(), payload(0.5));
  const auto file = out.file(kCheckpointFile);
  const auto size = fs::file_size(file);
  for (std::uintmax_t at : {std::uintmax_t{0}, std::uintmax_t{9}, size / 2, size - 1}) {
    std::string bytes;
    {
      std::ifstream in(file, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    bytes[at] ^= 0x10;
    {
      std::ofstream o(file, std::ios::binary | std::ios::trunc);
      o << bytes;
    }
    CheckpointHeader found;
    EXPECT_THROW(read_checkpoint(out, header(), found, kCap), ConfigError) << "byte " << at;
    bytes[at] ^= 0x10;  // restore
    std::ofstream o(file, std::ios::binary | std::ios::trunc);
    o << bytes;
  }
  fs::resize_file(file, size - 3);
  CheckpointHeader found;
  EXPECT_THROW(read_checkpoint(out, header(), found, kCap), ConfigError);
}

TEST(Checkpoint, KilledInTheMiddleOfAWriteLeavesThePreviousCheckpoint) {
  TmpDir d;
  const OutputDir out(d.path);
  write_checkpoint(out, header(3), payload(0.5));
  const int next = checkpoint_writes() + 1;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // the fault hook kills this process at its next write
    ::setenv("AGGLO_FAULT_KILL_CHECKPOINT", std::to_string(next).c_str(), 1);
    write_checkpoint(out, header(9), payload(9.0));
    std::_Exit(0);  // not reached when the hook works
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  int tmp_files = 0;
  for (const auto& e : fs::directory_iterator(d.path))
    tmp_files += e.path().filename().string().find(".tmp-") != std::string::npos;
  EXPECT_EQ(tmp_files, 1);  // the half-written file of the killed write
  CheckpointHeader found;
  auto r = read_checkpoint(out, header(), found, kCap);
  EXPECT_EQ(found.step, 3u);  // the previous checkpoint, intact
  EXPECT_EQ(r.u64(), 42u);
  EXPECT_EQ(r.f64(), 0.5);
}

// Issue 23 item 11: what is not a checkpoint file is refused before it is read (a FIFO blocked for
// ever, a symlink to /dev/zero grew to 1.4 GB), and a file larger than the cap is refused unread.
TEST(Checkpoint, NotARegularFileIsRefusedUnread) {
  TmpDir d;
  const OutputDir out(d.path);
  const auto file = out.file(kCheckpointFile);
  fs::create_symlink("/dev/zero", file);
  EXPECT_NE(refusal(out).find("a character device, not a checkpoint file"), std::string::npos) << refusal(out);
  fs::remove(file);
  ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
  EXPECT_NE(refusal(out).find("a FIFO, not a checkpoint file"), std::string::npos) << refusal(out);
  fs::remove(file);
  fs::create_directory(file);
  EXPECT_NE(refusal(out).find("a directory"), std::string::npos) << refusal(out);
}

TEST(Checkpoint, LargerThanTheCapIsRefused) {
  TmpDir d;
  const OutputDir out(d.path);
  write_checkpoint(out, header(), payload(0.5));
  const auto size = static_cast<double>(fs::file_size(out.file(kCheckpointFile)));
  EXPECT_EQ(refusal(out, size), "");
  EXPECT_NE(refusal(out, size - 1).find("more than the memory budget"), std::string::npos);
}
