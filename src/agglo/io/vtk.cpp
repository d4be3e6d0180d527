#include "agglo/io/vtk.hpp"

#include <fmt/format.h>

namespace agglo::io {

namespace {
// 3-vectors one per line, scalars all on one line.
void array(std::ostream& o, const VtkArray& a) {
  if (a.components == 1) {
    o << fmt::format("        <DataArray type=\"{}\" Name=\"{}\" format=\"ascii\">\n          ", a.type, a.name);
    for (double v : a.values) o << fmt::format("{:.10g} ", v);
    o << "\n        </DataArray>\n";
    return;
  }
  o << fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n", a.type,
                   a.name, a.components);
  const auto m = static_cast<std::size_t>(a.components);
  for (std::size_t i = 0; i + m <= a.values.size(); i += m) {
    o << "         ";
    for (std::size_t c = 0; c < m; ++c) o << fmt::format(" {:.10g}", a.values[i + c]);
    o << '\n';
  }
  o << "        </DataArray>\n";
}
}  // namespace

VtkArray vtk_vectors(std::string name, const std::vector<Vec3>& v) {
  VtkArray a{std::move(name), "Float64", 3, {}};
  for (const auto& x : v) a.values.insert(a.values.end(), {x.x, x.y, x.z});
  return a;
}

void write_vtp(std::ostream& o, const std::vector<Vec3>& points, const std::vector<VtkArray>& point_data) {
  const std::size_t n = points.size();
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <PolyData>\n" << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\">\n", n, n)
    << (point_data.empty() ? std::string("      <PointData>\n")
                           : fmt::format("      <PointData Scalars=\"{}\">\n", point_data.front().name));
  for (const auto& a : point_data) array(o, a);
  o << "      </PointData>\n      <Points>\n";
  array(o, vtk_vectors("Points", points));
  o << "      </Points>\n      <Verts>\n"
    << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n          ";
  for (std::size_t k = 0; k < n; ++k) o << k << ' ';
  o << "\n        </DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n          ";
  for (std::size_t k = 0; k < n; ++k) o << k + 1 << ' ';
  o << "\n        </DataArray>\n      </Verts>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
}

void write_pvd(std::ostream& o, const std::vector<std::pair<double, std::string>>& files) {
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [t, f] : files) o << fmt::format("    <DataSet timestep=\"{:.10g}\" file=\"{}\"/>\n", t, f);
  o << "  </Collection>\n</VTKFile>\n";
}

}  // namespace agglo::io
