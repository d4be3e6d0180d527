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
// string), list/tuple/NumPy array (an array), dict (an inline table). TypeError for anything else.
std::string toml_value(pybind11::handle value);

// A copy of the case `c` (the functions never change the caller's case).
Config copy_of(const Case& c);

}  // namespace agglo::python
