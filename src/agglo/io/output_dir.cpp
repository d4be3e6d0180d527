#include "agglo/io/output_dir.hpp"

#include <chrono>
#include <ctime>
#include <fstream>
#include <unistd.h>

#include <fmt/format.h>
#include <omp.h>

#include "agglo/core/error.hpp"
#include "agglo/core/version.hpp"

namespace agglo {

void write_file_atomic(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body) {
  auto tmp = path;
  tmp += fmt::format(".tmp-{}", static_cast<long>(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
    try {
      body(out);
    } catch (...) {
      out.close();
      std::filesystem::remove(tmp);
      throw;
    }
    out.flush();
    if (!out) {
      std::filesystem::remove(tmp);
      throw std::runtime_error(fmt::format("error while writing {}", tmp.string()));
    }
  }
  std::filesystem::rename(tmp, path);
}

OutputDir::OutputDir(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) throw std::runtime_error(fmt::format("cannot create output folder {}: {}", dir_.string(), ec.message()));
}

void OutputDir::write(const std::string& name, const std::function<void(std::ostream&)>& body) const {
  auto p = dir_ / name;
  std::filesystem::create_directories(p.parent_path());
  write_file_atomic(p, body);
}

void OutputDir::write_text(const std::string& name, const std::string& text) const {
  write(name, [&](std::ostream& o) { o << text; });
}

void OutputDir::write_json(const std::string& name, const nlohmann::json& j) const {
  write(name, [&](std::ostream& o) { o << j.dump(2) << '\n'; });
}

nlohmann::json run_metadata(const std::string& command, const std::string& case_file, long long seed,
                            double wall_time_s) {
  auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return nlohmann::json{{"program", "agglo"},
                        {"version", kVersion},
                        {"git_hash", kGitHash},
                        {"command", command},
                        {"case", case_file},
                        {"seed", seed},
                        {"threads", omp_get_max_threads()},
                        {"wall_time_s", wall_time_s},
                        {"finished_utc", buf}};
}

std::filesystem::path default_output_dir(const std::string& case_file, const std::string& command) {
  auto stem = std::filesystem::path(case_file).stem().string();
  return std::filesystem::path("results") / (command.empty() ? stem : stem + "-" + command);
}

}  // namespace agglo
