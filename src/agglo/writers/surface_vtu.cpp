#include "agglo/writers/surface_vtu.hpp"

#include <fmt/format.h>

namespace agglo::writers {

void write_surface_vtu(std::ostream& os, const std::vector<SurfaceSample>& s,
                       const std::vector<std::array<int, 3>>& tri) {
  const bool mesh = !tri.empty();
  const std::size_t ncell = mesh ? tri.size() : s.size();
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "<UnstructuredGrid>\n"
     << fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", s.size(), ncell);
  os << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : s) os << fmt::format("{:.9g} {:.9g} {:.9g}\n", p.position.x, p.position.y, p.position.z);
  os << "</DataArray>\n</Points>\n";
  os << "<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  if (mesh)
    for (const auto& t : tri) os << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  else
    for (std::size_t i = 0; i < s.size(); ++i) os << i << '\n';
  os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < ncell; ++c) os << (mesh ? 3 * (c + 1) : c + 1) << '\n';
  os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < ncell; ++c) os << (mesh ? 5 : 1) << '\n';
  os << "</DataArray>\n</Cells>\n";
  os << "<PointData Scalars=\"sigma\">\n";
  auto scalar = [&](const char* name, auto f) {
    os << fmt::format("<DataArray type=\"Float64\" Name=\"{}\" format=\"ascii\">\n", name);
    for (const auto& p : s) os << fmt::format("{:.9g}\n", f(p));
    os << "</DataArray>\n";
  };
  scalar("sigma_f", [](const SurfaceSample& p) { return p.sigma_free; });
  scalar("sigma_b", [](const SurfaceSample& p) { return p.sigma_bound; });
  scalar("sigma", [](const SurfaceSample& p) { return p.sigma_free + p.sigma_bound; });
  scalar("area", [](const SurfaceSample& p) { return p.area; });
  os << "<DataArray type=\"Int32\" Name=\"body\" format=\"ascii\">\n";
  for (const auto& p : s) os << p.body << '\n';
  os << "</DataArray>\n";
  os << "<DataArray type=\"Float64\" Name=\"normal\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : s) os << fmt::format("{:.6g} {:.6g} {:.6g}\n", p.normal.x, p.normal.y, p.normal.z);
  os << "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace agglo::writers
