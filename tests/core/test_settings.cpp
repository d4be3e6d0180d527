// Settings tables: one declaration per key gives the default, the range check, the error text,
// the resolved config and the --list / --markdown listings.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "agglo/core/error.hpp"
#include "agglo/core/settings.hpp"
#include "agglo/core/settings_catalogue.hpp"
#include "agglo/core/settings_impact.hpp"
#include "agglo/impact/impact_case.hpp"
#include "agglo/run/commands.hpp"

using namespace agglo;
using namespace agglo::settings;

namespace {

// A small table of every kind of setting (not part of the catalogue).
struct Demo {
  Table t{"demo", "test", "demo section"};
  Real length{t, {"demo.length", "m", "a length"}, 2.5, Range::positive()};
  Real gap{t, {"demo.gap", "m", "a gap", {}, "0 = none"}, 0.0, Range::nonnegative()};
  Real size{t, {"demo.size", "m", "a required size"}, std::nullopt, Range::positive()};
  Integer count{t, {"demo.count", "", "a count"}, 3, 1, 10};
  Bool on{t, {"demo.on", "", "a switch"}, true};
  Choice mode{t, {"demo.mode", "", "a mode"}, "fast", {"fast", "slow"}};
  Reals times{t, {"demo.times", "s", "some times"}, std::vector<double>{0.0, 1.0}, Range::nonnegative()};
  Vector3 field{t, {"demo.field", "V/m", "a field"}, Vec3{0, 0, 1}, Range::any()};
};

const Demo& demo() {
  static const Demo d;
  return d;
}

std::string error_of(const std::string& toml, void (*read)(ConfigSection)) {
  try {
    auto cfg = Config::from_string(toml, "case.toml");
    read(demo().t.open(cfg.root()));
    cfg.check_unknown_keys();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

void read_all(ConfigSection s) {
  const auto& d = demo();
  d.length.read(s);
  d.gap.read(s);
  d.size.read(s);
  d.count.read(s);
  d.on.read(s);
  d.mode.read(s);
  d.times.read(s);
  d.field.read(s);
}

}  // namespace

TEST(Settings, DefaultsAreReturnedAndWrittenBack) {
  auto cfg = Config::from_string("[demo]\nsize = 1.0\n", "case.toml");
  auto s = demo().t.open(cfg.root());
  EXPECT_DOUBLE_EQ(demo().length.read(s), 2.5);
  EXPECT_EQ(demo().count.read(s), 3);
  EXPECT_TRUE(demo().on.read(s));
  EXPECT_EQ(demo().mode.read(s), "fast");
  EXPECT_EQ(demo().times.read(s), (std::vector<double>{0.0, 1.0}));
  EXPECT_DOUBLE_EQ(demo().field.read(s).z, 1.0);
  EXPECT_DOUBLE_EQ(demo().length.read_or(s, 7.0), 2.5) << "a default never overrides a value read before";
  const std::string text = cfg.resolved_toml();
  for (const char* line : {"length = 2.5", "count = 3", "on = true", "mode = 'fast'", "size = 1.0"})
    EXPECT_NE(text.find(line), std::string::npos) << line << " missing in\n" << text;
}

TEST(Settings, ComputedDefault) {
  auto cfg = Config::from_string("", "case.toml");
  auto s = demo().t.open(cfg.root());
  EXPECT_DOUBLE_EQ(demo().size.read_or(s, 4.0), 4.0);
  EXPECT_NE(cfg.resolved_toml().find("size = 4.0"), std::string::npos);
}

TEST(Settings, ErrorsNameTheDottedKeyValueAndRule) {
  EXPECT_EQ(error_of("[demo]\nsize = 1.0\nlength = -1.0\n", read_all),
            "case.toml: key 'demo.length' = -1: out of range, allowed (0, inf) m");
  EXPECT_EQ(error_of("[demo]\nsize = 1.0\ngap = -1.0\n", read_all),
            "case.toml: key 'demo.gap' = -1: out of range, allowed [0, inf) m (0 = none)");
  EXPECT_EQ(error_of("[demo]\nsize = 1.0\ncount = 11\n", read_all),
            "case.toml: key 'demo.count' = 11: out of range, allowed [1, 10]");
  EXPECT_EQ(error_of("[demo]\nsize = 1.0\nmode = \"medium\"\n", read_all),
            "case.toml: key 'demo.mode' = \"medium\": unknown choice, allowed \"fast\", \"slow\"");
  EXPECT_EQ(error_of("[demo]\nsize = 1.0\non = 1\n", read_all),
            "case.toml: key 'demo.on' = 1: expected true or false");
  EXPECT_EQ(error_of("[demo]\nsize = 1.0\nfield = [1, 2]\n", read_all),
            "case.toml: key 'demo.field' = [1, 2]: expected an array of 3 numbers [x, y, z]");
}

TEST(Settings, RequiredKey) {
  EXPECT_EQ(error_of("", read_all), "case.toml: key 'demo.size': required key is missing (a number in (0, inf) m)");
}

TEST(Settings, UnknownKeyListsTheDeclaredOnes) {
  const std::string m = error_of("[demo]\nsize = 1.0\nlenght = 1.0\n", read_all);
  EXPECT_NE(m.find("unknown key 'demo.lenght'"), std::string::npos) << m;
  EXPECT_NE(m.find("length"), std::string::npos) << m;
}

TEST(Settings, ModelErrorsAreMappedToTheSetting) {
  auto cfg = Config::from_string("[demo]\nlength = 3.0\n", "case.toml");
  auto s = demo().t.open(cfg.root());
  try {
    check_as(demo().length, s, [] { throw NumericalError("too long for the box"); });
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_STREQ(e.what(), "case.toml: key 'demo.length' = 3: too long for the box");
  }
  EXPECT_NO_THROW(check_as(demo().length, s, [] {}));
}

TEST(Settings, DeclarationsDescribeThemselves) {
  EXPECT_EQ(demo().length.leaf(), "length");
  EXPECT_EQ(demo().length.default_text(), "2.5");
  EXPECT_EQ(demo().size.default_text(), "required");
  EXPECT_EQ(demo().gap.range_text(), "[0, inf) (0 = none)");
  EXPECT_EQ(demo().mode.range_text(), "\"fast\", \"slow\"");
  EXPECT_EQ(demo().count.range_text(), "[1, 10]");
  EXPECT_EQ(demo().times.default_text(), "[0, 1]");
  EXPECT_EQ(demo().t.settings().size(), 8u);
}

TEST(Settings, CatalogueKeysAreUniqueAndInTheirSection) {
  std::set<std::string> seen;
  for (const auto* t : all_tables())
    for (const auto* s : t->settings()) {
      const std::string key(s->dotted());
      EXPECT_TRUE(seen.insert(key).second) << key << " declared twice";
      if (!t->name().empty()) {
        EXPECT_EQ(key.rfind(std::string(t->name()) + ".", 0), 0u) << key;
      }
      EXPECT_EQ(key.find('.', t->name().empty() ? 0 : t->name().size() + 1), std::string::npos) << key;
      EXPECT_FALSE(s->info().meaning.empty()) << key;
    }
  EXPECT_GT(seen.size(), 100u);
}

// [contact] and [kernels] are declared beside the models they name and join the catalogue after
// [material] and [domain]; their allowed values are the registered names, the former spellings noted.
TEST(Settings, EngineTablesJoinTheCatalogue) {
  (void)agglo::run::all_commands();  // builds the tables the engines declare
  std::vector<std::string> names;
  for (const auto* t : all_tables()) names.emplace_back(t->name());
  const auto at = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
  EXPECT_EQ(at("contact"), at("material") + 1);
  EXPECT_EQ(at("kernels"), at("domain") + 1);
  const std::string contact = list_text("contact");
  EXPECT_NE(contact.find("\"marshall\", \"ruan_li\" (\"seed\": deprecated name of \"ruan_li\")"), std::string::npos)
      << contact;
  EXPECT_NE(contact.find("\"marshall\", \"none\" (also true = \"marshall\", false = \"none\")"), std::string::npos)
      << contact;
  const std::string kernels = list_text("kernels");
  EXPECT_NE(kernels.find("\"acoustic\", \"brownian_fuchs\", \"constant\", \"additive\", \"brownian_partmc\""),
            std::string::npos)
      << kernels;
}

TEST(Settings, ListOneSection) {
  const std::string text = list_text("vcrit");
  EXPECT_EQ(text.rfind("[vcrit] (vcrit, breakup): critical break-up speed search\n", 0), 0u) << text;
  EXPECT_NE(text.find("vcrit.points_per_round  integer  -     2        [1, 64]"), std::string::npos) << text;
  EXPECT_EQ(text.find("material."), std::string::npos);
  EXPECT_THROW(list_text("nosuchsection"), ConfigError);
  EXPECT_NE(markdown_text().find("| `vcrit.points_per_round` | integer |  | 2 | [1, 64] |"), std::string::npos);
}

TEST(Settings, PointsPerRound) {
  const auto& k = impact_settings().vcrit.points_per_round;
  auto cfg = Config::from_string("", "case.toml");
  EXPECT_EQ(impact::parse_impact_case(cfg).vcrit.points_per_round, 2);
  EXPECT_NE(cfg.resolved_toml().find("points_per_round = 2"), std::string::npos);
  for (const char* bad : {"0", "65"}) {
    auto c = Config::from_string(std::string("[vcrit]\npoints_per_round = ") + bad + "\n", "case.toml");
    try {
      impact::parse_impact_case(c);
      ADD_FAILURE() << bad << " accepted";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(k.dotted()) + "' = " + bad + ": out of range, allowed [1, 64]"),
                std::string::npos)
          << e.what();
    }
  }
  auto c = Config::from_string("[vcrit]\npoints_per_round = 8\n", "case.toml");
  EXPECT_EQ(impact::parse_impact_case(c).vcrit.points_per_round, 8);
}
