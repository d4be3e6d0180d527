#pragma once
// ParaView files (VTK XML, binary): PolyData (.vtp) point clouds with one vertex per point, any
// dataset given as sections of arrays (writers/surface_vtu.cpp: an UnstructuredGrid), and a .pvd
// collection listing files with their times. What the arrays mean is up to the caller
// (writers/impact.cpp: particle snapshots; writers/aggregate.cpp; writers/surface_vtu.cpp).
//
// Encoding (docs/outputs.md): every DataArray is format="appended" with an offset into one
// <AppendedData encoding="raw"> block after the XML; there each array is a UInt64 byte count then
// its values, little-endian, in the array's declared type (Float64 exact, integers converted from
// the stored doubles). The file header says version="1.0" header_type="UInt64"
// byte_order="LittleEndian".
#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "agglo/core/vec3.hpp"

namespace agglo::io {

// One data array: `components` values per tuple (1: scalars, 3: vectors), tuple after tuple.
struct VtkArray {
  std::string name;
  std::string type = "Float64";  // "Float64", "Int64", "Int32" or "UInt8"
  int components = 1;
  std::vector<double> values;  // integer types: whole numbers within the type's range
};

// The type of cell connectivity and offsets whose largest value is `largest`: "Int32" when it fits,
// else "Int64".
std::string vtk_index_type(std::size_t largest);

// A Float64 array of one 3-vector per point.
VtkArray vtk_vectors(std::string name, const std::vector<Vec3>& v);

// One element of a Piece (e.g. "PointData", "Points", "Cells", "Verts") with its attributes
// (e.g. `Scalars="sigma"`, may be empty) and its arrays.
struct VtkSection {
  std::string element;
  std::string attributes;
  std::vector<VtkArray> arrays;
};

// A VTK XML file of one Piece: `dataset` is the VTKFile type ("PolyData", "UnstructuredGrid"),
// `piece_attributes` the Piece's attributes (e.g. `NumberOfPoints="4" NumberOfCells="4"`).
// Throws std::invalid_argument for an unknown type or a value count that is not a multiple of the
// components.
void write_vtk(std::ostream& out, std::string_view dataset, std::string_view piece_attributes,
               const std::vector<VtkSection>& sections);

// Writes the points (coordinates in metres) and their arrays as PolyData; the first array is the
// active scalars.
void write_vtp(std::ostream& out, const std::vector<Vec3>& points, const std::vector<VtkArray>& point_data);
// files: (time [s], file name relative to the .pvd); plain XML (no data arrays).
void write_pvd(std::ostream& out, const std::vector<std::pair<double, std::string>>& files);

}  // namespace agglo::io
