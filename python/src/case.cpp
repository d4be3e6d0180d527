// agglo.Case (case.hpp): TOML file / text / dict -> Config, set (Config::apply_override), get, to_toml.
#include "case.hpp"

#include <regex>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "agglo/core/error.hpp"
#include "agglo/run/command.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

constexpr int kMaxDepth = 64;  // nesting levels of a dict or value (docs/limits.md)

std::string toml_string(const std::string& s) {
  std::string q = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') q += std::string("\\") + ch;
    else if (c < 0x20 || c == 0x7f) q += fmt::format("\\u{:04x}", c);
    else q += ch;
  }
  return q + "\"";
}

std::string toml_key(const std::string& k) {
  static const std::regex bare("[A-Za-z0-9_-]+");
  return std::regex_match(k, bare) ? k : toml_string(k);
}

std::string toml_real(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".ein") == std::string::npos) s += ".0";
  return s;
}

bool is_table_list(py::handle v) {
  if (!py::isinstance<py::list>(v) && !py::isinstance<py::tuple>(v)) return false;
  auto seq = py::reinterpret_borrow<py::sequence>(v);
  if (seq.size() == 0) return false;
  for (auto item : seq)
    if (!py::isinstance<py::dict>(item)) return false;
  return true;
}

// `d` as the body of a TOML table called `path` ("" = the document): plain keys first, then sub-tables
// ([path.key]) and arrays of tables ([[path.key]]).
// `depth`: the tables above it (kMaxDepth at most: a dict that contains itself ends there).
void emit_table(std::string& out, const std::string& path, const py::dict& d, int depth) {
  if (depth > kMaxDepth)
    throw ConfigError(fmt::format("Case(dict): '{}' is nested deeper than {} levels (a dict or list that contains "
                                  "itself?)", path.substr(0, path.find('.')), kMaxDepth));
  for (auto [k, v] : d)
    if (!py::isinstance<py::dict>(v) && !is_table_list(v))
      out += toml_key(py::str(k)) + " = " + toml_value(v, depth + 1) + "\n";
  for (auto [k, v] : d) {
    const std::string sub = (path.empty() ? "" : path + ".") + toml_key(py::str(k));
    if (py::isinstance<py::dict>(v)) {
      out += "\n[" + sub + "]\n";
      emit_table(out, sub, py::reinterpret_borrow<py::dict>(v), depth + 1);
    } else if (is_table_list(v)) {
      for (auto item : py::reinterpret_borrow<py::sequence>(v)) {
        out += "\n[[" + sub + "]]\n";
        emit_table(out, sub, py::reinterpret_borrow<py::dict>(item), depth + 1);
      }
    }
  }
}

// The value at a dotted key of a TOML document parsed by tomllib (list elements by index).
py::object lookup(py::object node, const std::string& key) {
  std::size_t start = 0;
  while (start <= key.size()) {
    const auto end = std::min(key.find('.', start), key.size());
    const std::string part = key.substr(start, end - start);
    if (py::isinstance<py::dict>(node) && node.contains(part)) {
      node = node[py::str(part)];
    } else if (py::isinstance<py::list>(node) && !part.empty() &&
               part.find_first_not_of("0123456789") == std::string::npos &&
               std::stoul(part) < py::len(node)) {
      node = node[py::int_(std::stoul(part))];
    } else {
      throw py::key_error(fmt::format("key '{}' is not in the case", key));
    }
    start = end + 1;
  }
  return node;
}

// The case as TOML; resolved by `command` (validated, every default filled in) when given.
std::string toml_of(const Case& c, const std::optional<std::string>& command) {
  if (!command) return c.cfg.resolved_toml();
  Config cfg = c.cfg.clone();
  run::find_command(*command).parse(cfg);
  return cfg.resolved_toml();
}

Config from_dict(const py::dict& d) {
  std::string text;
  emit_table(text, "", d, 0);
  return Config::from_string(text, "<dict>");
}

}  // namespace

