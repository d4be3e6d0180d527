#include "agglo/io/vtk_particles.hpp"

#include <fmt/format.h>

namespace agglo::io {

namespace {
void vec_array(std::ostream& o, const char* name, const std::vector<Vec3>& v) {
  o << fmt::format("        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"3\" format=\"ascii\">\n", name);
  for (const auto& a : v) o << fmt::format("          {:.10g} {:.10g} {:.10g}\n", a.x, a.y, a.z);
  o << "        </DataArray>\n";
}
template <class T>
void scalar_array(std::ostream& o, const char* type, const char* name, const std::vector<T>& v) {
  o << fmt::format("        <DataArray type=\"{}\" Name=\"{}\" format=\"ascii\">\n          ", type, name);
  for (const auto& a : v) o << fmt::format("{:.10g} ", static_cast<double>(a));
  o << "\n        </DataArray>\n";
}
}  // namespace

void write_vtp(std::ostream& o, const ParticleSnapshot& s) {
  const std::size_t n = s.position.size();
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
    << "  <PolyData>\n"
    << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\">\n", n, n) << "      <PointData Scalars=\"radius\">\n";
  scalar_array(o, "Float64", "radius", s.radius);
  vec_array(o, "velocity", s.velocity);
  vec_array(o, "angular_velocity", s.angular_velocity);
  scalar_array(o, "Float64", "charge", s.charge);
  scalar_array(o, "Int32", "contacts", s.contacts);
  o << "      </PointData>\n      <Points>\n";
  vec_array(o, "Points", s.position);
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
