#include "agglo/writers/surface_vtu.hpp"

#include <fmt/format.h>

#include "agglo/core/cancel.hpp"
#include "agglo/io/vtk.hpp"

namespace agglo::writers {

namespace {
constexpr double kVtkVertex = 1, kVtkTriangle = 5;  // VTK cell type ids

template <class F>
io::VtkArray per_sample(const char* name, const char* type, const std::vector<SurfaceSample>& s, F f) {
  poll_cancel();  // millions of samples: each array takes tens of ms to build (core/cancel.hpp)
  io::VtkArray a{name, type, 1, {}};
  a.values.reserve(s.size());
  for (const auto& p : s) a.values.push_back(f(p));
  return a;
}

template <class F>
io::VtkArray per_sample3(const char* name, const std::vector<SurfaceSample>& s, F f) {
  poll_cancel();
  io::VtkArray a{name, "Float64", 3, {}};
  a.values.reserve(3 * s.size());
  for (const auto& p : s) {
    const Vec3 v = f(p);
    a.values.insert(a.values.end(), {v.x, v.y, v.z});
  }
  return a;
}

// connectivity, offsets and types of the cells.
std::vector<io::VtkArray> cells(std::size_t samples, const std::vector<std::array<int, 3>>& tri) {
  const bool mesh = !tri.empty();
  const std::string index = io::vtk_index_type(mesh ? 3 * tri.size() : samples);
  io::VtkArray conn{"connectivity", index, 1, {}}, offsets{"offsets", index, 1, {}}, types{"types", "UInt8", 1, {}};
  const std::size_t ncell = mesh ? tri.size() : samples;
  conn.values.reserve(mesh ? 3 * ncell : ncell);
  offsets.values.reserve(ncell);
  if (mesh)
    for (const auto& t : tri) conn.values.insert(conn.values.end(), {double(t[0]), double(t[1]), double(t[2])});
  else
    for (std::size_t i = 0; i < samples; ++i) conn.values.push_back(static_cast<double>(i));
  poll_cancel();
  for (std::size_t c = 0; c < ncell; ++c) offsets.values.push_back(static_cast<double>(mesh ? 3 * (c + 1) : c + 1));
  poll_cancel();
  types.values.assign(ncell, mesh ? kVtkTriangle : kVtkVertex);
  std::vector<io::VtkArray> out;
  out.push_back(std::move(conn));
  out.push_back(std::move(offsets));
  out.push_back(std::move(types));
  return out;
}
}  // namespace

void write_surface_vtu(std::ostream& os, const std::vector<SurfaceSample>& s,
                       const std::vector<std::array<int, 3>>& tri) {
  using P = SurfaceSample;
  const std::size_t ncell = tri.empty() ? s.size() : tri.size();
  // Built by moves (an initializer list would copy every array once more).
  std::vector<io::VtkSection> sections(3);
  sections[0].element = "Points";
  sections[0].arrays.push_back(per_sample3("Points", s, [](const P& p) { return p.position; }));
  sections[1].element = "Cells";
  sections[1].arrays = cells(s.size(), tri);
  sections[2].element = "PointData";
  sections[2].attributes = "Scalars=\"sigma\"";
  auto& d = sections[2].arrays;
  d.push_back(per_sample("sigma_f", "Float64", s, [](const P& p) { return p.sigma_free; }));
  d.push_back(per_sample("sigma_b", "Float64", s, [](const P& p) { return p.sigma_bound; }));
  d.push_back(per_sample("sigma", "Float64", s, [](const P& p) { return p.sigma_free + p.sigma_bound; }));
  d.push_back(per_sample("area", "Float64", s, [](const P& p) { return p.area; }));
  d.push_back(per_sample("body", "Int32", s, [](const P& p) { return double(p.body); }));
  d.push_back(per_sample3("normal", s, [](const P& p) { return p.normal; }));
  io::write_vtk(os, "UnstructuredGrid", fmt::format("NumberOfPoints=\"{}\" NumberOfCells=\"{}\"", s.size(), ncell),
                sections);
}

}  // namespace agglo::writers
