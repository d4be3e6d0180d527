#pragma once
// agglo.Case: a case (core/config.hpp Config) built from a TOML file, TOML text or a Python dict, and
// the conversion of Python values into TOML text for Config::apply_override.
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file: the casters of std types must agree (ODR)

#include "agglo/core/config.hpp"

namespace agglo::python {

struct Case {
  Config cfg;
};

// A Python value as a TOML value: bool, int, float (always with '.', 'e', inf or nan), str (a quoted
// string), list/tuple/NumPy array (an array, of any size), NumPy scalar or 0-d array (its Python value),
// dict (an inline table). TypeError for anything else; ConfigError nested deeper than 64 levels (`depth`:
// the levels above `value`).
std::string toml_value(pybind11::handle value, int depth = 0);

// A copy of the case `c` (the functions never change the caller's case).
Config copy_of(const Case& c);

}  // namespace agglo::python
