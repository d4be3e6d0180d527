#pragma once
// Journal of the finished jobs of an ensemble (vcrit, breakup, sweep): one JSON line per job,
// appended and flushed as each job finishes, in <output folder>/journal.jsonl:
//   {"context": <hash of the command and the case>, "job": <hash of the job key>, "key": "...",
//    "index": i, "result": {...}, "rank": r, "seconds": s}   (the rank that ran it and its wall time)
// `--resume` into the same folder reuses every entry whose context matches and repeats only the
// jobs that are missing. The context hash covers the command and the resolved case except the
// sections that only choose which jobs run (e.g. [vcrit], [breakup]), so a break-up curve extended by
// more speeds reuses the runs it already has. A torn last line (a killed run) is ignored.
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace agglo::run {

// 64-bit FNV-1a of `text`, as 16 hex digits.
std::string hash_hex(std::string_view text);

// `resolved_toml` with the named top-level tables removed (text of config.resolved.toml).
std::string without_sections(const std::string& resolved_toml, const std::vector<std::string>& sections);

class Journal {
 public:
  // resume = false: a new journal (an old file is replaced); true: entries of `context` are loaded.
  Journal(std::filesystem::path file, std::string context, bool resume);

  // The stored result of job `key`, if this context has one.
  std::optional<nlohmann::json> find(const std::string& key) const;
  // Appends a finished job (thread-safe); the members of `about` (e.g. rank and seconds) are added to its line.
  // OutputError (io/output_dir.hpp: "cannot write FILE: <reason>") when the line cannot be written.
  void record(const std::string& key, std::size_t index, const nlohmann::json& result,
              const nlohmann::json& about = nlohmann::json::object());
  std::size_t loaded() const { return entries_.size(); }
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::string context_;
  std::map<std::string, nlohmann::json> entries_;  // job hash -> result
  mutable std::mutex mutex_;
};

}  // namespace agglo::run
