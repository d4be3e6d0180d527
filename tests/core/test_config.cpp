// Config layer: every kind of bad input gives a one-line ConfigError naming file, key, value and rule.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "agglo/impact/impact_case.hpp"
#include "agglo/core/config.hpp"
#include "agglo/core/error.hpp"

using namespace agglo;

namespace {

std::string error_of(const std::string& toml, const std::vector<std::string>& sets = {}) {
  try {
    auto cfg = Config::from_string(toml, "case.toml");
    for (const auto& s : sets) cfg.apply_override(s);
    impact::parse_impact_case(cfg);
    cfg.check_unknown_keys();
  } catch (const ConfigError& e) {
    std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "message must be one line: " << m;
    return m;
  }
  return "";
}

void expect_has(const std::string& msg, std::initializer_list<const char*> parts) {
  ASSERT_FALSE(msg.empty()) << "expected an error";
  for (auto p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' missing in: " << msg;
}

TEST(Config, ValidCaseParses) { EXPECT_EQ(error_of("[material]\nrestitution = 0.5\n"), ""); }

TEST(Config, UnknownKey) {
  expect_has(error_of("[material]\nrestitutoin = 0.5\n"), {"case.toml", "material.restitutoin", "unknown", "restitution"});
  expect_has(error_of("bogus = 1\n"), {"case.toml", "'bogus'", "unknown"});
  expect_has(error_of("[nosuchsection]\nx = 1\n"), {"nosuchsection", "unknown"});
}

TEST(Config, WrongType) {
  expect_has(error_of("[agglomerate]\nradius = \"big\"\n"), {"case.toml", "agglomerate.radius", "\"big\"", "number"});
  expect_has(error_of("[contact]\nrolling = 1\n"), {"contact.rolling", "expected one of \"marshall\", \"none\""});
  expect_has(error_of("material = 3\n"), {"'material'", "table"});
}

TEST(Config, OutOfRangeAndNonFinite) {
  expect_has(error_of("[agglomerate]\nradius = -1e-6\n"), {"agglomerate.radius", "-1e-06", "(0, 0.1] m"});
  expect_has(error_of("[material]\nrestitution = 1.5\n"), {"material.restitution", "1.5", "(0, 1]"});
  expect_has(error_of("[material]\nrestitution = 0.0\n"), {"material.restitution", "(0, 1]"});
  expect_has(error_of("[material]\nyoungs_modulus = nan\n"), {"material.youngs_modulus", "nan", "finite"});
  expect_has(error_of("[material]\ndensity = inf\n"), {"material.density", "inf", "finite"});
  expect_has(error_of("[contact]\nbreak_rule = \"sometimes\"\n"), {"contact.break_rule", "\"marshall\", \"lammps\""});
  expect_has(error_of("[vcrit]\nv_min = 0.5\nv_max = 0.1\n"), {"vcrit.v_max", "0.1"});
}

// The contact sub-models by name: the former booleans still read (true/false = the Marshall springs
// or alpha damping / none), the deprecated "seed" reads as "ruan_li" with one warning, and a rolling
// spring without a sliding spring is rejected on its key, as the rolling model declares.
TEST(Config, ContactModelsByName) {
  auto cfg = Config::from_string(
      "[contact]\ntangential = \"marshall\"\nrolling = true\ntwisting = false\ndamping = false\n", "case.toml");
  auto m = impact::parse_impact_case(cfg).dem.contact.models;
  EXPECT_EQ(m.tangential, "marshall");
  EXPECT_EQ(m.rolling, "marshall");
  EXPECT_EQ(m.twisting, "none");
  EXPECT_EQ(m.damping, "none");
  EXPECT_TRUE(cfg.take_warnings().empty());
  cfg = Config::from_string("[contact]\ntangential = \"seed\"\n", "case.toml");
  m = impact::parse_impact_case(cfg).dem.contact.models;
  EXPECT_EQ(m.tangential, "ruan_li");
  EXPECT_EQ(m.damping, "alpha");
  const auto warnings = cfg.take_warnings();
  ASSERT_EQ(warnings.size(), 1u);
  expect_has(warnings[0], {"case.toml", "contact.tangential", "\"seed\"", "deprecated", "\"ruan_li\""});
  expect_has(error_of("[contact]\nrolling = \"marshall\"\n"),
             {"contact.rolling", "needs a tangential model with a sliding spring (\"marshall\")", "\"ruan_li\""});
  expect_has(error_of("[contact]\ntwisting = true\n"), {"contact.twisting", "sliding spring"});
  expect_has(error_of("[contact]\nrolling = \"velcro\"\n"), {"contact.rolling", "\"marshall\", \"none\""});
}

TEST(Config, MissingRequiredKey) {
  expect_has(error_of("[agglomerate]\nshape = \"list\"\n[[particles]]\nposition = [0,0,0]\n[[particles]]\nposition = [1,0,0]\nradius = 1e-6\n"),
             {"particles.0.radius", "required"});
}

TEST(Config, SyntaxError) { expect_has(error_of("[material\n"), {"case.toml:1", "syntax"}); }

TEST(Config, OverridesApplyAndAreValidated) {
  auto cfg = Config::from_string("[material]\nrestitution = 0.5\n", "case.toml");
  cfg.apply_override("material.restitution=0.8");
  cfg.apply_override("contact.tangential=marshall");  // bare word = string
  auto c = impact::parse_impact_case(cfg);
  cfg.check_unknown_keys();
  EXPECT_DOUBLE_EQ(c.dem.contact.restitution, 0.8);
  EXPECT_EQ(c.dem.contact.models.tangential, "marshall");
  expect_has(error_of("", {"material.restitution=2"}), {"material.restitution", "2", "(0, 1]"});
  expect_has(error_of("", {"material.nope=2"}), {"material.nope", "unknown"});
  EXPECT_THROW(Config::from_string("").apply_override("novalue"), ConfigError);
}

TEST(Config, ResolvedConfigHoldsDefaults) {
  auto cfg = Config::from_string("[material]\nrestitution = 0.5\n", "case.toml");
  impact::parse_impact_case(cfg);
  auto text = cfg.resolved_toml();
  // Round trip: the resolved text parses to the same values, with every default present.
  auto again = Config::from_string(text, "resolved.toml");
  auto c = impact::parse_impact_case(again);
  again.check_unknown_keys();
  EXPECT_DOUBLE_EQ(c.dem.contact.restitution, 0.5);
  EXPECT_NE(text.find("youngs_modulus"), std::string::npos);
  EXPECT_NE(text.find("break_rule"), std::string::npos);
}

}  // namespace

// Issue 9 items 1, 11, 13, 14: malformed --set assignments, empty case files, one-line messages.
TEST(ConfigHardening, WhitespaceKeyIsAnErrorNotACrash) {
  for (const char* s : {" =5", "\t=5", " \t \n=5", ". =5"})
    EXPECT_THROW(Config::from_string("").apply_override(s), ConfigError) << s;
}

TEST(ConfigHardening, TrailingDotAndSecondAssignmentRejected) {
  EXPECT_THROW(Config::from_string("").apply_override("material.density.=2500"), ConfigError);
  EXPECT_THROW(Config::from_string("").apply_override(".material.density=2500"), ConfigError);
  EXPECT_THROW(Config::from_string("").apply_override("material.density=2500\nbogus=1"), ConfigError);
  EXPECT_THROW(Config::from_string("").apply_override("material.density=2500\n[x]\ny=1"), ConfigError);
  EXPECT_THROW(Config::from_string("").apply_override("material.name=a\nb c"), ConfigError);
  auto cfg = Config::from_string("");
  cfg.apply_override(" material . density = 2500 # comment");
  EXPECT_NE(cfg.resolved_toml().find("density = 2500"), std::string::npos) << cfg.resolved_toml();
}

TEST(ConfigHardening, EmptyCaseFileIsAnError) {
  const auto dir = std::filesystem::temp_directory_path() / ("agglo_empty_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "empty.toml") << ""; }
  try {
    Config::load(dir / "empty.toml");
    ADD_FAILURE() << "an empty case file must be an error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("empty.toml: empty case file"), std::string::npos) << e.what();
  }
  { std::ofstream(dir / "newline.toml") << "\n"; }
  EXPECT_NO_THROW(Config::load(dir / "newline.toml"));  // an explicit "all defaults" case
  std::filesystem::remove_all(dir);
}

TEST(ConfigHardening, OneLineEscapesControlCharacters) {
  EXPECT_EQ(one_line("a\nb\tc\rd\x1b" "e"), "a\\nb\\tc\\rd\\x1be");
  EXPECT_EQ(one_line("x\u2028y\u2029z\u0085w"), "x\\u2028y\\u2029z\\u0085w");
  EXPECT_EQ(one_line("plain é ü"), "plain é ü");
}
