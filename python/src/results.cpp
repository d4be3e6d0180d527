// agglo.Result (results.hpp). Arrays are read-only NumPy views of the variables of the run's dataset:
// a capsule holding the dataset's shared_ptr is their base object, so no values are copied and the
// dataset lives as long as any array does.
#include "results.hpp"

#include <cstring>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"

namespace py = pybind11;

namespace agglo::python {

namespace {

const io::Variable& variable(const Result& r, const std::string& name) {
  const io::Variable* v = r.data ? r.data->find(name) : nullptr;
  if (!v) {
    std::string names;
    if (r.data)
      for (const auto& x : r.data->variables) names += (names.empty() ? "" : ", ") + x.name;
    throw py::key_error(fmt::format("{}: no variable '{}' (available: {})", r.command, name,
                                    names.empty() ? "none" : names));
  }
  return *v;
}

py::array array_of(const io::DatasetPtr& data, const io::Variable& v) {
  std::vector<py::ssize_t> shape;
  for (const auto& d : v.dims) shape.push_back(static_cast<py::ssize_t>(data->dim_length(d)));
  py::capsule owner(new io::DatasetPtr(data), [](void* p) { delete static_cast<io::DatasetPtr*>(p); });
  py::array a = v.integer ? py::array(py::dtype::of<std::int64_t>(), shape, {}, v.ints.data(), owner)
                          : py::array(py::dtype::of<double>(), shape, {}, v.reals.data(), owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

py::dict variable_attributes(const io::Variable& v) {
  py::dict attrs = to_python(v.attributes);
  attrs["units"] = v.units;
  attrs["long_name"] = v.long_name;
  return attrs;
}

py::object to_xarray(const Result& r) {
  py::module_ xr;
  try {
    xr = py::module_::import("xarray");
  } catch (py::error_already_set&) {
    throw py::import_error("Result.to_xarray() needs xarray (Debian: apt-get install python3-xarray)");
  }
  py::dict vars, coords;
  py::dict attrs = r.data ? to_python(r.data->attributes) : py::dict();
  attrs["command"] = r.command;
  attrs["seed"] = r.seed;
  if (r.data)
    for (const auto& v : r.data->variables) {
      const bool coordinate = v.dims.size() == 1 && v.dims[0] == v.name;
      (coordinate ? coords : vars)[py::str(v.name)] =
          py::make_tuple(py::tuple(py::cast(v.dims)), array_of(r.data, v), variable_attributes(v));
    }
  return xr.attr("Dataset")(vars, py::arg("coords") = coords, py::arg("attrs") = attrs);
}

// A small dataset for the tests of the array conversion: time (3), a 2-D real variable and an integer one.
Result example_result() {
  auto d = std::make_shared<io::Dataset>();
  d->add_dim("time", 3);
  d->add_dim("bin", 2);
  d->add("time", {"time"}, "s", "simulated time", {0.0, 0.5, 1.0});
  d->add("psd", {"time", "bin"}, "m-3", "number concentration per bin", {1, 2, 3, 4, 5, 6});
  d->add_ints("count", {"time"}, "1", "number of particles", {7, 8, 9});
  d->attributes["title"] = "example";
  return Result{"example", {{"answer", 42}}, 7, std::nullopt, d, {}};
}

// Pickling (e.g. results returned by Dask tasks): the dataset as plain tuples, values as raw bytes.
py::tuple dataset_state(const io::Dataset& d) {
  py::list vars;
  for (const auto& v : d.variables) {
    const auto* bytes = v.integer ? reinterpret_cast<const char*>(v.ints.data()) : reinterpret_cast<const char*>(v.reals.data());
    vars.append(py::make_tuple(v.name, v.dims, v.units, v.long_name, v.integer, py::bytes(bytes, v.size() * 8),
                               v.attributes.dump()));
  }
  return py::make_tuple(d.dims, vars, d.attributes.dump());
}

io::DatasetPtr dataset_of(const py::tuple& state) {
  auto d = std::make_shared<io::Dataset>();
  for (const auto& [name, len] : state[0].cast<std::vector<std::pair<std::string, std::size_t>>>()) d->add_dim(name, len);
  for (auto item : state[1].cast<py::list>()) {
    const auto t = item.cast<py::tuple>();
    const auto raw = t[5].cast<std::string>();
    io::Variable* v = nullptr;
    if (t[4].cast<bool>()) {
      std::vector<std::int64_t> ints(raw.size() / 8);
      std::memcpy(ints.data(), raw.data(), raw.size());
      v = &d->add_ints(t[0].cast<std::string>(), t[1].cast<std::vector<std::string>>(), t[2].cast<std::string>(),
                       t[3].cast<std::string>(), std::move(ints));
    } else {
      std::vector<double> reals(raw.size() / 8);
      std::memcpy(reals.data(), raw.data(), raw.size());
      v = &d->add(t[0].cast<std::string>(), t[1].cast<std::vector<std::string>>(), t[2].cast<std::string>(),
                  t[3].cast<std::string>(), std::move(reals));
    }
    v->attributes = nlohmann::json::parse(t[6].cast<std::string>());
  }
  d->attributes = nlohmann::json::parse(state[2].cast<std::string>());
  return d;
}

py::tuple result_state(const Result& r) {
  return py::make_tuple(r.command, r.summary.dump(), r.seed, r.out, r.messages,
                        r.data ? py::object(dataset_state(*r.data)) : py::object(py::none()));
}

Result result_of(const py::tuple& t) {
  return Result{t[0].cast<std::string>(), nlohmann::json::parse(t[1].cast<std::string>()), t[2].cast<long long>(),
                t[3].cast<std::optional<std::string>>(), t[5].is_none() ? nullptr : dataset_of(t[5].cast<py::tuple>()),
                t[4].cast<std::vector<std::string>>()};
}

}  // namespace

py::object to_python(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

void bind_results(py::module_& m) {
  py::class_<Result>(m, "Result", R"(The result of a command function (agglo.collide, ...).

summary   dict: the scalars of the run in SI units (the result.json / summary the CLI writes)
seed      int: the random seed the run used (0 for deterministic commands)
out       str or None: the output folder (None: nothing was kept on disk)
result[name]   NumPy array of a variable (read-only, shares the run's memory: no copy), e.g. result["time"] [s]
variables / dims / attrs, units(name), long_name(name), dimensions(name): labels of the arrays
to_xarray()    an xarray.Dataset with units and long_name attributes)")
      .def_readonly("command", &Result::command, "The command that ran (str).")
      .def_property_readonly("summary", [](const Result& r) { return to_python(r.summary); },
                             "The run's scalars as a dict (SI units; the CLI's result.json / summary).")
      .def_readonly("seed", &Result::seed, "Random seed of the run (int; 0 for deterministic commands).")
      .def_readonly("out", &Result::out, "Output folder (str), or None when out=None was given.")
      .def_readonly("messages", &Result::messages, "The run's one-line results (the CLI prints them on stdout).")
      .def_property_readonly("variables", [](const Result& r) {
            std::vector<std::string> names;
            if (r.data)
              for (const auto& v : r.data->variables) names.push_back(v.name);
            return names;
          }, "Names of the arrays (list of str), in order of definition.")
      .def_property_readonly("dims", [](const Result& r) {
            py::dict d;
            if (r.data)
              for (const auto& [name, len] : r.data->dims) d[py::str(name)] = len;
            return d;
          }, "Dimension names and lengths (dict).")
      .def_property_readonly("attrs", [](const Result& r) { return r.data ? to_python(r.data->attributes) : py::dict(); },
                             "Global attributes of the dataset (dict: version, git hash, resolved config, ...).")
      .def("keys", [](const Result& r) { return py::cast(r).attr("variables"); }, "The variable names, as variables.")
      .def("__getitem__", [](const Result& r, const std::string& name) { return array_of(r.data, variable(r, name)); },
           py::arg("name"), "result[name]: the variable as a read-only NumPy array (float64 or int64) without a copy.")
      .def("__contains__", [](const Result& r, const std::string& name) { return r.data && r.data->find(name); })
      .def("units", [](const Result& r, const std::string& name) { return variable(r, name).units; }, py::arg("name"),
           "units(name): the UDUNITS string of a variable, e.g. 's', 'J', 'm s-1', '1'.")
      .def("long_name", [](const Result& r, const std::string& name) { return variable(r, name).long_name; },
           py::arg("name"), "long_name(name): one-line description of a variable.")
      .def("dimensions", [](const Result& r, const std::string& name) { return variable(r, name).dims; },
           py::arg("name"), "dimensions(name): the dimension names of a variable, outermost first.")
      .def("to_xarray", &to_xarray,
           "to_xarray(): the arrays as an xarray.Dataset (variables named after a dimension become its coordinates; "
           "attributes units and long_name; the global attributes plus command and seed). ImportError without xarray.")
      .def(py::pickle(&result_state, &result_of))
      .def("__repr__", [](const Result& r) {
        return fmt::format("<agglo.Result of {}: {} variables, out={}>", r.command, r.data ? r.data->variables.size() : 0,
                           r.out ? *r.out : std::string("None"));
      });
  m.def("_example_result", &example_result, "A Result holding a small constructed dataset (for the tests).");
}

}  // namespace agglo::python
