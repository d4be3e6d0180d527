#pragma once
// Output folder of a run. Every file is written to "<name>.tmp-<pid>" and renamed when complete,
// so a crash or an error never leaves a half-written result under its final name.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "agglo/core/error.hpp"

namespace agglo {

class OutputDir {
 public:
  OutputDir() = default;
  // Creates the folder; ConfigError (one line naming the folder and the reason) when it cannot be
  // created or written into. Removes the "*.tmp-<pid>" files of killed runs (pid no longer alive)
  // from it and its sub-folders.
  explicit OutputDir(std::filesystem::path dir);

  const std::filesystem::path& path() const { return dir_; }
  std::filesystem::path file(const std::string& name) const { return dir_ / name; }

  // Write atomically through a stream callback.
  void write(const std::string& name, const std::function<void(std::ostream&)>& body) const;
  void write_text(const std::string& name, const std::string& text) const;
  void write_json(const std::string& name, const nlohmann::json& j) const;

 private:
  std::filesystem::path dir_;
};

// What a run may do with an output folder that already holds files (docs/limits.md, "Output folders").
enum class FolderPolicy {
  fresh,      // refuse a folder holding another run's files
  overwrite,  // clear a folder holding an agglo run, then start afresh (--overwrite)
  resume,     // keep it: an ensemble continues from its journal.jsonl (--resume)
};

// The output-folder contract, checked before a run creates or writes anything: a missing or empty
// folder is taken; one holding an agglo run (run.json, config.resolved.toml or journal.jsonl) is refused
// under `fresh` (ConfigError naming the run's command and status and both flags), cleared under
// `overwrite` and kept under `resume` if its run.json names the same `command`; a folder holding files
// but no agglo run is always refused, so --overwrite never deletes anything agglo did not write.
// Temporary "*.tmp-<pid>" files do not count.
void claim_output_folder(const std::filesystem::path& dir, FolderPolicy policy, std::string_view command);

// The OutputError of a file that cannot be written, from the errno of the failed call (0: unknown):
// "cannot write FILE: No space left on device (free space or choose another --out)".
OutputError output_error(const std::filesystem::path& file, int err);
// The same with the reason in words ("40 KiB free, it needs up to 100 KiB").
OutputError output_error(const std::filesystem::path& file, const std::string& reason);

// Atomic write to an arbitrary path. A failed write, close or rename (e.g. a full disk) removes the
// temporary file and throws output_error.
void write_file_atomic(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body);

// The x86-64 micro-architecture level of this CPU ("x86-64-v4": AVX-512, where the DEM pair loop runs eight
// pairs at a time; "x86-64-v3": AVX2; "x86-64-v2", "x86-64"; "other" off x86-64): what a run's wall time
// depends on beyond the thread count (the results do not).
std::string cpu_level();

// Metadata common to every run (run.json): version, git hash, command, case, seed, threads, CPU level, time.
nlohmann::json run_metadata(const std::string& command, const std::string& case_file, long long seed,
                            double wall_time_s);

// Default output folder for a case file: results/<case stem>[-<command>].
std::filesystem::path default_output_dir(const std::string& case_file, const std::string& command);

}  // namespace agglo
