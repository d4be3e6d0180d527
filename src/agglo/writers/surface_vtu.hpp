#pragma once
// VTK XML UnstructuredGrid (.vtu, binary: io/vtk.hpp) of the surface charge of a solve:
// points = surface samples, cells = triangles (VTK_TRIANGLE) when the solver provides a
// triangulation, else one VTK_VERTEX per sample. Point data: sigma_f, sigma_b, sigma
// (= sigma_f + sigma_b) [C/m^2], area [m^2], body id, normal. Coordinates in metres.
#include <array>
#include <ostream>
#include <vector>

#include "agglo/electrostatics/solver.hpp"

namespace agglo::writers {

using es::SurfaceSample;

void write_surface_vtu(std::ostream& os, const std::vector<SurfaceSample>& samples,
                       const std::vector<std::array<int, 3>>& triangles);

}  // namespace agglo::writers
