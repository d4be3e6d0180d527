#include "agglo/writers/surface_vtu.hpp"

#include <fmt/format.h>

#include "agglo/io/vtk.hpp"

namespace agglo::writers {

namespace {
constexpr double kVtkVertex = 1, kVtkTriangle = 5;  // VTK cell type ids

template <class F>
io::VtkArray per_sample(const char* name, const char* type, const std::vector<SurfaceSample>& s, F f) {
  io::VtkArray a{name, type, 1, {}};
  a.values.reserve(s.size());
  for (const auto& p : s) a.values.push_back(f(p));
  return a;
}

// connectivity, offsets and types of the cells.
std::vector<io::VtkArray> cells(std::size_t samples, const std::vector<std::array<int, 3>>& tri) {
  const bool mesh = !tri.empty();
  const std::string index = io::vtk_index_type(mesh ? 3 * tri.size() : samples);
  io::VtkArray conn{"connectivity", index, 1, {}}, offsets{"offsets", index, 1, {}}, types{"types", "UInt8", 1, {}};
  if (mesh)
    for (const auto& t : tri) conn.values.insert(conn.values.end(), {double(t[0]), double(t[1]), double(t[2])});
  else
    for (std::size_t i = 0; i < samples; ++i) conn.values.push_back(static_cast<double>(i));
  const std::size_t ncell = mesh ? tri.size() : samples;
  for (std::size_t c = 0; c < ncell; ++c) offsets.values.push_back(static_cast<double>(mesh ? 3 * (c + 1) : c + 1));
  types.values.assign(ncell, mesh ? kVtkTriangle : kVtkVertex);
  return {std::move(conn), std::move(offsets), std::move(types)};
}
}  // namespace

void write_surface_vtu(std::ostream& os, const std::vector<SurfaceSample>& s,
                       const std::vector<std::array<int, 3>>& tri) {
  using P = SurfaceSample;
  std::vector<Vec3> x, n;
  for (const auto& p : s) {
    x.push_back(p.position);
    n.push_back(p.normal);
  }
  const std::size_t ncell = tri.empty() ? s.size() : tri.size();
  io::write_vtk(os, "UnstructuredGrid", fmt::format("NumberOfPoints=\"{}\" NumberOfCells=\"{}\"", s.size(), ncell),
                {{"Points", "", {io::vtk_vectors("Points", x)}},
                 {"Cells", "", cells(s.size(), tri)},
                 {"PointData",
                  "Scalars=\"sigma\"",
                  {per_sample("sigma_f", "Float64", s, [](const P& p) { return p.sigma_free; }),
                   per_sample("sigma_b", "Float64", s, [](const P& p) { return p.sigma_bound; }),
                   per_sample("sigma", "Float64", s, [](const P& p) { return p.sigma_free + p.sigma_bound; }),
                   per_sample("area", "Float64", s, [](const P& p) { return p.area; }),
                   per_sample("body", "Int32", s, [](const P& p) { return double(p.body); }),
                   io::vtk_vectors("normal", n)}}});
}

}  // namespace agglo::writers
