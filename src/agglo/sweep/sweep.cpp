#include "agglo/sweep/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <mutex>
#include <sstream>
#include <thread>

#include <fmt/format.h>
#include <omp.h>

#include "agglo/core/error.hpp"

namespace agglo::sweep {

std::vector<std::string> split_values(const std::string& list) {
  std::vector<std::string> v;
  std::string cur;
  std::istringstream is(list);
  while (std::getline(is, cur, ',')) {
    const auto b = cur.find_first_not_of(" \t"), e = cur.find_last_not_of(" \t");
    if (b == std::string::npos) throw ConfigError(fmt::format("--values '{}': empty entry", list));
    v.push_back(cur.substr(b, e - b + 1));
  }
  if (v.empty()) throw ConfigError("--values: at least one value is required");
  return v;
}

std::string case_folder(std::size_t index, const std::string& value) {
  std::string s;
  for (char c : value) s += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+') ? c : '_';
  return fmt::format("case_{:02d}_{}", index, s);
}

std::vector<nlohmann::json> run_sweep(const Config& base, const std::string& key, const std::vector<std::string>& values,
                                      const OutputDir& out, const CaseRunner& run,
                                      const std::function<void(Config&)>& validate, int threads, bool verbose) {
  if (key.empty()) throw ConfigError("--param: a config key is required (e.g. population.1.diameter)");
  const std::size_t n = values.size();
  std::vector<Config> cfgs;
  std::vector<SweepCase> cases;
  for (std::size_t i = 0; i < n; ++i) {
    SweepCase c{i, values[i], key + "=" + values[i]};
    Config cfg = base.clone();
    cfg.apply_override(c.assignment);
    if (validate) {
      Config probe = cfg.clone();
      validate(probe);
    }
    cfgs.push_back(std::move(cfg));
    cases.push_back(c);
  }
  const int total = threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const std::size_t workers = std::min<std::size_t>(n, static_cast<std::size_t>(total));
  const int per_case = std::max(1, total / static_cast<int>(workers));
  std::vector<nlohmann::json> results(n);
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> next{0};
  std::mutex io;
  auto worker = [&] {
    omp_set_num_threads(per_case);
    for (;;) {
      const std::size_t i = next++;
      if (i >= n) break;
      try {
        OutputDir sub(out.path() / case_folder(i, values[i]));
        results[i] = run(cfgs[i], sub, cases[i]);
        if (verbose) {
          std::lock_guard<std::mutex> lk(io);
          std::fprintf(stderr, "sweep: case %zu/%zu (%s) done\n", i + 1, n, cases[i].assignment.c_str());
        }
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 0; w < workers; ++w) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  return results;
}

void flatten_scalars(const nlohmann::json& j, const std::string& prefix, std::vector<std::pair<std::string, double>>& out) {
  if (!j.is_object()) return;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string k = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_number()) out.emplace_back(k, it->get<double>());
    else if (it->is_boolean()) out.emplace_back(k, it->get<bool>() ? 1.0 : 0.0);
    else if (it->is_object()) flatten_scalars(*it, k, out);
  }
}

void write_table(const OutputDir& out, const std::string& key, const std::vector<std::string>& values,
                 const std::vector<nlohmann::json>& summaries) {
  std::vector<std::string> cols;
  std::vector<std::vector<std::pair<std::string, double>>> rows(summaries.size());
  for (std::size_t i = 0; i < summaries.size(); ++i) {
    flatten_scalars(summaries[i], "", rows[i]);
    for (const auto& [k, v] : rows[i])
      if (std::find(cols.begin(), cols.end(), k) == cols.end()) cols.push_back(k);
  }
  out.write("sweep.csv", [&](std::ostream& os) {
    os << "index," << key << ",case";
    for (const auto& c : cols) os << ',' << c;
    os << '\n';
    for (std::size_t i = 0; i < summaries.size(); ++i) {
      os << i << ',' << values[i] << ',' << case_folder(i, values[i]);
      for (const auto& c : cols) {
        os << ',';
        for (const auto& [k, v] : rows[i])
          if (k == c) {
            os << fmt::format("{:.10g}", v);
            break;
          }
      }
      os << '\n';
    }
  });
}

}  // namespace agglo::sweep
