#include "agglo/run/journal.hpp"

#include <cerrno>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "agglo/io/output_dir.hpp"

namespace agglo::run {

std::string hash_hex(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return fmt::format("{:016x}", h);
}

std::string without_sections(const std::string& resolved_toml, const std::vector<std::string>& sections) {
  std::istringstream in(resolved_toml);
  std::string line, out;
  bool skipping = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.front() == '[') {
      skipping = false;
      for (const auto& s : sections)
        if (line == "[" + s + "]" || line.rfind("[" + s + ".", 0) == 0) skipping = true;
    }
    if (!skipping) out += line + '\n';
  }
  return out;
}

Journal::Journal(std::filesystem::path file, std::string context, bool resume)
    : file_(std::move(file)), context_(std::move(context)) {
  if (!resume) {
    std::filesystem::remove(file_);
    return;
  }
  std::ifstream in(file_, std::ios::binary);
  std::string line;
  bool ends_with_newline = true;
  while (std::getline(in, line)) {
    ends_with_newline = !in.eof();
    const auto j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object() || !j.contains("result")) continue;  // torn line
    if (j.value("context", std::string()) != context_) continue;
    entries_[j.value("job", std::string())] = j["result"];
  }
  // A line torn by a killed run is ended, so that the next entry starts on a line of its own.
  if (!ends_with_newline) std::ofstream(file_, std::ios::app) << '\n';
}

std::optional<nlohmann::json> Journal::find(const std::string& key) const {
  std::lock_guard<std::mutex> lk(mutex_);
  auto it = entries_.find(hash_hex(key));
  if (it == entries_.end()) return std::nullopt;
  return it->second;
}

void Journal::record(const std::string& key, std::size_t index, const nlohmann::json& result,
                     const nlohmann::json& about) {
  nlohmann::json j = {{"context", context_}, {"job", hash_hex(key)}, {"key", key}, {"index", index}, {"result", result}};
  for (auto it = about.begin(); it != about.end(); ++it) j[it.key()] = it.value();
  std::lock_guard<std::mutex> lk(mutex_);
  errno = 0;
  std::ofstream out(file_, std::ios::app);
  out << j.dump() << '\n';
  out.flush();
  // A line that cannot be appended (a full or read-only disk) fails the job instead of being lost: a
  // --resume would silently repeat it.
  if (!out) throw output_error(file_, errno);
  entries_[hash_hex(key)] = result;
}

}  // namespace agglo::run
