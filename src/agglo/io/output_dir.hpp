#pragma once
// Output folder of a run. Every file is written to "<name>.tmp-<pid>" and renamed when complete,
// so a crash or an error never leaves a half-written result under its final name.
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

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

// Atomic write to an arbitrary path.
void write_file_atomic(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body);

// Metadata common to every run (run.json): version, git hash, command, case, seed, threads, time.
nlohmann::json run_metadata(const std::string& command, const std::string& case_file, long long seed,
                            double wall_time_s);

// Default output folder for a case file: results/<case stem>[-<command>].
std::filesystem::path default_output_dir(const std::string& case_file, const std::string& command);

}  // namespace agglo
