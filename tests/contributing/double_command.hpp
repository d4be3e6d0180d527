#pragma once
// Command "double": reads [double] value and returns twice it, in summary.json's "twice" and, with CSV
// output on, in result.json (the worked example of a command in docs/contributing.md).
#include "agglo/core/settings.hpp"
#include "agglo/run/command.hpp"

namespace agglo::run {

struct DoubleSettings {
  settings::Table t{"double", "double", "the number the example command doubles"};
  settings::Real value{t, {"double.value", "", "the number to double"}, 1.0, Range::closed(-1e6, 1e6)};
};

class DoubleCommand final : public Command {
 public:
  std::string_view name() const override { return "double"; }
  std::string_view help() const override { return "Doubles [double] value (the example of docs/contributing.md)"; }
  void parse(Config& cfg) const override { (void)value(cfg); }
  CommandResult run(Config& cfg, const OutputDir& out, const RunContext& ctx) const override {
    CommandResult r;
    r.summary = {{"twice", 2.0 * value(cfg)}};
    if (ctx.formats.csv) out.write_json("result.json", r.summary);
    return r;
  }

 private:
  static const DoubleSettings& keys() {
    static const DoubleSettings k;
    return k;
  }
  static double value(Config& cfg) { return keys().value.read(keys().t.open(cfg.root())); }
};

}  // namespace agglo::run
