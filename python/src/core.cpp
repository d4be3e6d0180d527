// Cases, errors, commands and results (placeholder: filled in by the Python-module work).
#include "bindings.hpp"

namespace agglo::python {

void bind_core(pybind11::module_&) {}

}  // namespace agglo::python
