// agglo.electrostatic_forces (placeholder: filled in by the Python-module work).
#include "bindings.hpp"

namespace agglo::python {

void bind_electrostatic_forces(pybind11::module_&) {}

}  // namespace agglo::python
