// agglo config --list [SECTION] | --markdown: the declared case-file settings (key, type, unit,
// default, range, meaning) from the settings tables; --markdown writes docs/config.md's text.
#include <cstdio>
#include <memory>
#include <string>

#include "agglo/core/settings_catalogue.hpp"
#include "command.hpp"

namespace {

struct ConfigArgs {
  std::string section;
  bool list = false;
  bool markdown = false;
};

agglo::cli::Registration register_config([](CLI::App& app) {
  auto a = std::make_shared<ConfigArgs>();
  auto* sub = app.add_subcommand("config", "List the case-file settings: key, type, unit, default, range, meaning");
  sub->add_flag("--list", a->list, "Print the settings tables (all, or the SECTION given)");
  sub->add_option("section", a->section, "Section to list, e.g. material, population, top (default: all)");
  auto* md = sub->add_flag("--markdown", a->markdown, "Print every table as Markdown (docs/config.md)");
  md->excludes("section");
  sub->callback([a] {
    const std::string text = a->markdown ? agglo::settings::markdown_text() : agglo::settings::list_text(a->section);
    std::fputs(text.c_str(), stdout);
  });
});

}  // namespace
