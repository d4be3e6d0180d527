#include "agglo/run/calibrate_case.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "agglo/core/error.hpp"
#include "agglo/core/settings_calibrate.hpp"
#include "agglo/core/settings_catalogue.hpp"
#include "agglo/impact/impact_case.hpp"

namespace agglo::run {

namespace {

void parse_fit(const ConfigSection& root, calibrate::Spec& spec) {
  const auto& f = settings::calibrate_settings().fit;
  const auto s = f.t.open(root);
  spec.grid_points = static_cast<int>(f.grid_points.read(s));
  spec.refine_rounds = static_cast<int>(f.refine_rounds.read(s));
  spec.refine_points = static_cast<int>(f.refine_points.read(s));
  spec.fine_points = static_cast<int>(f.fine_points.read(s));
  spec.span = f.span.read(s);
  spec.smoothing = f.smoothing.read(s);
  spec.robustness_iterations = static_cast<int>(f.robustness_iterations.read(s));
  spec.check = f.check.read(s);
  spec.widths = f.widths.read(s);
}

// The declared setting of a dotted key of a target case ("particles.2.radius" -> particles.radius); null
// when no table declares it (the target cases then refuse the key).
const settings::Setting* declared_setting(const std::string& key) {
  std::string dotted;
  for (std::size_t from = 0; from <= key.size();) {
    const std::size_t to = std::min(key.find('.', from), key.size());
    const std::string part = key.substr(from, to - from);
    if (part.empty() || part.find_first_not_of("0123456789") != std::string::npos)
      dotted += (dotted.empty() ? "" : ".") + part;
    from = to + 1;
  }
  for (const settings::Table* t : settings::all_tables())
    for (const settings::Setting* s : t->settings())
      if (s->dotted() == dotted) return s;
  return nullptr;
}

// A key fitted once, and a real number: the surrogate and its best fit are real values, which an integer
// key would not take (a best vcrit.scan_points of 5.4 was reported while the runs read other values).
void check_parameter_key(const settings::CalibrateSettings::Parameter& p, const ConfigSection& s,
                         const std::string& key, const std::vector<calibrate::Parameter>& earlier) {
  for (std::size_t j = 0; j < earlier.size(); ++j)
    if (earlier[j].key == key)
      p.key.reject(s, fmt::format("is also the key of [[{}]] {}: each key is fitted by one table", p.t.name(), j));
  if (const auto* d = declared_setting(key); d && d->type() != settings::Type::real)
    p.key.reject(s, fmt::format("is a key of type {}; calibrate fits keys of type real only",
                                settings::type_name(d->type())));
}

void parse_parameters(const ConfigSection& root, calibrate::Spec& spec) {
  const auto& p = settings::calibrate_settings().parameter;
  const auto elems = p.t.elements(root);
  if (elems.empty() || elems.size() > 2) p.t.fail(root, fmt::format("1 or 2 [[parameter]] tables required, {} given", elems.size()));
  for (const auto& s : elems) {
    calibrate::Parameter q;
    q.key = p.key.read(s);
    check_parameter_key(p, s, q.key, spec.parameters);
    q.lower = p.lower.read(s);
    q.upper = p.upper.read(s);
    q.log_scale = p.scale.read(s) == "log";
    if (!(q.upper > q.lower))
      p.upper.reject(s, fmt::format("empty range: must exceed {} = {:g}", p.lower.dotted(), q.lower));
    if (q.log_scale && !(q.lower > 0.0)) p.lower.reject(s, "a log-scale range must start above 0");
    spec.parameters.push_back(q);
  }
}

// The assignments of calibrate.case_overrides applied to a target case (ConfigError naming that key).
void apply_case_overrides(const ConfigSection& root, Config& target) {
  const auto& f = settings::calibrate_settings().fit;
  const auto s = f.t.open(root);
  const std::string text = f.case_overrides.read(s);
  try {
    std::size_t from = 0;
    while (from <= text.size()) {
      const std::size_t to = std::min(text.find(';', from), text.size());
      const auto a = text.substr(from, to - from);
      if (a.find_first_not_of(" \t") != std::string::npos) target.apply_override(a);
      from = to + 1;
    }
    Config probe = target.clone();
    (void)impact::parse_impact_case(probe);
    probe.check_unknown_keys();
  } catch (const ConfigError& e) {
    f.case_overrides.reject(s, fmt::format("not accepted by target case {}: {}", target.file(), e.what()));
  }
}

// The case of a [[target]] or [[prediction]] table, loaded relative to `dir`, with calibrate.case_overrides.
CalibrationTarget load_case(const ConfigSection& root, const ConfigSection& s, const std::filesystem::path& dir,
                            const settings::Text& case_file, const settings::Choice& observable) {
  CalibrationTarget ct;
  ct.file = dir / case_file.read(s);
  ct.observable = observable.read(s);
  if (!std::filesystem::is_regular_file(ct.file)) case_file.reject(s, fmt::format("no such file {}", ct.file.string()));
  ct.base = Config::load(ct.file);
  apply_case_overrides(root, ct.base);
  return ct;
}

void parse_targets(const ConfigSection& root, const std::filesystem::path& dir, CalibrateCase& c) {
  const auto& t = settings::calibrate_settings().target;
  const auto elems = t.t.elements(root);
  if (elems.empty()) t.t.fail(root, "at least one [[target]] table is required");
  for (const auto& s : elems) {
    CalibrationTarget ct = load_case(root, s, dir, t.case_file, t.observable);
    calibrate::Target target;
    target.value = t.value.read(s);
    target.tolerance = t.tolerance.read(s);
    target.name = fmt::format("{} {}", ct.file.stem().string(), ct.observable);
    c.spec.targets.push_back(target);
    c.targets.push_back(std::move(ct));
  }
}

void parse_predictions(const ConfigSection& root, const std::filesystem::path& dir, CalibrateCase& c) {
  const auto& t = settings::calibrate_settings().prediction;
  for (const auto& s : t.t.elements(root)) {
    CalibrationTarget ct = load_case(root, s, dir, t.case_file, t.observable);
    Config probe = ct.base.clone();
    (void)impact::parse_impact_case(probe);
    ct.resolved = probe.resolved_toml();
    c.predictions.push_back(std::move(ct));
  }
}

}  // namespace

Config target_config(const CalibrateCase& c, const CalibrationTarget& t, const std::vector<double>& x) {
  Config cfg = t.base.clone();
  for (std::size_t j = 0; j < x.size(); ++j) cfg.apply_override(fmt::format("{}={:.17g}", c.spec.parameters[j].key, x[j]));
  (void)impact::parse_impact_case(cfg);
  cfg.check_unknown_keys();
  return cfg;
}

CalibrateCase parse_calibrate_case(Config& cfg) {
  CalibrateCase c;
  auto root = cfg.root();
  parse_fit(root, c.spec);
  c.predict = settings::calibrate_settings().fit.predict.read(settings::calibrate_settings().fit.t.open(root));
  parse_parameters(root, c.spec);
  const auto dir = std::filesystem::path(cfg.file()).parent_path();
  parse_targets(root, dir, c);
  parse_predictions(root, dir, c);
  cfg.check_unknown_keys();
  // Every parameter key must be accepted by every target case at both ends of its range.
  const auto& p = settings::calibrate_settings().parameter;
  const auto elems = p.t.elements(root);
  for (std::size_t k = 0; k < c.targets.size(); ++k) {
    Config probe = c.targets[k].base.clone();
    (void)impact::parse_impact_case(probe);
    c.targets[k].resolved = probe.resolved_toml();
    for (std::size_t j = 0; j < c.spec.parameters.size(); ++j)
      for (double v : {c.spec.parameters[j].lower, c.spec.parameters[j].upper}) {
        std::vector<double> x;
        for (const auto& q : c.spec.parameters) x.push_back(q.lower);
        x[j] = v;
        try {
          (void)target_config(c, c.targets[k], x);
        } catch (const ConfigError& e) {
          p.key.reject(elems[j], fmt::format("not accepted by target case {} at {:g}: {}", c.targets[k].file.filename().string(), v, e.what()));
        }
      }
  }
  return c;
}

}  // namespace agglo::run
