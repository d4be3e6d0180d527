// Budgets of a run (src/agglo/run/budget.hpp): the SIZE and step-count parsers, the cgroup memory
// limit read from fake cgroup trees (v1 and v2), the precedence command line > environment >
// default, and the refusal message naming the keys, the estimate, the budget and how to raise it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <unistd.h>

#include "agglo/core/error.hpp"
#include "agglo/run/budget.hpp"

using namespace agglo;
using namespace agglo::run;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("agglo_budget_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Budget, SizeParserAcceptsBytesAndPowersOf1024) {
  EXPECT_EQ(parse_size("1000", "--max-memory"), 1000.0);
  EXPECT_EQ(parse_size("8K", "--max-memory"), 8.0 * 1024);
  EXPECT_EQ(parse_size("8k", "--max-memory"), 8.0 * 1024);
  EXPECT_EQ(parse_size("512M", "--max-memory"), 512.0 * 1024 * 1024);
  EXPECT_EQ(parse_size("1.5G", "--max-memory"), 1.5 * 1024 * 1024 * 1024);
  EXPECT_EQ(parse_size("2T", "--max-memory"), 2.0 * std::pow(1024.0, 4));
  EXPECT_EQ(parse_size(" 3G ", "--max-memory"), 3.0 * 1024 * 1024 * 1024);
}

