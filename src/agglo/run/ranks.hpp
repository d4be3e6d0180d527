#pragma once
// The processes of one agglo run. Without MPI (or not launched by mpirun) there is one process and it
// writes everything. Under `mpirun -n K` every rank runs the same pipeline, the ensemble runner spreads
// its jobs over the ranks (run/ensemble_farm.cpp), and only rank 0 writes the run's top-level outputs:
// the other ranks write theirs into a private scratch folder that is removed at the end. The folders of
// a sweep's cases are written by the rank that runs the case (the output folder must be on a file
// system every rank sees, as on any cluster).
#include <filesystem>
#include <string_view>

#include "agglo/io/output_dir.hpp"

namespace agglo::run {

// True in the process that writes a run's top-level outputs (always without MPI; rank 0 under mpirun).
bool is_output_rank();

// Number of processes of this run (1 without MPI).
int rank_count();

// The folder a top-level run writes into. Rank 0 (or the only process) claims `path` under `policy`
// (io::claim_output_folder) and returns it; under MPI the outcome is sent to every rank, so a refused
// folder is the same ConfigError on every rank, and the other ranks get a new private scratch folder.
// Nested runs (a job of an ensemble, run/ensemble.hpp in_job()) claim `path` themselves.
std::filesystem::path claim_run_folder(const std::filesystem::path& path, FolderPolicy policy,
                                       std::string_view command);

// Removes a rank's scratch folder (from claim_run_folder) when the run ends; nothing on rank 0.
class ScratchFolder {
 public:
  explicit ScratchFolder(std::filesystem::path folder, const std::filesystem::path& requested);
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

 private:
  std::filesystem::path folder_;
  bool remove_ = false;
};

}  // namespace agglo::run
