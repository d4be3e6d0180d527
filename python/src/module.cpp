// Entry point of the extension module _agglo (imported by python/agglo/__init__.py).
#include "bindings.hpp"

// apps/agglo/omp_wait/omp_wait.cpp: short OpenMP spin waits (referenced so that the linker keeps it).
extern "C" int agglo_omp_wait_linked();

PYBIND11_MODULE(_agglo, m) {
  m.attr("_omp_waits_linked") = agglo_omp_wait_linked() == 1;
  m.doc() = "agglo: adhesive DEM with dielectric electrostatics and DSMC acoustic agglomeration";
  agglo::python::bind_core(m);
  agglo::python::bind_electrostatic_forces(m);
}
