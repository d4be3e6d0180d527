#pragma once
// Budgets of a run (docs/limits.md): the most particle-steps, memory and output bytes a command may
// use. Before the output folder is created, run::execute compares the command's Estimate
// (core/estimate.hpp) with them and refuses a case that exceeds one (LimitError, a ConfigError: exit 2), so a typo
// (time.end = 1e300, patches_per_sphere = 1e6) cannot run for ever or exhaust the machine.
// Each budget comes from the command line (--max-steps, --max-memory, --max-output), else the
// environment (AGGLO_MAX_STEPS, AGGLO_MAX_MEMORY, AGGLO_MAX_OUTPUT), else the defaults below;
// never from the case file, so config.resolved.toml does not depend on the machine.
//   default steps  kDefaultMaxSteps particle-steps
//   default memory kMemoryFraction x min(cgroup memory limit, physical RAM), per process
//   default output kDefaultMaxOutputBytes
// SIZE values are bytes, or a number with a suffix K, M, G or T (powers of 1024), e.g. 8G, 1.5T.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "agglo/core/estimate.hpp"

namespace agglo::run {

// 1e12 steps: 3.5x the largest shipped case (a default breakup of a charged seed-000 case, 12 speeds x
// 16 offsets with induced charges, 2.9e11 weighted particle-steps, about an hour on 2 cores), 750x the
// 4 s acoustic baseline (1.3e9 sample-steps) and 100x the largest study sweep of
// bench/acoustic_studies.sh (9.4e9); hours of work. A time step or run length off by many orders of
// magnitude is far above it.
inline constexpr double kDefaultMaxSteps = 1e12;
// Share of the usable memory (cgroup limit or RAM) one process may plan to use.
inline constexpr double kMemoryFraction = 0.8;
// 1 GiB: about 270x the largest estimated output of a shipped case (3.7 MiB, the surface.vtu of
// electrostatics_tetrahedron; the 4 s acoustic baseline 1.9 MiB).
inline constexpr double kDefaultMaxOutputBytes = 1024.0 * 1024.0 * 1024.0;

struct Budgets {
  double max_steps = kDefaultMaxSteps;
  double max_memory_bytes = 0.0;  // resolve_budgets fills in the default
  double max_output_bytes = kDefaultMaxOutputBytes;
};

// Budget values as given on the command line ("" = not given).
struct BudgetArgs {
  std::string max_steps, max_memory, max_output;
};

// "8G", "512M", "1.5T", "1000000" -> bytes. ConfigError naming `source` (the option or variable),
// the value and what is allowed.
double parse_size(std::string_view value, std::string_view source);
// "2e9", "1000000" -> a count >= 1. ConfigError naming `source`, the value and what is allowed.
double parse_steps(std::string_view value, std::string_view source);

// The limit in a cgroup memory file (v2 memory.max, v1 memory.limit_in_bytes); nullopt when the
// file is missing, unreadable or says "max" (no limit).
std::optional<double> read_memory_limit(const std::filesystem::path& file);
// The tightest memory limit of the cgroups this process is in (v2 and v1, the cgroup and its
// parents), read below `root` (normally /sys/fs/cgroup) using `self` (normally /proc/self/cgroup);
// infinity when none is set.
double cgroup_memory_limit(const std::filesystem::path& root = "/sys/fs/cgroup",
                           const std::filesystem::path& self = "/proc/self/cgroup");
// Physical RAM [bytes] (sysconf).
double physical_memory();
// kMemoryFraction x min(cgroup limit, physical RAM).
double default_memory_budget();

// Command line first, then AGGLO_MAX_STEPS / AGGLO_MAX_MEMORY / AGGLO_MAX_OUTPUT, then the defaults.
Budgets resolve_budgets(const BudgetArgs& cli);

// Throws LimitError (a ConfigError) when `e` exceeds a budget: one line naming the keys that drive it, the estimate,
// the budget and how to raise it. `what` names the case (file or command).
void check_budgets(const Estimate& e, const Budgets& b, std::string_view what);

// The estimates against the budgets, one line per quantity with its driving keys (--dry-run).
std::string describe(const Estimate& e, const Budgets& b);

// The time line of --dry-run: steps x seconds_per_step (Command::seconds_per_step, seconds of one
// thread per step unit, measured) as CPU time of one thread and its cost class, "seconds" (< 1 min),
// "minutes" (< 1 h), "hours" (< 1 day), "days" (< 30 days) or "months or more". An upper bound like the
// steps; the wall time on n threads is at best 1/n of it. "not estimated" when the rate is 0.
std::string describe_time(double steps, double seconds_per_step);
// "12.3 s", "4.5 min", "2.1 h", "3.2 d".
std::string format_duration(double seconds);

// "2.1e+09 particle-steps", "3.4 GiB": human-readable values for messages and --dry-run.
std::string format_bytes(double bytes);
std::string format_steps(double steps);

}  // namespace agglo::run