std::string toml_value(py::handle v, int depth) {
  if (depth > kMaxDepth)
    throw ConfigError(fmt::format("a value nested deeper than {} levels (a list or dict that contains itself?)",
                                  kMaxDepth));
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::str>(v)) return toml_string(v.cast<std::string>());
  if (py::isinstance<py::dict>(v)) {
    std::string s;
    for (auto [k, x] : py::reinterpret_borrow<py::dict>(v))
      s += (s.empty() ? "" : ", ") + toml_key(py::str(k)) + " = " + toml_value(x, depth + 1);
    return "{" + s + "}";
  }
  // NumPy arrays, 0-d arrays and scalars: the Python values they hold (tolist keeps float as float; an
  // array stays a list even of size 1, so it is never taken for a scalar and truncated by __index__).
  if (py::hasattr(v, "ndim") && py::hasattr(v, "tolist")) return toml_value(v.attr("tolist")(), depth + 1);
  if (py::hasattr(v, "__index__")) return py::str(py::int_(py::reinterpret_borrow<py::object>(v)));
  if (py::hasattr(v, "__float__")) return toml_real(v.cast<double>());
  if (py::isinstance<py::iterable>(v) && !py::isinstance<py::bytes>(v)) {
    std::string s;
    for (auto x : py::reinterpret_borrow<py::iterable>(v)) s += (s.empty() ? "" : ", ") + toml_value(x, depth + 1);
    return "[" + s + "]";
  }
  throw py::type_error(fmt::format("cannot write a {} as a TOML value", std::string(py::str(v.get_type()))));
}

Config copy_of(const Case& c) { return c.cfg.clone(); }

void bind_case(py::module_& m) {
  py::class_<Case>(m, "Case", R"(A case: the TOML configuration of a run (docs/config.md lists every key, unit and range).

Build one from a file (Case.load), TOML text (Case.from_toml) or a dict of sections (Case(dict)), change
keys with set(), read them with get(). The command functions (agglo.collide, ...) never change the case
they are given. Keys are validated like the CLI's: a value TOML cannot hold raises ConfigError at set();
unknown keys and values outside their range raise ConfigError when a command parses the case (run, or
to_toml(command)), with the CLI's one-line message.)")
      .def(py::init([](const py::dict& d) { return Case{from_dict(d)}; }), py::arg("data") = py::dict(),
           R"(Case(data={}): a case from a dict of sections, e.g.
{"material": {"restitution": 0.9}, "agglomerate": {"shape": "square"}, "particles": [{...}, {...}]}
(nested dicts are tables, lists of dicts arrays of tables; values in SI units as in the case files).)")
      .def_static("load", [](const py::object& path) {
            return Case{Config::load(py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>())};
          }, py::arg("path"), "Case.load(path): the case in a TOML file (str or os.PathLike); ConfigError if missing or invalid TOML.")
      .def_static("from_toml", [](const std::string& text, const std::string& name) {
            return Case{Config::from_string(text, name)};
          }, py::arg("text"), py::arg("name") = "<string>",
          "Case.from_toml(text, name='<string>'): the case in TOML text; `name` stands for the file in error messages.")
      .def("set", [](Case& c, const std::string& key, py::handle value) -> Case& {
            c.cfg.apply_override(key + "=" + toml_value(value));
            return c;
          }, py::arg("key"), py::arg("value"), py::return_value_policy::reference,
          R"(set(key, value): sets the dotted key (e.g. "material.restitution", "particles.0.radius") to value
(bool, int, float, str, list or dict; SI units as in docs/config.md), like the CLI's --set key=value.
Returns the case, so calls can be chained.)")
      .def("get", [](const Case& c, const std::string& key, const std::optional<std::string>& command) {
            return lookup(py::module_::import("tomllib").attr("loads")(toml_of(c, command)), key);
          }, py::arg("key"), py::arg("command") = py::none(),
          R"(get(key, command=None): the value of a dotted key as given in the case (KeyError if absent); with a
command name, the value the command runs with (its default when the case does not give it).)")
      .def("to_toml", &toml_of, py::arg("command") = py::none(),
          R"(to_toml(command=None): the case as TOML text. With a command name ("collide", ...) the case is
validated by that command (ConfigError as the CLI would raise) and every default is filled in: the
config.resolved.toml a run writes.)")
      .def("copy", [](const Case& c) { return Case{c.cfg.clone()}; }, "copy(): an independent copy of the case.")
      .def_property_readonly("file", [](const Case& c) { return c.cfg.file(); },
                             "The file the case was read from ('<dict>' or '<string>' otherwise).")
      .def("__repr__", [](const Case& c) { return fmt::format("agglo.Case({})", toml_string(c.cfg.file())); });
}

}  // namespace agglo::python
