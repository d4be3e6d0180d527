#pragma once
// ParaView files (ASCII VTK XML): a point cloud as PolyData (.vtp) with one vertex per point and named
// point-data arrays, and a .pvd collection listing files with their times. What the arrays mean is up
// to the caller (writers/impact.cpp: particle snapshots).
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::io {

// One point-data array: `components` values per point (1: scalars, 3: vectors), point after point.
struct VtkArray {
  std::string name;
  std::string type = "Float64";  // VTK type of the values ("Float64", "Int32", ...)
  int components = 1;
  std::vector<double> values;
};

// A Float64 array of one 3-vector per point.
VtkArray vtk_vectors(std::string name, const std::vector<Vec3>& v);

// Writes the points (coordinates in metres) and their arrays; the first array is the active scalars.
// Values are written with 10 significant digits.
void write_vtp(std::ostream& out, const std::vector<Vec3>& points, const std::vector<VtkArray>& point_data);
// files: (time [s], file name relative to the .pvd)
void write_pvd(std::ostream& out, const std::vector<std::pair<double, std::string>>& files);

}  // namespace agglo::io
