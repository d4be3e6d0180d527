#include "agglo/io/vtk.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "agglo/core/cancel.hpp"

namespace agglo::io {

namespace {

// Stores `v` at `p` as the little-endian bytes of T.
template <class T>
void store(char* p, T v) {
  std::memcpy(p, &v, sizeof(T));
  if constexpr (std::endian::native == std::endian::big) std::reverse(p, p + sizeof(T));
}

template <class T>
std::string block_of(const std::vector<double>& values) {
  std::string b(8 + values.size() * sizeof(T), '\0');
  store<std::uint64_t>(b.data(), values.size() * sizeof(T));
  char* p = b.data() + 8;
  for (double v : values) {
    store<T>(p, static_cast<T>(v));
    p += sizeof(T);
  }
  return b;
}

// Bytes per value of the array's type; throws for an unknown type or a partial tuple.
std::size_t value_bytes(const VtkArray& a) {
  if (a.components < 1 || a.values.size() % static_cast<std::size_t>(a.components) != 0)
    throw std::invalid_argument(fmt::format("VTK array {}: {} values for {} components", a.name, a.values.size(),
                                            a.components));
  if (a.type == "Float64" || a.type == "Int64") return 8;
  if (a.type == "Int32") return 4;
  if (a.type == "UInt8") return 1;
  throw std::invalid_argument(fmt::format("VTK array {}: unsupported type {}", a.name, a.type));
}

// The array's block in the appended data: UInt64 byte count, then the values.
std::string block(const VtkArray& a) {
  if (a.type == "Float64") return block_of<double>(a.values);
  if (a.type == "Int64") return block_of<std::int64_t>(a.values);
  if (a.type == "Int32") return block_of<std::int32_t>(a.values);
  return block_of<std::uint8_t>(a.values);
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
  std::size_t offset = 0;
  std::string xml = fmt::format(
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"{}\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n  <{}>\n    <Piece {}>\n",
      dataset, dataset, piece_attributes);
  for (const auto& s : sections) {
    xml += fmt::format("      <{}{}{}>\n", s.element, s.attributes.empty() ? "" : " ", s.attributes);
    for (const auto& a : s.arrays) {
      xml += fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
                         "offset=\"{}\"/>\n",
                         a.type, a.name, a.components, offset);
      offset += 8 + a.values.size() * value_bytes(a);
    }
    xml += fmt::format("      </{}>\n", s.element);
  }
  xml += fmt::format("    </Piece>\n  </{}>\n  <AppendedData encoding=\"raw\">\n   _", dataset);
  o << xml;
  for (const auto& s : sections)
    for (const auto& a : s.arrays) {
      poll_cancel();  // a large array takes a fraction of a second to encode (core/cancel.hpp)
      const std::string b = block(a);  // one array's bytes at a time
      o.write(b.data(), static_cast<std::streamsize>(b.size()));
    }
  o << "\n  </AppendedData>\n</VTKFile>\n";
}

void write_vtp(std::ostream& o, const std::vector<Vec3>& points, const std::vector<VtkArray>& point_data) {
  const std::size_t n = points.size();
  const std::string index = vtk_index_type(n);
  VtkArray connectivity{"connectivity", index, 1, {}}, offsets{"offsets", index, 1, {}};
  connectivity.values.reserve(n);
  offsets.values.reserve(n);
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
