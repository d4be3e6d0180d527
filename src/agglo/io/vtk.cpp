#include "agglo/io/vtk.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace agglo::io {

namespace {

// Appends `v` as the little-endian bytes of T.
template <class T>
void put(std::string& bytes, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::big)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  bytes.append(b, sizeof(T));
}

template <class T>
void put_values(std::string& bytes, const std::vector<double>& values) {
  put<std::uint64_t>(bytes, values.size() * sizeof(T));
  for (double v : values) put<T>(bytes, static_cast<T>(v));
}

// Appends the array's block (byte count, values) to `bytes`.
void encode(std::string& bytes, const VtkArray& a) {
  if (a.components < 1 || a.values.size() % static_cast<std::size_t>(a.components) != 0)
    throw std::invalid_argument(fmt::format("VTK array {}: {} values for {} components", a.name, a.values.size(),
                                            a.components));
  if (a.type == "Float64")
    put_values<double>(bytes, a.values);
  else if (a.type == "Int64")
    put_values<std::int64_t>(bytes, a.values);
  else if (a.type == "Int32")
    put_values<std::int32_t>(bytes, a.values);
  else if (a.type == "UInt8")
    put_values<std::uint8_t>(bytes, a.values);
  else
    throw std::invalid_argument(fmt::format("VTK array {}: unsupported type {}", a.name, a.type));
}

}  // namespace

std::string vtk_index_type(std::size_t largest) {
  return largest <= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()) ? "Int32" : "Int64";
}

VtkArray vtk_vectors(std::string name, const std::vector<Vec3>& v) {
  VtkArray a{std::move(name), "Float64", 3, {}};
  a.values.reserve(3 * v.size());
  for (const auto& x : v) a.values.insert(a.values.end(), {x.x, x.y, x.z});
  return a;
}

void write_vtk(std::ostream& o, std::string_view dataset, std::string_view piece_attributes,
               const std::vector<VtkSection>& sections) {
  std::string bytes;
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n  <{}>\n    <Piece {}>\n",
      dataset, dataset, piece_attributes);
  for (const auto& s : sections) {
    xml += fmt::format("      <{}{}{}>\n", s.element, s.attributes.empty() ? "" : " ", s.attributes);
    for (const auto& a : s.arrays) {
      xml += fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
                         "offset=\"{}\"/>\n",
                         a.type, a.name, a.components, bytes.size());
      encode(bytes, a);
    }
    xml += fmt::format("      </{}>\n", s.element);
  }
  xml += fmt::format("    </Piece>\n  </{}>\n  <AppendedData encoding=\"raw\">\n   _", dataset);
  o << xml;
  o.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  o << "\n  </AppendedData>\n</VTKFile>\n";
}

void write_vtp(std::ostream& o, const std::vector<Vec3>& points, const std::vector<VtkArray>& point_data) {
  const std::size_t n = points.size();
  const std::string index = vtk_index_type(n);
  VtkArray connectivity{"connectivity", index, 1, {}}, offsets{"offsets", index, 1, {}};
  for (std::size_t k = 0; k < n; ++k) {
    connectivity.values.push_back(static_cast<double>(k));
    offsets.values.push_back(static_cast<double>(k + 1));
  }
  write_vtk(o, "PolyData", fmt::format("NumberOfPoints=\"{}\" NumberOfVerts=\"{}\"", n, n),
            {{"PointData", point_data.empty() ? "" : fmt::format("Scalars=\"{}\"", point_data.front().name), point_data},
             {"Points", "", {vtk_vectors("Points", points)}},
             {"Verts", "", {std::move(connectivity), std::move(offsets)}}});
}

void write_pvd(std::ostream& o, const std::vector<std::pair<double, std::string>>& files) {
  o << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (const auto& [t, f] : files) o << fmt::format("    <DataSet timestep=\"{:.10g}\" file=\"{}\"/>\n", t, f);
  o << "  </Collection>\n</VTKFile>\n";
}

}  // namespace agglo::io
