#include "agglo/run/ranks.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <string>

#include <unistd.h>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/mpi/comm.hpp"
#include "agglo/run/ensemble.hpp"

namespace agglo::run {

bool is_output_rank() { return mpi::rank() == 0; }

int rank_count() { return mpi::size(); }

namespace {
bool distributed() { return mpi::size() > 1 && !in_job(); }

constexpr std::string_view kScratchPrefix = "agglo-rank";

// Scratch folders of ranks killed on this machine (their process is gone) are removed.
void remove_dead_scratch_folders(const std::filesystem::path& tmp) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(tmp, ec)) {
    const std::string name = e.path().filename().string();
    const auto dash = name.rfind('-');
    if (name.rfind(kScratchPrefix, 0) != 0 || dash == std::string::npos) continue;
    const long pid = std::strtol(name.c_str() + dash + 1, nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) std::filesystem::remove_all(e.path(), ec);
  }
}

std::filesystem::path scratch_folder() {
  std::error_code ec;
  const auto tmp = std::filesystem::temp_directory_path(ec);
  if (ec)
    throw ConfigError(fmt::format("no folder for temporary files (TMPDIR={}: {})",
                                  std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "", ec.message()));
  remove_dead_scratch_folders(tmp);
  return tmp / fmt::format("{}{}-{}", kScratchPrefix, mpi::rank(), ::getpid());
}
}  // namespace

std::filesystem::path claim_run_folder(const std::filesystem::path& path, FolderPolicy policy,
                                       std::string_view command) {
  if (!distributed()) {
    claim_output_folder(path, policy, command);
    return path;
  }
  std::string refusal;
  if (is_output_rank()) {
    try {
      claim_output_folder(path, policy, command);
    } catch (const ConfigError& e) {
      refusal = e.what();
      if (refusal.empty()) refusal = "the output folder was refused";
    }
  }
  refusal = mpi::broadcast(refusal);
  if (!refusal.empty()) throw ConfigError(refusal);
  if (is_output_rank()) return path;
  const auto scratch = scratch_folder();
  claim_output_folder(scratch, FolderPolicy::overwrite, command);
  return scratch;
}

ScratchFolder::ScratchFolder(std::filesystem::path folder, const std::filesystem::path& requested)
    : folder_(std::move(folder)), remove_(folder_ != requested) {}

ScratchFolder::~ScratchFolder() {
  std::error_code ec;
  if (remove_) std::filesystem::remove_all(folder_, ec);
}

}  // namespace agglo::run
