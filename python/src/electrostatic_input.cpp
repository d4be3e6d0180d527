#include "electrostatic_input.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>

#include "agglo/core/config.hpp"
#include "agglo/core/error.hpp"
#include "agglo/core/settings_electrostatics.hpp"
#include "agglo/electrostatics/config.hpp"
#include "agglo/electrostatics/estimate.hpp"
#include "agglo/electrostatics/validate_spheres.hpp"
#include "agglo/run/budget.hpp"
#include "agglo/run/command.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

constexpr const char* kWhere = "agglo.electrostatic_forces";
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

[[noreturn]] void fail(const std::string& what) { throw ConfigError(one_line(fmt::format("{}: {}", kWhere, what))); }

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) s += fmt::format("{}{}", d ? ", " : "", a.shape(d));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// `o` as a C-contiguous float64 array; integers are converted, anything else is refused.
Array real_array(const py::object& o, const char* name) {
  if (o.is_none()) fail(fmt::format("{} is None (must be an array of real numbers)", name));
  py::array a;
  try {
    a = py::module_::import("numpy").attr("asarray")(o);
  } catch (py::error_already_set& e) {
    fail(fmt::format("{} cannot be read as an array of real numbers ({})", name, e.what()));
  }
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    fail(fmt::format("{} has dtype {} (must be real numbers: float64, or integers or floats converted to it)", name,
                     py::str(a.dtype()).cast<std::string>()));
  return Array::ensure(a);
}

// "(must be in (0, 0.1] m, the range of particles.radius)": the range of the [[particles]] key a CLI case
// would give the same value with.
std::string range_rule(const Range& range, std::string_view key) {
  return fmt::format("(must be in {}, the range of {})", range.describe(), key);
}

std::vector<Vec3> read_positions(const py::object& o) {
  const Array a = real_array(o, "positions");
  if (a.ndim() != 2 || a.shape(1) != 3 || a.shape(0) < 1)
    fail(fmt::format("positions has shape {} (must be (N, 3) with N >= 1 spheres, in m)", shape_text(a)));
  const auto& key = settings::electrostatics_settings().particles.position;
  std::vector<Vec3> x(static_cast<std::size_t>(a.shape(0)));
  const double* p = a.data();
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = {p[3 * i], p[3 * i + 1], p[3 * i + 2]};
    if (!key.component_range().contains(x[i].x) || !key.component_range().contains(x[i].y) ||
        !key.component_range().contains(x[i].z))
      fail(fmt::format("positions[{}] = [{}, {}, {}] m {}", i, x[i].x, x[i].y, x[i].z,
                       range_rule(key.component_range(), key.dotted())));
  }
  return x;
}

// One value per sphere (a scalar applies to all), within the range of the [[particles]] key `key`.
std::vector<double> read_per_sphere(const py::object& o, const char* name, const settings::Real& key, std::size_t n) {
  const Array a = real_array(o, name);
  const bool scalar = a.ndim() == 0;
  if (!scalar && (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n))
    fail(fmt::format("{} has shape {} (must be ({},), one value per row of positions, or a scalar)", name,
                     shape_text(a), n));
  const std::string_view unit = key.info().unit;
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = a.data()[scalar ? 0 : i];
    if (!key.range().contains(v[i]))
      fail(fmt::format("{}[{}] = {}{}{} {}", name, i, v[i], unit.empty() ? "" : " ", unit,
                       range_rule(key.range(), key.dotted())));
  }
  return v;
}

Vec3 read_field(const py::object& o) {
  if (o.is_none()) return {};
  const Array a = real_array(o, "external_field");
  if (a.ndim() != 1 || a.shape(0) != 3)
    fail(fmt::format("external_field has shape {} (must be (3,), in V/m, or None)", shape_text(a)));
  const Vec3 e{a.data()[0], a.data()[1], a.data()[2]};
  if (!isfinite(e)) fail(fmt::format("external_field = [{}, {}, {}] V/m (must be finite)", e.x, e.y, e.z));
  return e;
}

// A Python number or string as a TOML value (read back by the [electrostatics] settings).
std::string option_toml_value(const std::string& name, const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(v)) return nlohmann::json(v.cast<std::string>()).dump();
  if (PyIndex_Check(v.ptr())) {
    int overflow = 0;
    const long long i = PyLong_AsLongLongAndOverflow(py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr())).ptr(),
                                                     &overflow);
    if (overflow) fail(fmt::format("argument '{}' = {} is out of range", name, py::str(v).cast<std::string>()));
    return std::to_string(i);
  }
  if (py::isinstance<py::float_>(v)) {  // a TOML float also when integral (2.0 is no integer, as in a case file)
    std::string f = fmt::format("{}", v.cast<double>());
    if (f.find_first_of(".eni") == std::string::npos) f += ".0";
    return f;
  }
  fail(fmt::format("argument '{}' has type {} (must be a number or a string)", name,
                   py::str(py::type::of(v).attr("__name__")).cast<std::string>()));
}

const std::vector<const settings::Setting*>& option_settings() {
  const auto& k = es::es_keys();
  static const std::vector<const settings::Setting*> s{
      &k.max_degree, &k.target_accuracy, &k.max_degree_limit, &k.far_field, &k.preconditioner, &k.preconditioner_steps,
      &k.patches_per_sphere, &k.tolerance,
      &k.max_iterations, &k.matvec, &k.fmm_order, &k.fmm_leaf_size};
  return s;
}

// The settings' message names the key 'electrostatics.x'; here it is the argument 'x'.
std::string as_argument_message(std::string m) {
  const std::string key = fmt::format("key '{}.", es::es_keys().t.name());
  if (auto at = m.find(key); at != std::string::npos) m.replace(at, key.size(), "argument '");
  return m;
}

