#include "agglo/run/command.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <fstream>
#include <sstream>

#include <omp.h>

#include <unistd.h>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/version.hpp"
#include "agglo/io/netcdf_writer.hpp"
#include "agglo/run/commands.hpp"
#include "agglo/run/ensemble.hpp"
#include "agglo/run/ranks.hpp"

namespace agglo::run {

Reporter& RunContext::report() const {
  static SilentReporter silent;
  return reporter ? *reporter : silent;
}

int RunContext::thread_count() const { return threads > 0 ? threads : omp_get_max_threads(); }

long long Command::seed(const Config&) const { return 0; }

Estimate Command::estimate(Config&, const RunContext&) const { return {}; }

Estimate Command::lower_bound(Config&) const { return {}; }

double Command::seconds_per_step(Config&) const { return 0.0; }

double output_bytes(double csv_estimate, const OutputFormats& f) {
  return (f.csv ? csv_estimate : 0.0) + (f.netcdf ? csv_estimate + kNetcdfOverhead : 0.0);
}

OutputFormats parse_formats(std::string_view text) {
  OutputFormats f{false, false};
  for (std::size_t start = 0; start <= text.size();) {
    const auto end = std::min(text.find(',', start), text.size());
    const auto item = text.substr(start, end - start);
    if (item == "csv") f.csv = true;
    else if (item == "netcdf") f.netcdf = true;
    else throw ConfigError(fmt::format("format '{}': give csv, netcdf or csv,netcdf", text));
    start = end + 1;
  }
  return f;
}

namespace {
std::atomic<std::size_t> g_case_parses{0};
}  // namespace

void parse_case(const Command& cmd, Config& cfg) {
  ++g_case_parses;
  cmd.parse(cfg);
}

std::size_t case_parses() { return g_case_parses.load(); }

Estimate plan(const Command& cmd, Config& cfg, const RunContext& ctx) {
  check_budgets(cmd.lower_bound(cfg), budgets_of(ctx), cfg.file());
  const CancelScope cancel_scope(ctx.cancel);  // parsing may build a large structure, which polls it
  try {
    parse_case(cmd, cfg);
  } catch (InterruptedError& e) {
    e.before_output = true;  // no output folder exists yet
    throw;
  }
  for (const auto& w : cfg.take_warnings()) ctx.report().warning(w);
  Estimate e = cmd.estimate(cfg, ctx);
  e.memory.value += kProcessBaseBytes;
  if (ctx.formats.netcdf) e.memory.value += e.output.value;  // the results.nc arrays, at most as large
  e.output.value = output_bytes(e.output.value, ctx.formats);
  return e;
}

Budgets budgets_of(const RunContext& ctx) { return ctx.budgets ? *ctx.budgets : resolve_budgets({}); }

const Command& find_command(std::string_view name) {
  for (const Command* c : all_commands())
    if (c->name() == name) return *c;
  std::string list;
  for (const auto& n : command_names()) list += (list.empty() ? "" : ", ") + n;
  throw ConfigError(fmt::format("command '{}' does not exist (available: {})", cut_for_message(name), list));
}

std::vector<std::string> command_names() {
  std::vector<std::string> names;
  for (const Command* c : all_commands()) names.emplace_back(c->name());
  return names;
}

FolderPolicy folder_policy(const RunContext& ctx) {
  if (ctx.resume) return FolderPolicy::resume;
  return ctx.overwrite ? FolderPolicy::overwrite : FolderPolicy::fresh;
}

void write_run_started(const OutputDir& out, std::string_view command, const std::string& case_file,
                       const nlohmann::json& details) {
  nlohmann::json j = {{"program", "agglo"},
                      {"command", command},
                      {"case", case_file},
                      {"status", "running"},
                      {"pid", static_cast<long>(::getpid())}};
  if (!details.is_null() && !details.empty()) j["details"] = details;
  out.write_json("run.json", j);
}

namespace {
nlohmann::json run_json(const Config& cfg, std::string_view command, long long seed, double wall_time_s,
                        const nlohmann::json& details, std::string_view status) {
  auto meta = run_metadata(std::string(command), cfg.file(), seed, wall_time_s);
  meta["status"] = status;
  meta["ranks"] = rank_count();  // MPI processes of the run (1 without mpirun)
  if (!details.is_null() && !details.empty()) meta["details"] = details;
  return meta;
}
}  // namespace

void write_run_files(const OutputDir& out, const Config& cfg, std::string_view command, long long seed,
                     double wall_time_s, const nlohmann::json& details, std::string_view status) {
  out.write_text("config.resolved.toml", cfg.resolved_toml());
  out.write_json("run.json", run_json(cfg, command, seed, wall_time_s, details, status));
}

void write_stopped_run_files(const OutputDir& out, const Config& cfg, std::string_view command, long long seed,
                             double wall_time_s, const nlohmann::json& details, std::string_view status) noexcept {
  try {
    write_run_files(out, cfg, command, seed, wall_time_s, details, status);
    return;
  } catch (const std::exception&) {  // e.g. the disk is full: run.json in place, over its own blocks
  }
  try {
    std::ofstream f(out.file("run.json"), std::ios::binary | std::ios::trunc);
    f << run_json(cfg, command, seed, wall_time_s, details, status).dump(2) << '\n';
  } catch (const std::exception&) {  // nothing more can be done; the error itself is reported
  }
}

void write_results_nc(const OutputDir& out, const Config& cfg, std::string_view command, long long seed,
                      const io::Dataset& data, std::string_view status, const std::string& file) {
  nlohmann::json provenance{
      {"Conventions", "CF-1.8"},
      {"title", fmt::format("agglo {} of {}", command, std::filesystem::path(cfg.file()).filename().string())},
      {"agglo_version", kVersion},
      {"git_hash", kGitHash},
      {"command", std::string(command)},
      {"seed", seed},
      {"config", cfg.resolved_toml()}};
  if (status != "complete") provenance["status"] = std::string(status);
  io::write_netcdf(out, data, file, provenance);
}

namespace {
// The whole text of a file; "" when it is missing or unreadable.
std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

CommandResult execute(const Command& cmd, Config& cfg, const std::filesystem::path& out_dir, const RunContext& ctx,
                      const nlohmann::json& extra) {
  if (rank_count() > 1 && !in_job() && !cmd.resumable())
    throw ConfigError(fmt::format("{} is a single run; under mpirun ({} ranks) run an ensemble of it (sweep, or "
                                  "acoustic --seeds) or one of vcrit, breakup, calibrate",
                                  cmd.name(), rank_count()));
  const Estimate planned = plan(cmd, cfg, ctx);
  return execute_planned(cmd, cfg, planned, out_dir, ctx, extra);
}

CommandResult execute_planned(const Command& cmd, Config& cfg, const Estimate& planned,
                              const std::filesystem::path& out_dir, const RunContext& ctx,
                              const nlohmann::json& extra) {
  const auto start = std::chrono::steady_clock::now();
  check_budgets(planned, budgets_of(ctx), cfg.file());
  std::error_code ec;
  // A seed ensemble's folder records its command too (e.g. acoustic --seeds N); a single run does not
  // continue it: its journal marks it as an ensemble.
  if (ctx.resume && !cmd.resumable() && !in_job() && std::filesystem::exists(out_dir / "journal.jsonl", ec))
    throw ConfigError(fmt::format("output folder {}: holds an ensemble of {} runs (journal.jsonl); --resume it with "
                                  "the same --seeds, or choose another --out", out_dir.string(), cmd.name()));
  const bool existed = std::filesystem::exists(out_dir, ec);
  // A single run without checkpoints starts again under --resume; a restartable one continues in place.
  const bool restart = ctx.resume && !cmd.resumable() && !cmd.restartable();
  const auto folder = claim_run_folder(out_dir, folder_policy(ctx), cmd.name());  // rank 0's, or a scratch
  const ScratchFolder scratch(folder, out_dir);
  if (restart) claim_output_folder(folder, FolderPolicy::overwrite, cmd.name());
  const OutputDir out(folder);
  // A restartable run continued in place whose input is refused (e.g. a checkpoint of another config)
  // leaves the folder as it was: its run.json is put back and config.resolved.toml is not touched.
  const std::string previous_run = ctx.resume && cmd.restartable() ? read_text_file(out.file("run.json")) : "";
  write_run_started(out, cmd.name(), cfg.file());
  auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  auto merged = [&](nlohmann::json details) {
    if (!extra.is_null())
      for (auto it = extra.begin(); it != extra.end(); ++it) details[it.key()] = it.value();
    return details;
  };
  CommandResult res;
  auto stopped = [&](const char* what, const std::exception& e, std::string_view status) {
    write_stopped_run_files(out, cfg, cmd.name(), cmd.seed(cfg), seconds(), merged({{what, e.what()}}), status);
  };
  try {
    const CancelScope cancel_scope(ctx.cancel);  // the engines poll it (core/cancel.hpp)
    res = cmd.run(cfg, out, ctx);
    if (ctx.formats.netcdf && res.data) write_results_nc(out, cfg, cmd.name(), res.seed, *res.data);
    write_run_files(out, cfg, cmd.name(), res.seed, seconds(), merged(res.details));
  } catch (const OutputError& e) {  // a full or read-only disk: the folder stays, marked failed
    stopped("error", e, "failed");
    throw;
  } catch (const ConfigError& e) {  // input found invalid only by the engine: leave no new folder behind
    if (!existed) std::filesystem::remove_all(folder, ec);
    else if (!previous_run.empty()) out.write_text("run.json", previous_run);
    else stopped("error", e, "failed");
    throw;
  } catch (const InterruptedError& e) {
    stopped("interrupted", e, "incomplete");
    throw;
  } catch (const std::exception& e) {
    stopped("error", e, "failed");
    throw;
  }
  return res;
}

}  // namespace agglo::run
