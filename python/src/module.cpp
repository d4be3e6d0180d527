// Entry point of the extension module _agglo (imported by python/agglo/__init__.py).
#include "bindings.hpp"

PYBIND11_MODULE(_agglo, m) {
  m.doc() = "agglo: adhesive DEM with dielectric electrostatics and DSMC acoustic agglomeration";
  agglo::python::bind_core(m);
  agglo::python::bind_electrostatic_forces(m);
}