TEST(Budget, SizeParserRejectsGarbageWithOneLineNamingSourceAndValue) {
  for (const char* bad : {"", "G", "-1G", "0", "12X", "1e999", "nan", "1G5", "1 G B", "inf", "8GB"}) {
    const std::string m = message_of([&] { parse_size(bad, "AGGLO_MAX_MEMORY"); });
    ASSERT_FALSE(m.empty()) << bad;
    EXPECT_NE(m.find("AGGLO_MAX_MEMORY"), std::string::npos) << m;
    EXPECT_NE(m.find(std::string("'") + bad + "'"), std::string::npos) << m;
    EXPECT_NE(m.find("K, M, G or T"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(Budget, StepParser) {
  EXPECT_EQ(parse_steps("2e9", "--max-steps"), 2e9);
  EXPECT_EQ(parse_steps("1000000", "--max-steps"), 1e6);
  for (const char* bad : {"", "0", "-5", "abc", "1e400", "5G"}) {
    const std::string m = message_of([&] { parse_steps(bad, "--max-steps"); });
    EXPECT_NE(m.find("--max-steps"), std::string::npos) << bad;
  }
}

TEST(Budget, MemoryLimitFile) {
  const fs::path d = fresh_dir("file");
  write(d / "a", "max\n");
  write(d / "b", "1073741824\n");
  write(d / "c", "garbage\n");
  EXPECT_FALSE(read_memory_limit(d / "a").has_value());
  EXPECT_EQ(read_memory_limit(d / "b").value(), 1073741824.0);
  EXPECT_FALSE(read_memory_limit(d / "c").has_value());
  EXPECT_FALSE(read_memory_limit(d / "missing").has_value());
  fs::remove_all(d);
}

TEST(Budget, CgroupV2TakesTheTightestLimitOfTheGroupAndItsParents) {
  const fs::path d = fresh_dir("v2");
  write(d / "self", "0::/user.slice/job\n");
  write(d / "fs/user.slice/job/memory.max", "max\n");
  write(d / "fs/user.slice/memory.max", "2147483648\n");
  EXPECT_EQ(cgroup_memory_limit(d / "fs", d / "self"), 2147483648.0);
  write(d / "fs/user.slice/job/memory.max", "1073741824\n");
  EXPECT_EQ(cgroup_memory_limit(d / "fs", d / "self"), 1073741824.0);
  fs::remove_all(d);
}

TEST(Budget, CgroupV1AndNoLimit) {
  const fs::path d = fresh_dir("v1");
  write(d / "self", "9:name=systemd:/\n4:memory:/box/42\n0::/\n");
  write(d / "fs/memory/memory.limit_in_bytes", "9223372036854771712\n");  // v1 "no limit"
  write(d / "fs/memory/box/42/memory.limit_in_bytes", "536870912\n");
  EXPECT_EQ(cgroup_memory_limit(d / "fs", d / "self"), 536870912.0);
  fs::remove(d / "fs/memory/box/42/memory.limit_in_bytes");
  EXPECT_EQ(cgroup_memory_limit(d / "fs", d / "self"), 9223372036854771712.0);
  EXPECT_TRUE(std::isinf(cgroup_memory_limit(d / "nothing", d / "no_self")));
  fs::remove_all(d);
}

TEST(Budget, DefaultMemoryIsAFractionOfTheUsableMemory) {
  const double usable = std::min(cgroup_memory_limit(), physical_memory());
  ASSERT_TRUE(std::isfinite(usable));
  EXPECT_DOUBLE_EQ(default_memory_budget(), std::floor(kMemoryFraction * usable));
}

TEST(Budget, CommandLineBeatsEnvironmentBeatsDefault) {
  ::unsetenv("AGGLO_MAX_STEPS");
  ::unsetenv("AGGLO_MAX_MEMORY");
  ::unsetenv("AGGLO_MAX_OUTPUT");
  Budgets b = resolve_budgets({});
  EXPECT_EQ(b.max_steps, kDefaultMaxSteps);
  EXPECT_EQ(b.max_output_bytes, kDefaultMaxOutputBytes);
  EXPECT_EQ(b.max_memory_bytes, default_memory_budget());
  ::setenv("AGGLO_MAX_STEPS", "1e6", 1);
  ::setenv("AGGLO_MAX_MEMORY", "2G", 1);
  ::setenv("AGGLO_MAX_OUTPUT", "3M", 1);
  b = resolve_budgets({});
  EXPECT_EQ(b.max_steps, 1e6);
  EXPECT_EQ(b.max_memory_bytes, 2.0 * 1024 * 1024 * 1024);
  EXPECT_EQ(b.max_output_bytes, 3.0 * 1024 * 1024);
  b = resolve_budgets({"5e7", "1K", "2K"});
  EXPECT_EQ(b.max_steps, 5e7);
  EXPECT_EQ(b.max_memory_bytes, 1024.0);
  EXPECT_EQ(b.max_output_bytes, 2048.0);
  ::setenv("AGGLO_MAX_OUTPUT", "lots", 1);
  EXPECT_NE(message_of([] { resolve_budgets({}); }).find("AGGLO_MAX_OUTPUT = 'lots'"), std::string::npos);
  ::unsetenv("AGGLO_MAX_STEPS");
  ::unsetenv("AGGLO_MAX_MEMORY");
  ::unsetenv("AGGLO_MAX_OUTPUT");
}

TEST(Budget, RefusalNamesKeysEstimateBudgetAndHowToRaise) {
  Estimate e;
  e.steps = {3e12, {"time.after_contact", "time.dt"}};
  e.memory = {1e6, {"population.samples"}};
  e.output = {1e3, {}};
  const Budgets b{2e11, 1e9, 1e9};
  const std::string m = message_of([&] { check_budgets(e, b, "case.toml"); });
  EXPECT_NE(m.find("case.toml"), std::string::npos) << m;
  EXPECT_NE(m.find("time.after_contact, time.dt"), std::string::npos) << m;
  EXPECT_NE(m.find("3e+12"), std::string::npos) << m;
  EXPECT_NE(m.find("2e+11"), std::string::npos) << m;
  EXPECT_NE(m.find("--max-steps or AGGLO_MAX_STEPS"), std::string::npos) << m;
  EXPECT_NO_THROW(check_budgets(e, Budgets{3e12, 1e6, 1e3}, "case.toml"));  // at the budget is allowed
  e.memory.value = 2e9;
  EXPECT_NE(message_of([&] { check_budgets(e, Budgets{3e12, 1e9, 1e9}, "x"); }).find("--max-memory"),
            std::string::npos);
}
