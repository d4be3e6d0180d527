#pragma once
// The parts of the extension module _agglo, each bound from its own file (python/src/*.cpp).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>  // in every file: the casters of std types must agree (ODR)

namespace agglo::python {

void bind_core(pybind11::module_& m);                  // everything below but electrostatic_forces (core.cpp)
void bind_errors(pybind11::module_& m);                // Error, ConfigError, LimitError, ... (errors.cpp)
void bind_case(pybind11::module_& m);                  // Case (case.cpp)
void bind_results(pybind11::module_& m);               // Result: summary and NumPy arrays (results.cpp)
void bind_commands(pybind11::module_& m);              // collide, vcrit, ... one function per command (commands.cpp)
void bind_sweep(pybind11::module_& m);                 // sweep (sweep.cpp)
void bind_electrostatic_forces(pybind11::module_& m);  // agglo.electrostatic_forces (electrostatic_forces.cpp)

}  // namespace agglo::python
