#include "agglo/run/command.hpp"

#include <chrono>

#include <omp.h>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/run/commands.hpp"

namespace agglo::run {

Reporter& RunContext::report() const {
  static SilentReporter silent;
  return reporter ? *reporter : silent;
}

int RunContext::thread_count() const { return threads > 0 ? threads : omp_get_max_threads(); }

long long Command::seed(const Config&) const { return 0; }

Estimate Command::estimate(Config&, const RunContext&) const { return {}; }

Estimate Command::lower_bound(Config&) const { return {}; }

Estimate plan(const Command& cmd, Config& cfg, const RunContext& ctx) {
  check_budgets(cmd.lower_bound(cfg), budgets_of(ctx), cfg.file());
  cmd.parse(cfg);
  Estimate e = cmd.estimate(cfg, ctx);
  e.memory.value += kProcessBaseBytes;
  return e;
}

Budgets budgets_of(const RunContext& ctx) { return ctx.budgets ? *ctx.budgets : resolve_budgets({}); }

const Command& find_command(std::string_view name) {
  for (const Command* c : all_commands())
    if (c->name() == name) return *c;
  std::string list;
  for (const auto& n : command_names()) list += (list.empty() ? "" : ", ") + n;
  throw ConfigError(fmt::format("command '{}' does not exist (available: {})", name, list));
}

std::vector<std::string> command_names() {
  std::vector<std::string> names;
  for (const Command* c : all_commands()) names.emplace_back(c->name());
  return names;
}

void write_run_files(const OutputDir& out, const Config& cfg, std::string_view command, long long seed,
                     double wall_time_s, const nlohmann::json& details) {
  out.write_text("config.resolved.toml", cfg.resolved_toml());
  auto meta = run_metadata(std::string(command), cfg.file(), seed, wall_time_s);
  if (!details.is_null() && !details.empty()) meta["details"] = details;
  out.write_json("run.json", meta);
}

CommandResult execute(const Command& cmd, Config& cfg, const std::filesystem::path& out_dir, const RunContext& ctx,
                      const nlohmann::json& extra) {
  const auto start = std::chrono::steady_clock::now();
  check_budgets(plan(cmd, cfg, ctx), budgets_of(ctx), cfg.file());
  std::error_code ec;
  const bool existed = std::filesystem::exists(out_dir, ec);
  const OutputDir out(out_dir);
  CommandResult res;
  try {
    res = cmd.run(cfg, out, ctx);
  } catch (const ConfigError&) {  // input found invalid only by the engine: leave no new empty folder
    if (!existed && std::filesystem::is_empty(out_dir, ec)) std::filesystem::remove(out_dir, ec);
    throw;
  }
  nlohmann::json details = res.details;
  if (!extra.is_null())
    for (auto it = extra.begin(); it != extra.end(); ++it) details[it.key()] = it.value();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_run_files(out, cfg, cmd.name(), res.seed, wall, details);
  return res;
}

}  // namespace agglo::run