es::EsConfig read_settings(const EsArguments& a) {
  const auto& k = es::es_keys();
  std::string text = fmt::format("[{}]\n", k.t.name());
  auto add = [&](std::string_view leaf, const py::handle& v) {
    text += fmt::format("{} = {}\n", leaf, option_toml_value(std::string(leaf), v));
  };
  add(k.solver.leaf(), a.solver);
  add(k.medium_permittivity.leaf(), a.medium_permittivity);
  add(k.min_gap.leaf(), a.min_gap.is_none() ? py::float_(0.0) : a.min_gap);
  const auto names = es_option_names();
  for (const auto& [key, value] : a.options) {
    const auto name = key.cast<std::string>();
    if (std::find(names.begin(), names.end(), name) == names.end())
      fail(fmt::format("unknown option '{}' (allowed: {})", name, fmt::join(names, ", ")));
    add(name, value);
  }
  try {
    Config cfg = Config::from_string(text, kWhere);
    return es::parse_electrostatics(k.t.open(cfg.root()));
  } catch (const ConfigError& e) {
    throw ConfigError(one_line(as_argument_message(e.what())));
  }
}

// Refuse touching or overlapping spheres with a message naming the pair and the gap.
void check_spheres(const es::Problem& p, const std::optional<double>& min_gap) {
  try {
    es::validate_spheres(p);
  } catch (const es::InvalidSpheres& e) {
    if (e.reason != es::InvalidSpheres::Reason::overlap) fail(e.detail);
    const auto& a = p.spheres[static_cast<std::size_t>(e.first)];
    const auto& b = p.spheres[static_cast<std::size_t>(e.second)];
    const double d = norm(a.center - b.center);
    const std::string what = fmt::format("spheres {} and {} touch or overlap: surface gap {:.6g} m (centre distance "
                                         "{:.6g} m, radii {:.6g} m and {:.6g} m",
                                         e.first, e.second, d - a.radius - b.radius, d, a.radius, b.radius);
    if (!min_gap) fail(what + "); separate them, or pass min_gap to regularise contacts (docs/model.md §B.3)");
    fail(fmt::format("{} after shrinking by min_gap = {}); separate them or raise min_gap", what, *min_gap));
  }
}

// max_steps and max_memory (a number, or a size text such as "8G"), else the environment's or the
// defaults, as for the command functions (docs/limits.md). No output budget: nothing is written.
run::Budgets read_budgets(const EsArguments& a) {
  run::Budgets b = run::resolve_budgets({});
  auto text = [](const py::object& o, const char* name) -> std::optional<std::string> {
    if (o.is_none()) return std::nullopt;
    if (py::isinstance<py::str>(o)) return o.cast<std::string>();
    if (!py::isinstance<py::bool_>(o) && (PyIndex_Check(o.ptr()) || py::isinstance<py::float_>(o)))
      return py::str(o).cast<std::string>();
    fail(fmt::format("argument '{}' = {} (must be a number or a size text such as \"8G\", or None)", name,
                     py::repr(o).cast<std::string>()));
  };
  const auto steps = text(a.max_steps, "max_steps"), memory = text(a.max_memory, "max_memory");
  try {
    if (steps) b.max_steps = run::parse_steps(*steps, "max_steps");
    if (memory) b.max_memory_bytes = run::parse_size(*memory, "max_memory");
  } catch (const ConfigError& e) {
    fail(e.what());
  }
  return b;
}

std::optional<int> read_threads(const py::object& o) {
  if (o.is_none()) return std::nullopt;
  const std::string v = option_toml_value("threads", o);
  char* end = nullptr;
  const long long n = std::strtoll(v.c_str(), &end, 10);
  if (*end != '\0' || n < 0 || n > std::numeric_limits<int>::max())
    fail(fmt::format("argument 'threads' = {} (must be a whole number >= 0; 0 = all cores; None = OpenMP default)",
                     py::repr(o).cast<std::string>()));
  return static_cast<int>(n);
}

}  // namespace

std::vector<std::string> es_option_names() {
  std::vector<std::string> names;
  for (const auto* s : option_settings()) names.emplace_back(s->leaf());
  return names;
}

EsInput read_es_input(const EsArguments& a) {
  EsInput in;
  const std::vector<Vec3> x = read_positions(a.positions);
  const std::size_t n = x.size();
  const auto& keys = settings::electrostatics_settings().particles;
  const auto r = read_per_sphere(a.radii, "radii", keys.radius, n);
  const auto q = read_per_sphere(a.charges, "charges", keys.charge, n);
  const auto kappa = read_per_sphere(a.permittivities, "permittivities", keys.permittivity, n);
  const es::EsConfig ec = read_settings(a);
  const run::Budgets budgets = read_budgets(a);
  const bool surface = a.surface;
  // Before the O(N^2) check of the positions: the sizes alone (1e5 spheres are refused at once).
  run::check_budgets(es::static_solve_lower_bound(ec.options, static_cast<double>(n), surface), budgets, kWhere);
  in.options = ec.options;
  if (!a.min_gap.is_none()) in.min_gap = ec.min_gap;
  in.threads = read_threads(a.threads);
  in.problem.medium_permittivity = ec.medium_permittivity;
  in.problem.external_field = read_field(a.external_field);
  in.problem.spheres.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    in.problem.spheres[i] = {x[i], in.min_gap ? es::electrostatic_radius(r[i], *in.min_gap) : r[i], q[i], kappa[i]};
  check_spheres(in.problem, in.min_gap);
  Estimate e = es::static_solve_estimate(in.options, in.problem, surface);
  e.memory.value += run::kProcessBaseBytes;
  e.output = {};  // nothing is written
  run::check_budgets(e, budgets, kWhere);
  return in;
}

}  // namespace agglo::python
