#include "agglo/run/ranks.hpp"

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

std::filesystem::path scratch_folder() {
  return std::filesystem::temp_directory_path() / fmt::format("agglo-rank{}-{}", mpi::rank(), ::getpid());
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
