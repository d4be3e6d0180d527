#pragma once
// The parts of the extension module _agglo, each bound from its own file (python/src/*.cpp).
#include <pybind11/pybind11.h>

namespace agglo::python {

void bind_core(pybind11::module_& m);                  // cases, errors, commands, results (module.cpp)
void bind_electrostatic_forces(pybind11::module_& m);  // agglo.electrostatic_forces (electrostatic_forces.cpp)

}  // namespace agglo::python
